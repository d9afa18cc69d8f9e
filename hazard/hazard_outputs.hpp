#pragma once
// A hazard run's files (rank 0), each written atomically:
//   case.yaml        the case as run (with its --set overrides)
//   summary.txt      counts, stopping percentiles, collectors (also printed)
//   trajectories.csv one row per block: draws and outcome
//   stations.csv     per station along the profile: reach probability and envelopes (mean, p95)
//   collectors.csv   per collector: passing, hits, hit probability, energy of the hits
//   paths.csv        the first output.paths trajectories whole
//   hazard.h5        all of the above as arrays, and the per-block station and collector matrices
#include <filesystem>
#include <string>

#include "hazard_statistics.hpp"

namespace chute {

std::string format_hazard_summary(const HazardCase& c, const HazardSummary& s, double seconds, int ranks);
void write_hazard_outputs(const HazardCase& c, const HazardResults& r, const HazardSummary& s,
                          const std::string& case_text, int ranks, const std::filesystem::path& out_dir);

}  // namespace chute
