#include "enclosed_momentum.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>

namespace chute {

EnclosedMomentum enclosed_momentum(const Grid& grid, const Velocity& vel, const Body& body) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    const int nx = grid.nx(), ny = grid.ny();
    const Vec2 c = body.state().centre;
    const double angle = body.state().angle;
    double sums[3] = {0.0, 0.0, 0.0};
    if (body.outline().closed()) {
        const double reach = body.outline().reach();
        auto fraction = [&](const Vec2& p, double h) {
            const double d = body.outline().signed_distance(rotated(p - c, -angle));
            return std::clamp(0.5 - d / h, 0.0, 1.0);
        };
        for (int j = 0; j < ny; ++j) {
            if (Y.f(j + 1) < c.y() - reach - Y.w(j) || Y.f(j) > c.y() + reach + Y.w(j)) continue;
            for (int i = 0; i < nx; ++i) {
                if (X.f(i + 1) < c.x() - reach - X.w(i) || X.f(i) > c.x() + reach + X.w(i)) continue;
                const Vec2 pu(X.f(i), Y.c(j)), pv(X.c(i), Y.f(j));
                const double au = fraction(pu, std::sqrt(X.dc(i) * Y.w(j))) * X.dc(i) * Y.w(j);
                const double av = fraction(pv, std::sqrt(X.w(i) * Y.dc(j))) * X.w(i) * Y.dc(j);
                sums[0] += au * vel.u(i, j);
                sums[1] += av * vel.v(i, j);
                sums[2] += cross(pu - c, Vec2(au * vel.u(i, j), 0.0)) + cross(pv - c, Vec2(0.0, av * vel.v(i, j)));
            }
        }
    }
    if (grid.size() > 1) MPI_Allreduce(MPI_IN_PLACE, sums, 3, MPI_DOUBLE, MPI_SUM, grid.comm());
    return {Vec2(sums[0], sums[1]), sums[2]};
}

}  // namespace chute
