#include "wet_rebound.hpp"

#include <cmath>

namespace chute {

double impact_stokes_number(double block_density, double normal_speed, double size, double viscosity) {
    return block_density * normal_speed * size / (9.0 * viscosity);
}

double WetRebound::normal_kappa(double travel) const {
    if (wake_length <= 0.0) return kappa_n;
    return kappa_n + (kappa_n_start - kappa_n) * std::exp(-travel / wake_length);
}

Restitution wet_restitution(const WetRebound& law, double rn, double rt, double stokes, double travel) {
    return {rn * law.normal_kappa(travel) * std::exp(-law.beta / stokes), rt * law.kappa_t};
}

}  // namespace chute
