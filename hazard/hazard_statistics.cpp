#include "hazard_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace chute {

double percentile(std::vector<double> values, double p) {
    std::erase_if(values, [](double v) { return !std::isfinite(v); });
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(values.begin(), values.end());
    const double at = p * static_cast<double>(values.size() - 1);
    const std::size_t lo = static_cast<std::size_t>(std::floor(at));
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (at - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

namespace {

Envelope envelope(const std::vector<double>& matrix, long rows, int cols, int col) {
    std::vector<double> v;
    double sum = 0.0;
    for (long i = 0; i < rows; ++i) {
        const double x = matrix[i * cols + col];
        if (std::isfinite(x)) v.push_back(x), sum += x;
    }
    if (v.empty()) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    return {sum / static_cast<double>(v.size()), percentile(v, 0.95)};
}

}  // namespace

HazardSummary summarize(const HazardCase& c, const HazardResults& r) {
    HazardSummary s;
    const long N = static_cast<long>(r.outcomes.size());
    const int S = static_cast<int>(r.stations.size()), C = static_cast<int>(c.collectors.size());
    const SlopeProfile profile = c.profile();
    s.trajectories = N;
    std::vector<double> stops(N);
    for (long i = 0; i < N; ++i) {
        const TrajectoryOutcome& o = r.outcomes[i];
        s.ends[static_cast<int>(o.end)] += 1;
        stops[i] = o.end == TrajectoryEnd::past_end ? profile.x_max() : o.stop.x();
    }
    s.stop_p50 = percentile(stops, 0.5);
    s.stop_p90 = percentile(stops, 0.9);
    s.stop_p95 = percentile(stops, 0.95);
    s.stop_p99 = percentile(stops, 0.99);
    s.stop_max = percentile(stops, 1.0);
    std::vector<double> sorted = stops;
    std::sort(sorted.begin(), sorted.end());
    for (int j = 0; j < S; ++j) {
        StationSummary st;
        st.x = r.stations[j];
        st.ground = profile.height_at(st.x);
        const auto beyond = sorted.end() - std::upper_bound(sorted.begin(), sorted.end(), st.x);
        st.reach = N ? static_cast<double>(beyond) / static_cast<double>(N) : 0.0;
        long passing = 0;
        for (long i = 0; i < N; ++i) passing += std::isfinite(r.speed[i * S + j]) ? 1 : 0;
        st.passing_fraction = N ? static_cast<double>(passing) / static_cast<double>(N) : 0.0;
        st.speed = envelope(r.speed, N, S, j);
        st.kinetic_energy = envelope(r.kinetic_energy, N, S, j);
        st.rotational_energy = envelope(r.rotational_energy, N, S, j);
        st.height = envelope(r.height, N, S, j);
        s.stations.push_back(st);
    }
    for (int k = 0; k < C; ++k) {
        CollectorSummary cs;
        cs.collector = c.collectors[k];
        std::vector<double> hits;
        for (long i = 0; i < N; ++i) {
            const double h = r.collector_height[i * C + k];
            if (!std::isfinite(h)) continue;
            cs.passing += 1;
            if (h <= cs.collector.height) hits.push_back(r.collector_energy[i * C + k]);
        }
        cs.hits = static_cast<long>(hits.size());
        cs.hit_probability = N ? static_cast<double>(cs.hits) / static_cast<double>(N) : 0.0;
        cs.energy_mean = cs.energy_p50 = cs.energy_p95 = cs.energy_max = std::numeric_limits<double>::quiet_NaN();
        if (!hits.empty()) {
            double sum = 0.0;
            for (double e : hits) sum += e;
            cs.energy_mean = sum / static_cast<double>(hits.size());
            cs.energy_p50 = percentile(hits, 0.5);
            cs.energy_p95 = percentile(hits, 0.95);
            cs.energy_max = percentile(hits, 1.0);
        }
        s.collectors.push_back(cs);
    }
    return s;
}

}  // namespace chute
