#include "wet_rebound.hpp"

#include <cmath>

namespace chute {

double impact_stokes_number(double block_density, double normal_speed, double size, double viscosity) {
    return block_density * normal_speed * size / (9.0 * viscosity);
}

Restitution wet_restitution(const WetRebound& law, double rn, double rt, double stokes) {
    return {rn * law.kappa_n * std::exp(-law.beta / stokes), rt * law.kappa_t};
}

}  // namespace chute
