#include "hole_stress.hpp"

#include <mpi.h>

#include "hole.hpp"

namespace chute {

SurfaceForces hole_stress(const Grid& grid, const SolidBlock& hole, const BodyState& body, const Velocity& vel,
                          const Field2D& p, double density, double viscosity, double depth,
                          const WallTurbulence* turbulence) {
    // Sums: pressure force x, y, torque; viscous; turbulent.
    double s[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (const SideCell& c : side_cells(grid, hole, vel)) {
        const Vec2 n = c.normal, t = perp(n);
        const double d1 = c.distance, ds = c.length * depth;
        const double k1 = turbulence ? turbulence->k(c.i, c.j) : 0.0;
        const double shear = t.dot(c.slip) / d1;  // (u_t - U_t) / d1 along t = perp(n)
        const double p_wall = p(c.i, c.j) + body.acceleration.dot(n) * d1 - 2.0 / 3.0 * k1;
        const Vec2 fp = -density * p_wall * ds * n;
        const Vec2 fv = density * viscosity * shear * ds * t;
        const Vec2 ft = turbulence
                            ? density * (turbulence->wall_viscosity(k1, d1) * shear * t - 2.0 / 3.0 * k1 * n) * ds
                            : Vec2(Vec2::Zero());
        const Vec2 r = c.middle - body.centre;
        s[0] += fp.x(), s[1] += fp.y(), s[2] += cross(r, fp);
        s[3] += fv.x(), s[4] += fv.y(), s[5] += cross(r, fv);
        s[6] += ft.x(), s[7] += ft.y(), s[8] += cross(r, ft);
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
