#pragma once
// Statistics of a shedding body's force coefficients over the end of a run (validation tests of bluff bodies
// and DFG 2D-2): the forcing-based force (a), and the surface-stress drag (b) for the record.
#include <algorithm>
#include <cmath>
#include <vector>

#include "body_run.hpp"

namespace chute::validation {

struct Shedding {
    double cd_mean = 0.0, cd_mean_surface = 0.0, cd_max = 0.0;
    double cl_max = 0.0, cl_min = 0.0, cl_amplitude = 0.0, cl_rms = 0.0;
    double strouhal = NAN;  // f D / U from the lift's upward crossings of its mean
};

// Over t >= t0: coefficients C = F / q (q = 0.5 rho U^2 D per unit depth), St = f D / U (time_scale = D / U).
inline Shedding shedding(const BodyRun& run, double t0, double q, double time_scale) {
    std::vector<double> t, cl, cd, cds;
    for (const auto& h : run.history)
        if (h.t >= t0) {
            t.push_back(h.t);
            cd.push_back(h.f.forcing.x() / q);
            cds.push_back((h.f.surface.pressure.x() + h.f.surface.viscous.x()) / q);
            cl.push_back(h.f.forcing.y() / q);
        }
    Shedding s;
    if (t.empty()) return s;
    const double n = static_cast<double>(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) s.cd_mean += cd[k] / n, s.cd_mean_surface += cds[k] / n;
    double mean_cl = 0.0;
    for (double v : cl) mean_cl += v / n;
    for (double v : cl) s.cl_rms += (v - mean_cl) * (v - mean_cl) / n;
    s.cl_rms = std::sqrt(s.cl_rms);
    s.cd_max = *std::max_element(cd.begin(), cd.end());
    s.cl_max = *std::max_element(cl.begin(), cl.end());
    s.cl_min = *std::min_element(cl.begin(), cl.end());
    s.cl_amplitude = 0.5 * (s.cl_max - s.cl_min);
    // Period from the upward crossings of C_L - mean (linear interpolation between samples).
    std::vector<double> up;
    for (std::size_t k = 1; k < t.size(); ++k)
        if (cl[k - 1] - mean_cl < 0.0 && cl[k] - mean_cl >= 0.0)
            up.push_back(t[k - 1] + (t[k] - t[k - 1]) * (mean_cl - cl[k - 1]) / (cl[k] - cl[k - 1]));
    if (up.size() >= 2) s.strouhal = (up.size() - 1) / (up.back() - up.front()) * time_scale;
    return s;
}

}  // namespace chute::validation
