#include "convection.hpp"

#include "limiter.hpp"

#include <algorithm>
#include <cmath>

namespace chute {

namespace {

// Moving: the lines move (lv); the fluxes take the velocity relative to each face (the conservative form: where
// cells stretch, the change of their volume is the flow solver's, core/operators/line_motion.hpp).
template <ConvectionScheme S, bool Moving>
void convection_impl(const Grid& grid, const Velocity& vel, int u_first, int v_first, Velocity& out,
                     const LineVelocities* lv, const Velocity* wall, const Velocity* transport, const Velocity* far) {
    // A face value between a face a sharp surface sets (wall) and any other: linear interpolation, which the
    // ghost's mirror makes the wall's velocity (see convection.hpp).
    const auto value = [&](bool at_wall, double flux, double qm, double q0, double q1, double qp, double w1) {
        return at_wall ? q0 + w1 * (q1 - q0) : transported<S>(flux, qm, q0, q1, qp, w1);
    };
    const auto wall_u = [&](int i0, int j0, int i1, int j1) {
        return wall && (wall->u(i0, j0) != 0.0 || wall->u(i1, j1) != 0.0);
    };
    const auto wall_v = [&](int i0, int j0, int i1, int j1) {
        return wall && (wall->v(i0, j0) != 0.0 || wall->v(i1, j1) != 0.0);
    };
    const auto wx_line = [&](int i) { return Moving ? lv->x(i) : 0.0; };
    const auto wy_line = [&](int j) { return Moving ? lv->y(j) : 0.0; };
    const auto wx_centre = [&](int i) { return Moving ? lv->xc(i) : 0.0; };
    const auto wy_centre = [&](int j) { return Moving ? lv->yc(j) : 0.0; };
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    const int nx = grid.nx(), ny = grid.ny();
    const Field2D& u = vel.u;
    const Field2D& v = vel.v;
    const Field2D& tu = transport ? transport->u : vel.u;  // transporting velocities (convection.hpp)
    const Field2D& tv = transport ? transport->v : vel.v;
    const Field2D& fu = far ? far->u : vel.u;  // the values two faces away (the limiter's ratio)
    const Field2D& fv = far ? far->v : vel.v;

    // u momentum
    for (int j = 0; j < ny; ++j) {
        const double hy = Y.w(j);
        // weights for interpolating u to y-lines yf(j) and yf(j+1)
        const double wn = (Y.f(j + 1) - Y.c(j)) / Y.dc(j + 1);
        const double ws = (Y.f(j) - Y.c(j - 1)) / Y.dc(j);
        const double wyn = wy_line(j + 1), wys = wy_line(j);
        for (int i = u_first; i < nx; ++i) {
            // east/west faces are cell centres i and i-1: U = mean of the two faces, value at the midpoint.
            const double wxe = wx_centre(i), wxw = wx_centre(i - 1);
            const double Ue = 0.5 * (tu(i, j) + tu(i + 1, j)) - wxe;
            const double Uw = 0.5 * (tu(i - 1, j) + tu(i, j)) - wxw;
            const double fe =
                Ue * value(wall_u(i, j, i + 1, j), Ue, fu(i - 1, j), u(i, j), u(i + 1, j), fu(i + 2, j), 0.5);
            const double fw =
                Uw * value(wall_u(i - 1, j, i, j), Uw, fu(i - 2, j), u(i - 1, j), u(i, j), fu(i + 1, j), 0.5);
            // north/south faces: the volume flux through [xc(i-1), xc(i)] splits into the two cells' v faces.
            const double a0 = (X.f(i) - X.c(i - 1)) / X.dc(i), a1 = 1.0 - a0;
            const double Vn = a0 * tv(i - 1, j + 1) + a1 * tv(i, j + 1) - wyn;
            const double Vs = a0 * tv(i - 1, j) + a1 * tv(i, j) - wys;
            const double fn =
                Vn * value(wall_u(i, j, i, j + 1), Vn, fu(i, j - 1), u(i, j), u(i, j + 1), fu(i, j + 2), wn);
            const double fs =
                Vs * value(wall_u(i, j - 1, i, j), Vs, fu(i, j - 2), u(i, j - 1), u(i, j), fu(i, j + 1), ws);
            out.u(i, j) = -((fe - fw) / X.dc(i) + (fn - fs) / hy);
        }
    }
    // v momentum
    for (int j = v_first; j < ny; ++j) {
        const double b0 = (Y.f(j) - Y.c(j - 1)) / Y.dc(j), b1 = 1.0 - b0;
        const double wyn = wy_centre(j), wys = wy_centre(j - 1);
        for (int i = 0; i < nx; ++i) {
            const double Vn = 0.5 * (tv(i, j) + tv(i, j + 1)) - wyn;
            const double Vs = 0.5 * (tv(i, j - 1) + tv(i, j)) - wys;
            const double fn =
                Vn * value(wall_v(i, j, i, j + 1), Vn, fv(i, j - 1), v(i, j), v(i, j + 1), fv(i, j + 2), 0.5);
            const double fs =
                Vs * value(wall_v(i, j - 1, i, j), Vs, fv(i, j - 2), v(i, j - 1), v(i, j), fv(i, j + 1), 0.5);
            const double wxe = wx_line(i + 1), wxw = wx_line(i);
            const double Ue = b0 * tu(i + 1, j - 1) + b1 * tu(i + 1, j) - wxe;
            const double Uw = b0 * tu(i, j - 1) + b1 * tu(i, j) - wxw;
            const double we = (X.f(i + 1) - X.c(i)) / X.dc(i + 1);
            const double ww = (X.f(i) - X.c(i - 1)) / X.dc(i);
            const double fe =
                Ue * value(wall_v(i, j, i + 1, j), Ue, fv(i - 1, j), v(i, j), v(i + 1, j), fv(i + 2, j), we);
            const double fw =
                Uw * value(wall_v(i - 1, j, i, j), Uw, fv(i - 2, j), v(i - 1, j), v(i, j), fv(i + 1, j), ww);
            out.v(i, j) = -((fe - fw) / X.w(i) + (fn - fs) / Y.dc(j));
        }
    }
}

}  // namespace

void convection(const Grid& grid, ConvectionScheme scheme, const Velocity& vel, int u_first, int v_first, Velocity& out,
                const LineVelocities* lines, const Velocity* wall_faces, const Velocity* transport,
                const Velocity* far) {
    const bool moving = lines && !lines->zero();
    const auto run = [&]<ConvectionScheme S>() {
        if (moving)
            convection_impl<S, true>(grid, vel, u_first, v_first, out, lines, wall_faces, transport, far);
        else
            convection_impl<S, false>(grid, vel, u_first, v_first, out, nullptr, wall_faces, transport, far);
    };
    switch (scheme) {
        case ConvectionScheme::central:
            return run.template operator()<ConvectionScheme::central>();
        case ConvectionScheme::van_leer:
            return run.template operator()<ConvectionScheme::van_leer>();
        case ConvectionScheme::koren:
            return run.template operator()<ConvectionScheme::koren>();
    }
}

}  // namespace chute
