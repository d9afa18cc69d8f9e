#pragma once
// Log-law wall functions of the standard k-epsilon model (Launder & Spalding 1974), in the k-based form
// OpenFOAM uses (nutkWallFunction, epsilonWallFunction), which Turmel & Locat (2008) ran with:
//
//   u_tau = C_mu^{1/4} k^{1/2}            friction velocity from the k of the near-wall point
//   y+    = u_tau y / nu
//   nu_w  = nu (kappa y+ / ln(E y+) - 1)  for y+ > 11.53, else 0: the eddy viscosity at the wall that
//           makes (nu + nu_w) U_t / y equal the log-law wall shear u_tau kappa U_t / ln(E y+)
//   eps   = C_mu^{3/4} k^{3/2} / (kappa y)            (log layer; 2 nu k / y^2 below the switch)
//   P_k   = tau_w C_mu^{1/4} k^{1/2} / (kappa y)      (tau_w dU/dy with the log-law gradient; 0 below)
// kappa 0.41, E 9.8; the switch y+ = 11.53 is where the linear and log profiles meet.
#include <cmath>

namespace chute {

struct KEpsilonConstants {
    static constexpr double c_mu = 0.09, c1 = 1.44, c2 = 1.92, sigma_k = 1.0, sigma_eps = 1.3;
    static constexpr double kappa = 0.41, E = 9.8, y_plus_switch = 11.53;
};

struct WallFunction {
    double u_tau = 0.0;  // from k
    double y_plus = 0.0;
    double nu_wall = 0.0;    // eddy viscosity at the wall (m^2/s)
    bool log_layer = false;  // y+ above the switch

    // Near-wall point at distance y from the wall with turbulence energy k.
    WallFunction(double k, double y, double nu) {
        using C = KEpsilonConstants;
        u_tau = std::pow(C::c_mu, 0.25) * std::sqrt(std::max(k, 0.0));
        y_plus = u_tau * y / nu;
        log_layer = y_plus > C::y_plus_switch;
        nu_wall = log_layer ? nu * (C::kappa * y_plus / std::log(C::E * y_plus) - 1.0) : 0.0;
    }
    // Wall shear stress (kinematic, m^2/s^2) for the tangential speed |U_t| at distance y.
    double shear(double speed, double y, double nu) const { return (nu + nu_wall) * speed / y; }
    // Dissipation and production of k in the near-wall cell (centre at distance y, energy k).
    double dissipation(double k, double y, double nu) const {
        using C = KEpsilonConstants;
        return log_layer ? std::pow(C::c_mu, 0.75) * std::pow(k, 1.5) / (C::kappa * y) : 2.0 * nu * k / (y * y);
    }
    double production(double tau_w, double y) const {
        return log_layer ? tau_w * u_tau / (KEpsilonConstants::kappa * y) : 0.0;
    }
};

// The law of the wall in the two layers above (u+ = y+ below the switch, ln(E y+) / kappa above): the tangential
// speed at distance y from a wall where it is `speed` at distance L (m/s; nu the kinematic viscosity). u_tau is
// found from the speed at L (Newton's method on the log layer, from the viscous layer's value); the sharp immersed
// interface reconstructs the flow beside a surface with it (ibm/sharp_forcing.hpp).
inline double law_of_the_wall_speed(double speed, double L, double y, double nu) {
    using C = KEpsilonConstants;
    if (!(speed > 0.0) || !(L > 0.0)) return 0.0;
    double u_tau = std::sqrt(speed * nu / L);  // the viscous layer: speed = u_tau^2 L / nu
    if (u_tau * L / nu > C::y_plus_switch)
        for (int it = 0; it < 30; ++it) {
            const double log_term = std::log(C::E * L * u_tau / nu);
            const double step = (u_tau * log_term / C::kappa - speed) / ((log_term + 1.0) / C::kappa);
            u_tau = std::max(u_tau - step, 0.5 * u_tau);
            if (std::abs(step) < 1e-12 * u_tau) break;
        }
    const double y_plus = std::max(y, 0.0) * u_tau / nu;
    return u_tau * (y_plus > C::y_plus_switch ? std::log(C::E * y_plus) / C::kappa : y_plus);
}

}  // namespace chute
