#pragma once
// What engineers read from a hazard run (rank 0, from the gathered results): where blocks stop (percentiles, the
// probability of reaching past each station), envelopes along the profile (mean and 95th percentile of speed,
// translational and rotational kinetic energy and bounce height among the blocks that pass each station), and
// each collector's passing count, hits and the energy of the hits.
#include <array>
#include <vector>

#include "monte_carlo.hpp"

namespace chute {

// The p-quantile (0..1) of the finite values, linearly interpolated between order statistics (the definition
// numpy uses by default, Hyndman & Fan's type 7); NaN if there are none.
double percentile(std::vector<double> values, double p);

struct Envelope {
    double mean = 0.0, p95 = 0.0;
};

struct StationSummary {
    double x = 0.0, ground = 0.0;
    double reach = 0.0;             // fraction of all blocks that stop beyond x (or leave the profile's end)
    double passing_fraction = 0.0;  // of all blocks, those that cross x
    Envelope speed, kinetic_energy, rotational_energy, height;
};

struct CollectorSummary {
    Collector collector;
    long passing = 0, hits = 0;
    double hit_probability = 0.0;                                                    // hits / all blocks
    double energy_mean = 0.0, energy_p50 = 0.0, energy_p95 = 0.0, energy_max = 0.0;  // J, of the hits (NaN: none)
};

struct HazardSummary {
    long trajectories = 0;
    std::array<long, 4> ends{};  // by TrajectoryEnd: rest, past_end, past_start, time_limit
    double stop_p50 = 0.0, stop_p90 = 0.0, stop_p95 = 0.0, stop_p99 = 0.0, stop_max = 0.0;  // x
    std::vector<StationSummary> stations;
    std::vector<CollectorSummary> collectors;
};

HazardSummary summarize(const HazardCase& c, const HazardResults& r);

}  // namespace chute
