#include "time_step_control.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace chute {

double max_inverse_square_spacing(const Grid& grid) {
    double m = 0.0;
    for (int j = 0; j < grid.ny(); ++j)
        for (int i = 0; i < grid.nx(); ++i) {
            const double ix = 1.0 / grid.lx().w(i), iy = 1.0 / grid.ly().w(j);
            m = std::max(m, ix * ix + iy * iy);
        }
    MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_MAX, grid.comm());
    return m;
}

TimeStepLimits time_step_limits(const Grid& grid, const Velocity& vel, double nu, double cfl, double diffusion_number,
                                const LineVelocities* lines) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    const int nx = grid.nx(), ny = grid.ny();
    // Per column and row once: the inverse widths and the faces' velocities (no division in the cell loop).
    std::vector<double> ix(nx), wx(nx + 1, 0.0);
    for (int i = 0; i < nx; ++i) ix[i] = 1.0 / X.w(i);
    if (lines)
        for (int i = 0; i <= nx; ++i) wx[i] = lines->x(i);
    double rate[2] = {0.0, 0.0};  // max convective rate |u|/dx + |v|/dy, max diffusive rate
    for (int j = 0; j < ny; ++j) {
        const double iy = 1.0 / Y.w(j);
        const double s0 = lines ? lines->y(j) : 0.0, s1 = lines ? lines->y(j + 1) : 0.0;
        const double* u = vel.u.origin() + static_cast<std::ptrdiff_t>(j) * vel.u.stride();
        const double* v0 = vel.v.origin() + static_cast<std::ptrdiff_t>(j) * vel.v.stride();
        const double* v1 = v0 + vel.v.stride();
        double convective = rate[0], diffusive = rate[1];
        for (int i = 0; i < nx; ++i) {
            const double uc = std::max(std::abs(u[i] - wx[i]), std::abs(u[i + 1] - wx[i + 1]));
            const double vc = std::max(std::abs(v0[i] - s0), std::abs(v1[i] - s1));
            // A cell whose faces move apart or together (a modifier layer) changes by at most `cfl` of its width in
            // a step: it cannot close within one (band/layers.hpp changes it at the next step).
            const double deformation = std::abs(wx[i + 1] - wx[i]) * ix[i] + std::abs(s1 - s0) * iy;
            convective = std::max(convective, uc * ix[i] + vc * iy + deformation);
            diffusive = std::max(diffusive, nu * (ix[i] * ix[i] + iy * iy));
        }
        rate[0] = convective;
        rate[1] = diffusive;
    }
    MPI_Allreduce(MPI_IN_PLACE, rate, 2, MPI_DOUBLE, MPI_MAX, grid.comm());
    const double inf = std::numeric_limits<double>::infinity();
    return {rate[0] > 0.0 ? cfl / rate[0] : inf, rate[1] > 0.0 ? diffusion_number / rate[1] : inf};
}

}  // namespace chute
