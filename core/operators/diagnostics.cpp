#include "diagnostics.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>

#include "projection.hpp"

namespace chute {

double kinetic_energy(const Grid& grid, const Velocity& vel, const Field2D* fluid) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    double e = 0.0;
    for (int j = 0; j < grid.ny(); ++j)
        for (int i = 0; i < grid.nx(); ++i) {
            const double uc = 0.5 * (vel.u(i, j) + vel.u(i + 1, j));
            const double vc = 0.5 * (vel.v(i, j) + vel.v(i, j + 1));
            if (fluid && (*fluid)(i, j) == 0.0) continue;
            e += 0.5 * (uc * uc + vc * vc) * X.w(i) * Y.w(j);
        }
    MPI_Allreduce(MPI_IN_PLACE, &e, 1, MPI_DOUBLE, MPI_SUM, grid.comm());
    return e;
}

double max_divergence(const Grid& grid, const Velocity& vel, const Field2D* fluid) {
    double m = 0.0;
    for (int j = 0; j < grid.ny(); ++j)
        for (int i = 0; i < grid.nx(); ++i)
            if (!fluid || (*fluid)(i, j) != 0.0) {
                m = std::max(m, std::abs(cell_divergence(grid, vel, i, j)));
            }
    MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_MAX, grid.comm());
    return m;
}

void cell_centred_velocity(const Grid& grid, const Velocity& vel, Field2D& uc, Field2D& vc) {
    for (int j = 0; j < grid.ny(); ++j)
        for (int i = 0; i < grid.nx(); ++i) {
            uc(i, j) = 0.5 * (vel.u(i, j) + vel.u(i + 1, j));
            vc(i, j) = 0.5 * (vel.v(i, j) + vel.v(i, j + 1));
        }
}

void vorticity(const Grid& grid, const Velocity& vel, Field2D& omega) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    // Corner (i, j) sits at (xf(i), yf(j)).
    auto corner = [&](int i, int j) {
        return (vel.v(i, j) - vel.v(i - 1, j)) / X.dc(i) - (vel.u(i, j) - vel.u(i, j - 1)) / Y.dc(j);
    };
    for (int j = 0; j < grid.ny(); ++j)
        for (int i = 0; i < grid.nx(); ++i)
            omega(i, j) = 0.25 * (corner(i, j) + corner(i + 1, j) + corner(i, j + 1) + corner(i + 1, j + 1));
}

Probes::Probes(const Grid& grid, std::vector<std::array<double, 2>> points) : grid_(grid), points_(std::move(points)) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    for (const auto& pt : points_) {
        Stencil s;
        // The probe belongs to the rank whose owned cells contain it.
        const bool inside = pt[0] >= X.f(0) && pt[0] < X.f(grid.nx()) && pt[1] >= Y.f(0) && pt[1] < Y.f(grid.ny());
        const bool on_far_edge = (pt[0] == X.f(grid.nx()) && grid.touches(Side::right)) ||
                                 (pt[1] == Y.f(grid.ny()) && grid.touches(Side::top));
        if (inside || on_far_edge) {
            s.local = true;
            int i = 0, j = 0;
            while (i < grid.nx() && X.c(i) <= pt[0]) ++i;
            while (j < grid.ny() && Y.c(j) <= pt[1]) ++j;
            s.i = i - 1;  // centre left of / below the point (may be a ghost cell)
            s.j = j - 1;
            s.fx = (pt[0] - X.c(s.i)) / (X.c(s.i + 1) - X.c(s.i));
            s.fy = (pt[1] - Y.c(s.j)) / (Y.c(s.j + 1) - Y.c(s.j));
            // Within half a cell of a domain boundary: take the nearest centre (no values beyond the domain).
            if (grid.touches(Side::left) && s.i < 0) s.i = 0, s.fx = 0.0;
            if (grid.touches(Side::right) && s.i >= grid.nx() - 1) s.i = grid.nx() - 1, s.fx = 0.0;
            if (grid.touches(Side::bottom) && s.j < 0) s.j = 0, s.fy = 0.0;
            if (grid.touches(Side::top) && s.j >= grid.ny() - 1) s.j = grid.ny() - 1, s.fy = 0.0;
        }
        stencils_.push_back(s);
    }
}

std::vector<double> Probes::sample(const Field2D& f) const {
    // Stencils may reach one ghost cell across a patch edge: f's halo must be exchanged.
    std::vector<double> values(points_.size(), 0.0);
    for (std::size_t k = 0; k < points_.size(); ++k) {
        const Stencil& s = stencils_[k];
        if (!s.local) continue;
        values[k] = (1 - s.fx) * (1 - s.fy) * f(s.i, s.j) + s.fx * (1 - s.fy) * f(s.i + 1, s.j) +
                    (1 - s.fx) * s.fy * f(s.i, s.j + 1) + s.fx * s.fy * f(s.i + 1, s.j + 1);
    }
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
    return values;
}

}  // namespace chute
