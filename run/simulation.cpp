#include "simulation.hpp"

#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <sstream>

#include "case_file.hpp"
#include "health_check.hpp"
#include "model.hpp"
#include "restart_state.hpp"
#include "run_outputs.hpp"
#include "step.hpp"
#include "stop_request.hpp"

namespace chute {

namespace {

using clock = std::chrono::steady_clock;
double since(clock::time_point t0) { return std::chrono::duration<double>(clock::now() - t0).count(); }

// Grid, decomposition and body problems found only now (the rank count is not in the case file) are case
// errors too: same exit code, same kind of message, and nothing is written.
std::unique_ptr<Model> build_model(const CaseConfig& config, const std::string& carrier, MPI_Comm comm) {
    try {
        return std::make_unique<Model>(config, comm, carrier);
    } catch (const std::invalid_argument& e) {
        throw CaseError(e.what());
    }
}

// The stable step, landing exactly on the end time. Within kEndSteps stable steps of the end the run takes equal
// steps that land on it, each at most 1/kEndSteps shorter than the stable one: a step that shrinks at once (the
// old last two half steps) set off a transient in the forces of 7 % on the free fall's last step and 19-27 % on
// a fixed cylinder (docs/validation.md, The time step in the force measures). A remainder within round-off of a
// whole number of steps is that number (the time is a sum of steps).
constexpr double kEndSteps = 10.0;
double next_dt(const Model& model) {
    const double dt = model.stable_dt(), remaining = model.config().end_time - model.flow().time();
    if (dt >= remaining * (1.0 - 1e-9)) return remaining;
    if (remaining >= kEndSteps * dt) return dt;
    return remaining / std::ceil(remaining / dt * (1.0 - 1e-9));
}

// Where a step failed: its number, and the time it started from (the last completed one).
std::string where_failed(const Model& model) {
    std::ostringstream m;
    m << "run stopped in step " << model.flow().step() + 1 << ", after t = " << model.flow().time() << ": ";
    return m.str();
}

// A run that cannot go on keeps what it has written: flush, then say where it is.
[[noreturn]] void stop_failed(RunOutputs& outputs, const RunOptions& options, const std::string& why) {
    outputs.flush();
    throw RunFailure(why + " Outputs written so far are kept in " + options.out_dir.string());
}

bool finished(const Model& model, const RunSummary& summary) {
    const CaseConfig& c = model.config();
    return model.flow().time() >= c.end_time - 1e-12 * c.end_time || (c.max_steps >= 0 && summary.steps >= c.max_steps);
}

std::string format_hms(double seconds) {
    if (!std::isfinite(seconds)) return "--:--:--";
    const long s = std::lround(seconds);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
    return buf;
}

// One line every output.progress_interval wall seconds (rank 0).
class Progress {
public:
    Progress(const Model& model, const RunOptions& options)
        : show_(!options.quiet && model.config().progress_interval >= 0.0 && is_root(model)),
          interval_(model.config().progress_interval),
          start_time_(model.flow().time()),
          end_time_(model.config().end_time),
          start_(clock::now()),
          last_(start_) {}
    void report(const Model& model, const StepStats& step, const FlowHealth& health) {
        if (!show_ || since(last_) < interval_) return;
        last_ = clock::now();
        const double wall = since(start_), done = (model.flow().time() - start_time_) / (end_time_ - start_time_);
        std::printf(
            "step %8ld  t = %-11.5g dt = %-10.4g  |div| = %-9.2e  poisson it %3d  diffusion it %3d  wall %s  left %s\n",
            model.flow().step(), model.flow().time(), step.dt, health.max_divergence, step.poisson_iterations,
            step.diffusion_iterations, format_hms(wall).c_str(),
            format_hms(done > 0 ? wall * (1.0 - done) / done : NAN).c_str());
        std::fflush(stdout);
    }
    static bool is_root(const Model& model) { return model.flow().grid().rank() == 0; }

private:
    bool show_;
    double interval_, start_time_, end_time_;
    clock::time_point start_, last_;
};

// A step's counts and wall time into the summary.
void count_step(RunSummary& s, const Model& model, const StepStats& step, double seconds, double& iterations,
                double& diffusion_iterations) {
    ++s.steps;
    iterations += step.poisson_iterations;
    diffusion_iterations += step.diffusion_iterations;
    if (model.flow().implicit_diffusion()) ++s.implicit_steps;
    s.seconds_per_step_min = std::min(s.seconds_per_step_min, seconds);
    s.seconds_per_step_max = std::max(s.seconds_per_step_max, seconds);
}

void finish_summary(RunSummary& s, const Model& model, const StageTimer& stages, double iterations,
                    double diffusion_iterations) {
    const FlowHealth health = flow_health(model.flow());
    s.time = model.flow().time();
    s.kinetic_energy = health.kinetic_energy;
    s.max_divergence = health.max_divergence;
    s.stage_seconds = stages.stages();
    if (s.steps == 0) {
        s.seconds_per_step_min = 0.0;
        return;
    }
    s.seconds_per_step_mean = s.wall_seconds / s.steps;
    s.mean_poisson_iterations = iterations / s.steps;
    if (s.implicit_steps > 0) s.mean_diffusion_iterations = diffusion_iterations / s.implicit_steps;
    s.cell_steps_per_second = static_cast<double>(model.flow().grid().global_cells()) * s.steps / s.wall_seconds;
}

}  // namespace

RunSummary run_simulation(const CaseConfig& config, const RunOptions& options, MPI_Comm comm) {
    const std::unique_ptr<Model> model = build_model(config, options.carrier, comm);
    if (options.restart) restore_run(*model, *options.restart);
    RunOutputs outputs(*model, options);
    if (!options.restart) outputs.start(flow_health(model->flow()), measure_forces(*model));

    RunSummary summary;
    summary.seconds_per_step_min = std::numeric_limits<double>::infinity();
    StageTimer stages(kStepStages);
    stages.add("health", 0.0);
    stages.add("outputs", 0.0);
    HealthCheck health_check(config);
    Progress progress(*model, options);
    double iterations = 0.0, diffusion_iterations = 0.0;
    const auto loop_start = clock::now();
    while (!finished(*model, summary)) {
        const auto step_start = clock::now();
        StepStats step;
        try {
            step = take_step(*model, next_dt(*model), &stages);
        } catch (const RunFailure& e) {
            stop_failed(outputs, options, where_failed(*model) + e.what() + ".");
        }
        const std::vector<BodyForces> forces = measure_forces(*model, &stages);
        FlowHealth health;
        std::optional<std::string> problem;
        {
            auto timed = stages.scope("health");
            health = flow_health(model->flow());
            problem = health_check.problem(*model, step, health);
        }
        if (problem) stop_failed(outputs, options, *problem);
        if (const auto note = health_check.warning(*model, step); note && Progress::is_root(*model))
            std::fprintf(stderr, "chute: warning: %s\n", note->c_str());
        {
            auto timed = stages.scope("outputs");
            outputs.after_step(step, health, forces);
        }
        count_step(summary, *model, step, since(step_start), iterations, diffusion_iterations);
        if ((summary.stopped_by_signal = stop_requested(comm))) {
            if (Progress::is_root(*model))
                std::printf("chute: signal %d received: stopping after step %ld, t = %.6g, writing a checkpoint\n",
                            summary.stopped_by_signal, model->flow().step(), model->flow().time());
            break;
        }
        progress.report(*model, step, health);
    }
    summary.wall_seconds = since(loop_start);
    summary.last_checkpoint = outputs.finish(summary.steps > 0);
    summary.bodies = outputs.trajectories();
    finish_summary(summary, *model, stages, iterations, diffusion_iterations);
    return summary;
}

std::string format_summary(const RunSummary& s, long long cells) {
    std::ostringstream o;
    char buf[256];
    std::snprintf(buf, sizeof buf, "%ld steps to t = %.6g in %.3f s wall (time loop)\n", s.steps, s.time,
                  s.wall_seconds);
    o << buf;
    if (s.steps > 0) {
        std::snprintf(buf, sizeof buf, "per step: mean %.3g ms, min %.3g ms, max %.3g ms; %.3f us per cell-step\n",
                      1e3 * s.seconds_per_step_mean, 1e3 * s.seconds_per_step_min, 1e3 * s.seconds_per_step_max,
                      1e6 * s.seconds_per_step_mean / static_cast<double>(cells));
        o << buf;
        o << "shares:";
        double timed = 0.0;
        for (const auto& [stage, seconds] : s.stage_seconds) {
            timed += seconds;
            std::snprintf(buf, sizeof buf, " %s %.1f %%", stage.c_str(), 100 * seconds / s.wall_seconds);
            o << buf;
            if (stage == "poisson") {
                if (s.mean_poisson_iterations > 0.0) {
                    std::snprintf(buf, sizeof buf, " (%.1f iterations/step)", s.mean_poisson_iterations);
                    o << buf;
                } else {
                    o << " (direct)";
                }
            }
            o << ",";
        }
        std::snprintf(buf, sizeof buf, " other %.1f %%\n", 100 * (s.wall_seconds - timed) / s.wall_seconds);
        o << buf;
        if (s.implicit_steps > 0) {
            std::snprintf(buf, sizeof buf,
                          "implicit diffusion in %ld of %ld steps, %.1f PCG iterations each (in the momentum share)\n",
                          s.implicit_steps, s.steps, s.mean_diffusion_iterations);
            o << buf;
        }
        std::snprintf(buf, sizeof buf, "speed: %.3g cell-steps per second\n", s.cell_steps_per_second);
        o << buf;
    }
    std::snprintf(buf, sizeof buf, "final kinetic energy %.6g, max |div u| %.3g\n", s.kinetic_energy, s.max_divergence);
    o << buf << s.bodies;
    return o.str();
}

}  // namespace chute
