#include "time_step_control.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>

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
    double rate[2] = {0.0, 0.0};  // max convective rate |u|/dx + |v|/dy, max diffusive rate
    for (int j = 0; j < grid.ny(); ++j)
        for (int i = 0; i < grid.nx(); ++i) {
            const double w0 = lines ? lines->x(i) : 0.0, w1 = lines ? lines->x(i + 1) : 0.0;
            const double s0 = lines ? lines->y(j) : 0.0, s1 = lines ? lines->y(j + 1) : 0.0;
            const double uc = std::max(std::abs(vel.u(i, j) - w0), std::abs(vel.u(i + 1, j) - w1));
            const double vc = std::max(std::abs(vel.v(i, j) - s0), std::abs(vel.v(i, j + 1) - s1));
            const double ix = 1.0 / X.w(i), iy = 1.0 / Y.w(j);
            // A cell whose faces move apart or together (a modifier layer) changes by at most `cfl` of its width in
            // a step: it cannot close within one (band/layers.hpp changes it at the next step).
            const double deformation = std::abs(w1 - w0) * ix + std::abs(s1 - s0) * iy;
            rate[0] = std::max(rate[0], uc * ix + vc * iy + deformation);
            rate[1] = std::max(rate[1], nu * (ix * ix + iy * iy));
        }
    MPI_Allreduce(MPI_IN_PLACE, rate, 2, MPI_DOUBLE, MPI_MAX, grid.comm());
    const double inf = std::numeric_limits<double>::infinity();
    return {rate[0] > 0.0 ? cfl / rate[0] : inf, rate[1] > 0.0 ? diffusion_number / rate[1] : inf};
}

}  // namespace chute
