#pragma once
// Face values of a transported quantity for the convection schemes of case_config.hpp:
//   central:            linear interpolation;
//   van_leer, koren:    upwind value plus a limited anti-diffusive correction (TVD, bounded),
//                       phi_f = phi_U + 1/2 psi(r) (phi_D - phi_U),  r = (phi_U - phi_UU) / (phi_D - phi_U).
// Shared by the momentum convection (convection.cpp) and the scalar transport of turbulence/.
#include <algorithm>

#include "case_config.hpp"

namespace chute {

// Limited face value from the upwind (U), far-upwind (UU) and downwind (D) values.
template <ConvectionScheme S>
inline double face_value(double uu, double u, double d, double central) {
    if constexpr (S == ConvectionScheme::central) {
        (void)uu;
        (void)u;
        (void)d;
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

}  // namespace chute
