#pragma once
// A whole run: the model built from the case (model.hpp), then the loop (CaNS, incflo):
//
//   while t < end:  choose dt -> advance one step (step.hpp) -> force measures -> check health
//                   -> write what is due (run_outputs.hpp) -> stop on a signal -> progress line
//   final fields, checkpoint, series' HDF5 copies, timing summary
// Everything written is written atomically, so a run that aborts (divergence, bad input, Ctrl-C) keeps
// all it wrote before.
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "case_config.hpp"
#include "flow_solver.hpp"
#include "run_failure.hpp"

namespace chute {

struct RunOptions {
    std::filesystem::path out_dir = "results";
    std::optional<std::filesystem::path> restart;  // checkpoint to continue from
    std::string case_yaml;                         // the case as run, saved as out_dir/case.yaml
    bool quiet = false;                            // no progress lines (tests)
    std::string carrier;  // how bodies are carried, a name registered in carriers.hpp; empty: as the case says
};

struct RunSummary {
    long steps = 0;             // steps taken in this run (after a restart: since the restart)
    int stopped_by_signal = 0;  // SIGINT or SIGTERM received: the run stopped early, with a checkpoint
    double time = 0.0;          // final simulated time
    double wall_seconds = 0.0;  // time loop only
    double seconds_per_step_mean = 0.0, seconds_per_step_min = 0.0, seconds_per_step_max = 0.0;
    // Wall seconds per stage of the step (step.hpp: momentum, bodies, poisson, correction, turbulence, forces;
    // the loop's health and outputs), in the order they first ran.
    std::vector<std::pair<std::string, double>> stage_seconds;
    double mean_poisson_iterations = 0.0;
    double mean_diffusion_iterations = 0.0;  // per implicit step: PCG iterations of the larger component
    long implicit_steps = 0;                 // steps whose diffusion was implicit
    double cell_steps_per_second = 0.0;
    double kinetic_energy = 0.0, max_divergence = 0.0;
    std::filesystem::path last_checkpoint;
    std::string bodies;  // per free body: fall speed, impacts, rebound height, runout, peak forces
};

// Runs the case on `comm`. Throws RunFailure (core/run_failure.hpp) when the run cannot go on: it left the
// stable regime (health_check.hpp) or a step reached one of the method's bounds; the outputs written so far
// are flushed first and the message says where they are. Bad restarts throw std::runtime_error.
RunSummary run_simulation(const CaseConfig& config, const RunOptions& options, MPI_Comm comm);

// Human-readable timing summary (printed at the end of a run).
std::string format_summary(const RunSummary& s, long long cells);

}  // namespace chute
