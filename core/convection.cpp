#include "convection.hpp"

#include <algorithm>
#include <cmath>

namespace chute {

namespace {

// Limited face value from the upwind (U), far-upwind (UU) and downwind (D) values.
template <ConvectionScheme S>
inline double face_value(double uu, double u, double d, double central) {
    if constexpr (S == ConvectionScheme::central) {
        (void)uu; (void)u; (void)d;
        return central;
    } else {
        const double a = u - uu, b = d - u;
        if constexpr (S == ConvectionScheme::van_leer) {
            // 1/2 psi(r) b = ab / (a + b) for ab > 0 (same sign, so a + b != 0), else 0 (van Leer 1974).
            return (a * b > 0.0) ? u + a * b / (a + b) : u;
        } else {
            // Koren (1993): psi = max(0, min(2r, (1 + 2r)/3, 2)); third order where smooth.
            if (b == 0.0) return u;
            const double r = a / b;
            const double psi = std::max(0.0, std::min({2.0 * r, (1.0 + 2.0 * r) / 3.0, 2.0}));
            return u + 0.5 * psi * b;
        }
    }
}

// Transported value at a face between q0 (behind) and q1 (ahead), with neighbours qm (behind q0) and
// qp (ahead of q1); `flux` is the transporting velocity, `w1` the linear-interpolation weight of q1.
template <ConvectionScheme S>
inline double transported(double flux, double qm, double q0, double q1, double qp, double w1) {
    const double central = q0 + w1 * (q1 - q0);
    return flux >= 0.0 ? face_value<S>(qm, q0, q1, central) : face_value<S>(qp, q1, q0, central);
}

template <ConvectionScheme S>
void convection_impl(const Grid& grid, const Velocity& vel, int u_first, int v_first, Velocity& out) {
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
            const double Ue = 0.5 * (u(i, j) + u(i + 1, j));
            const double Uw = 0.5 * (u(i - 1, j) + u(i, j));
            const double fe = Ue * transported<S>(Ue, u(i - 1, j), u(i, j), u(i + 1, j), u(i + 2, j), 0.5);
            const double fw = Uw * transported<S>(Uw, u(i - 2, j), u(i - 1, j), u(i, j), u(i + 1, j), 0.5);
            // north/south faces: the volume flux through [xc(i-1), xc(i)] splits into the two cells' v faces.
            const double a0 = (X.f(i) - X.c(i - 1)) / X.dc(i), a1 = 1.0 - a0;
            const double Vn = a0 * v(i - 1, j + 1) + a1 * v(i, j + 1);
            const double Vs = a0 * v(i - 1, j) + a1 * v(i, j);
            const double fn = Vn * transported<S>(Vn, u(i, j - 1), u(i, j), u(i, j + 1), u(i, j + 2), wn);
            const double fs = Vs * transported<S>(Vs, u(i, j - 2), u(i, j - 1), u(i, j), u(i, j + 1), ws);
            out.u(i, j) = -((fe - fw) / X.dc(i) + (fn - fs) / hy);
        }
    }
    // v momentum
    for (int j = v_first; j < ny; ++j) {
        const double b0 = (Y.f(j) - Y.c(j - 1)) / Y.dc(j), b1 = 1.0 - b0;
        for (int i = 0; i < nx; ++i) {
            const double Vn = 0.5 * (v(i, j) + v(i, j + 1));
            const double Vs = 0.5 * (v(i, j - 1) + v(i, j));
            const double fn = Vn * transported<S>(Vn, v(i, j - 1), v(i, j), v(i, j + 1), v(i, j + 2), 0.5);
            const double fs = Vs * transported<S>(Vs, v(i, j - 2), v(i, j - 1), v(i, j), v(i, j + 1), 0.5);
            const double Ue = b0 * u(i + 1, j - 1) + b1 * u(i + 1, j);
            const double Uw = b0 * u(i, j - 1) + b1 * u(i, j);
            const double we = (X.f(i + 1) - X.c(i)) / X.dc(i + 1);
            const double ww = (X.f(i) - X.c(i - 1)) / X.dc(i);
            const double fe = Ue * transported<S>(Ue, v(i - 1, j), v(i, j), v(i + 1, j), v(i + 2, j), we);
            const double fw = Uw * transported<S>(Uw, v(i - 2, j), v(i - 1, j), v(i, j), v(i + 1, j), ww);
            out.v(i, j) = -((fe - fw) / X.w(i) + (fn - fs) / Y.dc(j));
        }
    }
}

}  // namespace

void convection(const Grid& grid, ConvectionScheme scheme, const Velocity& vel, int u_first, int v_first,
                Velocity& out) {
    switch (scheme) {
        case ConvectionScheme::central: return convection_impl<ConvectionScheme::central>(grid, vel, u_first, v_first, out);
        case ConvectionScheme::van_leer: return convection_impl<ConvectionScheme::van_leer>(grid, vel, u_first, v_first, out);
        case ConvectionScheme::koren: return convection_impl<ConvectionScheme::koren>(grid, vel, u_first, v_first, out);
    }
}

}  // namespace chute
