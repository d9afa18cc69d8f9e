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

}  // namespace chute
