#include "convection.hpp"

#include "limiter.hpp"

#include <algorithm>
#include <cmath>

namespace chute {

namespace {

template <ConvectionScheme S>
void convection_impl(const Grid& grid, const Velocity& vel, int u_first, int v_first, Velocity& out, double wx,
                     double wy) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    const int nx = grid.nx(), ny = grid.ny();
    const Field2D& u = vel.u;
    const Field2D& v = vel.v;

    // u momentum
    for (int j = 0; j < ny; ++j) {
        const double hy = Y.w(j);
        // weights for interpolating u to y-lines yf(j) and yf(j+1)
        const double wn = (Y.f(j + 1) - Y.c(j)) / Y.dc(j + 1);
        const double ws = (Y.f(j) - Y.c(j - 1)) / Y.dc(j);
        for (int i = u_first; i < nx; ++i) {
            // east/west faces are cell centres i and i-1: U = mean of the two faces, value at the midpoint.
            const double Ue = 0.5 * (u(i, j) + u(i + 1, j)) - wx;
            const double Uw = 0.5 * (u(i - 1, j) + u(i, j)) - wx;
            const double fe = Ue * transported<S>(Ue, u(i - 1, j), u(i, j), u(i + 1, j), u(i + 2, j), 0.5);
            const double fw = Uw * transported<S>(Uw, u(i - 2, j), u(i - 1, j), u(i, j), u(i + 1, j), 0.5);
            // north/south faces: the volume flux through [xc(i-1), xc(i)] splits into the two cells' v faces.
            const double a0 = (X.f(i) - X.c(i - 1)) / X.dc(i), a1 = 1.0 - a0;
            const double Vn = a0 * v(i - 1, j + 1) + a1 * v(i, j + 1) - wy;
            const double Vs = a0 * v(i - 1, j) + a1 * v(i, j) - wy;
            const double fn = Vn * transported<S>(Vn, u(i, j - 1), u(i, j), u(i, j + 1), u(i, j + 2), wn);
            const double fs = Vs * transported<S>(Vs, u(i, j - 2), u(i, j - 1), u(i, j), u(i, j + 1), ws);
            out.u(i, j) = -((fe - fw) / X.dc(i) + (fn - fs) / hy);
        }
    }
    // v momentum
    for (int j = v_first; j < ny; ++j) {
        const double b0 = (Y.f(j) - Y.c(j - 1)) / Y.dc(j), b1 = 1.0 - b0;
        for (int i = 0; i < nx; ++i) {
            const double Vn = 0.5 * (v(i, j) + v(i, j + 1)) - wy;
            const double Vs = 0.5 * (v(i, j - 1) + v(i, j)) - wy;
            const double fn = Vn * transported<S>(Vn, v(i, j - 1), v(i, j), v(i, j + 1), v(i, j + 2), 0.5);
            const double fs = Vs * transported<S>(Vs, v(i, j - 2), v(i, j - 1), v(i, j), v(i, j + 1), 0.5);
            const double Ue = b0 * u(i + 1, j - 1) + b1 * u(i + 1, j) - wx;
            const double Uw = b0 * u(i, j - 1) + b1 * u(i, j) - wx;
            const double we = (X.f(i + 1) - X.c(i)) / X.dc(i + 1);
            const double ww = (X.f(i) - X.c(i - 1)) / X.dc(i);
            const double fe = Ue * transported<S>(Ue, v(i - 1, j), v(i, j), v(i + 1, j), v(i + 2, j), we);
            const double fw = Uw * transported<S>(Uw, v(i - 2, j), v(i - 1, j), v(i, j), v(i + 1, j), ww);
            out.v(i, j) = -((fe - fw) / X.w(i) + (fn - fs) / Y.dc(j));
        }
    }
}

}  // namespace

void convection(const Grid& grid, ConvectionScheme scheme, const Velocity& vel, int u_first, int v_first, Velocity& out,
                std::array<double, 2> frame) {
    const double wx = frame[0], wy = frame[1];
    switch (scheme) {
        case ConvectionScheme::central:
            return convection_impl<ConvectionScheme::central>(grid, vel, u_first, v_first, out, wx, wy);
        case ConvectionScheme::van_leer:
            return convection_impl<ConvectionScheme::van_leer>(grid, vel, u_first, v_first, out, wx, wy);
        case ConvectionScheme::koren:
            return convection_impl<ConvectionScheme::koren>(grid, vel, u_first, v_first, out, wx, wy);
    }
}

}  // namespace chute
