#include "wet_rebound.hpp"

#include <algorithm>
#include <cmath>

namespace chute {

namespace {

// Linear between the table's points, held beyond its ends.
double table_at(const std::vector<double>& x, const std::vector<double>& y, double at) {
    if (at <= x.front()) return y.front();
    if (at >= x.back()) return y.back();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());
    const double w = (at - x[k - 1]) / (x[k] - x[k - 1]);
    return (1.0 - w) * y[k - 1] + w * y[k];
}

}  // namespace

double impact_stokes_number(double block_density, double normal_speed, double size, double viscosity) {
    return block_density * normal_speed * size / (9.0 * viscosity);
}

double impact_obliquity(double vt, double vn) { return std::atan2(std::abs(vt), std::abs(vn)); }

double SlopeRebound::weight(double slope_angle) const { return std::clamp(std::abs(slope_angle) / angle, 0.0, 1.0); }

double SlopeRebound::kappa_n_at(double at) const { return table_at(impact_angle, kappa_n, at); }
double SlopeRebound::push_at(double at) const { return table_at(travel, push, at); }

double WetRebound::normal_kappa(double travel) const {
    if (wake_length <= 0.0) return kappa_n;
    return kappa_n + (kappa_n_start - kappa_n) * std::exp(-travel / wake_length);
}

double WetRebound::normal_kappa(double travel, double slope_angle, double impact_angle) const {
    if (!slope.measured()) return normal_kappa(travel);
    const double w = slope.weight(slope_angle);
    return (1.0 - w) * normal_kappa(travel) + w * slope.kappa_n_at(impact_angle);
}

double WetRebound::push(double travel, double slope_angle) const {
    if (!slope.measured()) return 0.0;
    return slope.weight(slope_angle) * slope.push_at(travel);
}

Restitution wet_restitution(const WetRebound& law, double rn, double rt, double stokes, double travel,
                            double slope_angle, double impact_angle) {
    return {rn * law.normal_kappa(travel, slope_angle, impact_angle) * std::exp(-law.beta / stokes), rt * law.kappa_t,
            law.push(travel, slope_angle)};
}

}  // namespace chute
