#include "hole_stress.hpp"

#include <mpi.h>

namespace chute {

SurfaceForces hole_stress(const Grid& grid, const SolidBlock& hole, const BodyState& body, const Velocity& vel,
                          const Field2D& p, double density, double viscosity, double depth,
                          const WallTurbulence* turbulence) {
    const Axis& X = grid.x_axis();
    const Axis& Y = grid.y_axis();
    const int ox = grid.lx().offset, oy = grid.ly().offset;
    auto owned = [&](int gi, int gj) {
        const int i = gi - ox, j = gj - oy;
        return i >= 0 && i < grid.nx() && j >= 0 && j < grid.ny();
    };
    // Sums: pressure force x, y, torque; viscous; turbulent.
    double s[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    auto add = [&](const Vec2& mid, const Vec2& n, double p1, double k1, double d1, double shear, double ds) {
        const Vec2 t = perp(n);
        const double p_wall = p1 + body.acceleration.dot(n) * d1 - 2.0 / 3.0 * k1;
        const Vec2 fp = -density * p_wall * ds * n;
        const Vec2 fv = density * viscosity * shear * ds * t;
        const Vec2 ft = turbulence
                            ? density * (turbulence->wall_viscosity(k1, d1) * shear * t - 2.0 / 3.0 * k1 * n) * ds
                            : Vec2(Vec2::Zero());
        const Vec2 r = mid - body.centre;
        s[0] += fp.x(), s[1] += fp.y(), s[2] += cross(r, fp);
        s[3] += fv.x(), s[4] += fv.y(), s[5] += cross(r, fv);
        s[6] += ft.x(), s[7] += ft.y(), s[8] += cross(r, ft);
    };
    auto k_at = [&](int i, int j) { return turbulence ? turbulence->k(i, j) : 0.0; };
    const double Ux = hole.velocity[0], Uy = hole.velocity[1];
    // Bottom and top sides: segments along x, the fluid cell below / above, shear of u.
    for (const bool top : {false, true}) {
        const int gj = top ? hole.upper[1] : hole.lower[1] - 1;  // the fluid row
        const double wall = Y.line(top ? hole.upper[1] : hole.lower[1]);
        const double d1 = std::abs(Y.centre(gj) - wall);
        const Vec2 n(0.0, top ? 1.0 : -1.0);
        for (int gi = hole.lower[0]; gi < hole.upper[0]; ++gi) {
            if (!owned(gi, gj)) continue;
            const int i = gi - ox, j = gj - oy;
            // t = perp(n) = (-n_y, n_x): along -x on the top side, +x on the bottom one.
            const double sign = perp(n).x();
            const double shear = sign * (0.5 * (vel.u(i, j) + vel.u(i + 1, j)) - Ux) / d1;
            add(Vec2(X.centre(gi), wall), n, p(i, j), k_at(i, j), d1, shear, X.width(gi) * depth);
        }
    }
    // Left and right sides: segments along y, the fluid cell left / right, shear of v.
    for (const bool right : {false, true}) {
        const int gi = right ? hole.upper[0] : hole.lower[0] - 1;
        const double wall = X.line(right ? hole.upper[0] : hole.lower[0]);
        const double d1 = std::abs(X.centre(gi) - wall);
        const Vec2 n(right ? 1.0 : -1.0, 0.0);
        for (int gj = hole.lower[1]; gj < hole.upper[1]; ++gj) {
            if (!owned(gi, gj)) continue;
            const int i = gi - ox, j = gj - oy;
            const double sign = perp(n).y();
            const double shear = sign * (0.5 * (vel.v(i, j) + vel.v(i, j + 1)) - Uy) / d1;
            add(Vec2(wall, Y.centre(gj)), n, p(i, j), k_at(i, j), d1, shear, Y.width(gj) * depth);
        }
    }
    if (grid.size() > 1) MPI_Allreduce(MPI_IN_PLACE, s, 9, MPI_DOUBLE, MPI_SUM, grid.comm());
    SurfaceForces f;
    f.pressure = Vec2(s[0], s[1]);
    f.pressure_torque = s[2];
    f.viscous = Vec2(s[3], s[4]);
    f.viscous_torque = s[5];
    f.turbulent = Vec2(s[6], s[7]);
    f.turbulent_torque = s[8];
    return f;
}

}  // namespace chute
