#include "simulation.hpp"

#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>

#include "body_series.hpp"
#include "contact_log.hpp"
#include "lumped_comparison.hpp"
#include "trajectory_summary.hpp"
#include "coupled_step.hpp"
#include "case_file.hpp"
#include "checkpoint.hpp"
#include "diagnostics.hpp"
#include "field_output.hpp"
#include "gather.hpp"
#include "hdf5_file.hpp"
#include "immersed_boundary.hpp"
#include "stop_request.hpp"
#include "timeseries.hpp"

namespace chute {

namespace {

using clock = std::chrono::steady_clock;
double since(clock::time_point t0) { return std::chrono::duration<double>(clock::now() - t0).count(); }

std::vector<CheckpointField> checkpoint_fields(FlowSolver& s, KEpsilon* turbulence) {
    std::vector<CheckpointField> f = {{"u", &s.velocity().u, 1, 0},
                                      {"v", &s.velocity().v, 0, 1},
                                      {"p", &s.pressure(), 0, 0},
                                      {"p_old", &s.previous_pressure(), 0, 0},
                                      {"rhs_old_u", &s.previous_rhs().u, 1, 0},
                                      {"rhs_old_v", &s.previous_rhs().v, 0, 1}};
    if (turbulence) {
        f.push_back({"k", &turbulence->k(), 0, 0});
        f.push_back({"epsilon", &turbulence->epsilon(), 0, 0});
    }
    return f;
}

std::vector<std::string> timeseries_columns(const CaseConfig& c) {
    std::vector<std::string> cols = {"t", "step", "dt", "kinetic_energy", "max_divergence", "poisson_iterations",
                                     "poisson_residual"};
    for (std::size_t k = 0; k < c.probes.size(); ++k)
        for (const char* q : {"u", "v", "p"}) cols.push_back("probe" + std::to_string(k) + "_" + q);
    return cols;
}

std::string format_hms(double seconds) {
    if (!std::isfinite(seconds)) return "--:--:--";
    const long s = std::lround(seconds);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
    return buf;
}

}  // namespace

RunSummary run_simulation(const CaseConfig& config, const RunOptions& options, MPI_Comm comm) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    const bool root = rank == 0;
    // Grid and decomposition problems found only now (the rank count is not in the case file) are case
    // errors too: same exit code, same kind of message, and nothing is written.
    std::unique_ptr<FlowSolver> solver_ptr;
    std::unique_ptr<ImmersedBoundary> ibm_ptr;
    try {
        solver_ptr = std::make_unique<FlowSolver>(config, comm);
        ibm_ptr = std::make_unique<ImmersedBoundary>(solver_ptr->grid(), config);
    } catch (const std::invalid_argument& e) {
        throw CaseError(e.what());
    }
    FlowSolver& solver = *solver_ptr;
    ImmersedBoundary& bodies = *ibm_ptr;
    std::unique_ptr<FreeBodies> free_ptr;
    try {
        free_ptr = std::make_unique<FreeBodies>(config, bodies);
    } catch (const std::invalid_argument& e) {
        throw CaseError(e.what());
    }
    FreeBodies& free_bodies = *free_ptr;
    std::unique_ptr<KEpsilon> turbulence;
    if (config.turbulence.model == TurbulenceModelType::k_epsilon) {
        try {
            turbulence = std::make_unique<KEpsilon>(config, solver, bodies);
        } catch (const std::invalid_argument& e) {
            throw CaseError(e.what());
        }
    }

    if (root) std::filesystem::create_directories(options.out_dir);
    MPI_Barrier(comm);
    if (root && !options.case_yaml.empty())
        write_text_atomically(options.out_dir / "case.yaml", options.case_yaml);
    const Grid& grid = solver.grid();
    if (options.restart) {
        // Lines may have moved during the run that wrote the checkpoint: take them from the checkpoint.
        auto [xl, yl] = read_checkpoint_lines(*options.restart);
        if (static_cast<int>(xl.size()) != grid.global_nx() + 1 || static_cast<int>(yl.size()) != grid.global_ny() + 1)
            throw std::runtime_error("checkpoint " + options.restart->string() + ": grid " +
                                     std::to_string(xl.size() - 1) + "x" + std::to_string(yl.size() - 1) +
                                     " does not match the case grid " + std::to_string(grid.global_nx()) + "x" +
                                     std::to_string(grid.global_ny()));
        solver.set_grid_lines(xl, yl);
        const CheckpointHeader h = read_checkpoint(grid, *options.restart, checkpoint_fields(solver, turbulence.get()));
        solver.restore(h.step, h.time, h.dt_previous, h.implicit_diffusion);
        free_bodies.restore(*options.restart);
    }
    bodies.move_to(solver.time());
    if (turbulence && options.restart) turbulence->restored();

    TimeSeries series(grid, options.out_dir, timeseries_columns(config), options.restart ? solver.time() : -1.0);
    BodySeries body_series(grid, options.out_dir, bodies, config, options.restart ? solver.time() : -1.0);
    FieldOutput fields(grid, options.out_dir, options.restart ? solver.step() : -1);
    ContactLog contacts(root && !free_bodies.empty() ? options.out_dir / "contacts.csv" : std::filesystem::path(),
                        options.restart ? solver.time() : -1.0);
    TrajectorySummary trajectories(config, bodies);  // after a restart: of the part run since
    if (root && !free_bodies.empty() && !options.restart)
        write_lumped_comparison(config, bodies, free_bodies, options.out_dir);
    Probes probes(grid, config.probes);
    HaloExchange halo(grid);
    Field2D uc(grid), vc(grid), omega(grid), pressure_pa(grid);
    // The solver works with the kinematic pressure p/rho; outputs are in pascals (dynamic pressure).
    auto pressure_in_pascals = [&]() -> const Field2D& {
        const Field2D& p = solver.pressure();
        for (int j = -kGhost; j < grid.ny() + kGhost; ++j)
            for (int i = -kGhost; i < grid.nx() + kGhost; ++i) pressure_pa(i, j) = config.density * p(i, j);
        return pressure_pa;
    };

    auto write_fields = [&] {
        cell_centred_velocity(grid, solver.velocity(), uc, vc);
        vorticity(grid, solver.velocity(), omega);
        std::vector<NamedField> out = {
            {"u", &uc}, {"v", &vc}, {"p", &pressure_in_pascals()}, {"vorticity", &omega}};
        if (turbulence) {
            out.push_back({"k", &turbulence->k()});
            out.push_back({"epsilon", &turbulence->epsilon()});
            out.push_back({"nu_t", &turbulence->eddy_viscosity()});
        }
        fields.write(solver.step(), solver.time(), out);
    };
    auto write_checkpoint_now = [&] {
        const auto path = checkpoint_path(options.out_dir, solver.step());
        write_checkpoint(grid, path,
                         {solver.step(), solver.time(), solver.previous_dt(), solver.previous_dt(),
                          solver.implicit_diffusion()},
                         checkpoint_fields(solver, turbulence.get()), free_bodies.checkpoint_arrays());
        prune_checkpoints(options.out_dir, config.checkpoints_kept);
        return path;
    };
    auto record = [&](const StepStats& st, double ke, double div) {
        std::vector<double> row = {solver.time(), static_cast<double>(solver.step()), st.dt, ke, div,
                                   static_cast<double>(st.poisson_iterations), st.poisson_residual};
        if (probes.size() > 0) {
            cell_centred_velocity(grid, solver.velocity(), uc, vc);
            halo.exchange(uc);
            halo.exchange(vc);
            const auto pu = probes.sample(uc), pv = probes.sample(vc), pp = probes.sample(pressure_in_pascals());
            for (std::size_t k = 0; k < probes.size(); ++k) row.insert(row.end(), {pu[k], pv[k], pp[k]});
        }
        series.append(row);
        if (!bodies.empty()) {
            std::vector<BodyForces> forces = bodies.forces(solver.velocity(), solver.pressure(),
                                                              turbulence ? &turbulence->k() : nullptr);
            free_bodies.report(forces);
            body_series.append(solver.time(), forces);
            trajectories.observe(solver.time(), forces);
        }
    };

    RunSummary summary;
    const double eps = 1e-12 * config.end_time;
    if (!options.restart) {
        write_fields();
        record(StepStats{}, kinetic_energy(grid, solver.velocity()), max_divergence(grid, solver.velocity()));
    }
    double next_field_time = config.field_interval > 0.0
                                 ? (std::floor(solver.time() / config.field_interval + 1e-9) + 1) * config.field_interval
                                 : std::numeric_limits<double>::infinity();
    double next_checkpoint_time =
        config.checkpoint_interval > 0.0
            ? (std::floor(solver.time() / config.checkpoint_interval + 1e-9) + 1) * config.checkpoint_interval
            : std::numeric_limits<double>::infinity();

    const auto loop_start = clock::now();
    auto last_progress = loop_start;
    const double start_time = solver.time();
    double t_momentum = 0, t_poisson = 0, t_correction = 0, t_output = 0, t_forcing = 0, t_turbulence = 0,
           iterations = 0, diffusion_iterations = 0;
    summary.seconds_per_step_min = std::numeric_limits<double>::infinity();
    double ke = 0.0, div = 0.0, first_dt = 0.0;

    while (solver.time() < config.end_time - eps && (config.max_steps < 0 || summary.steps < config.max_steps)) {
        const auto step_start = clock::now();
        // Land exactly on the end time; avoid a sliver step by splitting the last two evenly.
        double dt = std::min(solver.next_dt(), free_bodies.max_dt(config.cfl));
        const double remaining = config.end_time - solver.time();
        if (dt >= remaining) dt = remaining;
        else if (dt > 0.5 * remaining) dt = 0.5 * remaining;
        // One step: predict u*, force it to follow the bodies at t^{n+1}, project (DESIGN.md data flow).
        const StepStats st = advance(solver, bodies, free_bodies, dt, turbulence.get());
        if (!free_bodies.events().empty()) {
            contacts.record(free_bodies.events());
            trajectories.impacts(free_bodies.events());
        }

        ke = kinetic_energy(grid, solver.velocity());
        div = max_divergence(grid, solver.velocity());
        // A blow-up also shows as a time step that collapses (the CFL limit follows the growing speed).
        if (first_dt == 0.0) first_dt = st.dt;
        const bool dt_collapsed = !config.fixed_dt && st.dt < 1e-6 * first_dt;
        const std::optional<std::string> turbulence_problem = turbulence ? turbulence->check() : std::nullopt;
        if (!std::isfinite(ke) || !std::isfinite(div) || div * st.dt > config.divergence_limit || dt_collapsed ||
            turbulence_problem) {
            std::ostringstream msg;
            msg << "run diverged at step " << solver.step() << ", t = " << solver.time() << ": ";
            if (turbulence_problem) msg << *turbulence_problem;
            else if (!std::isfinite(ke)) msg << "kinetic energy is " << ke;
            else if (dt_collapsed) msg << "the time step fell to " << st.dt << " s, a millionth of the first step's "
                                       << first_dt << " s (the velocity is blowing up)";
            else msg << "max |div u| dt = " << div * st.dt << " exceeds numerics.divergence_limit = "
                     << config.divergence_limit;
            msg << " (dt = " << st.dt << "; try a smaller numerics.cfl, a finer grid, or the van_leer scheme)."
                << " Outputs written so far are kept in " << options.out_dir.string();
            series.write_hdf5();
            body_series.write_hdf5();
            throw RunDiverged(msg.str());
        }

        const auto out_start = clock::now();
        if (config.timeseries_every > 0 && solver.step() % config.timeseries_every == 0) record(st, ke, div);
        if (solver.time() >= next_field_time - eps) {
            write_fields();
            while (next_field_time <= solver.time() + eps) next_field_time += config.field_interval;
        }
        if (solver.time() >= next_checkpoint_time - eps) {
            summary.last_checkpoint = write_checkpoint_now();
            series.write_hdf5();
            body_series.write_hdf5();
            while (next_checkpoint_time <= solver.time() + eps) next_checkpoint_time += config.checkpoint_interval;
        }
        const double out_seconds = since(out_start);

        const double step_seconds = since(step_start);
        ++summary.steps;
        t_momentum += st.seconds_momentum;
        t_poisson += st.seconds_poisson;
        t_correction += st.seconds_correction;
        t_output += out_seconds;
        t_forcing += st.seconds_forcing;
        t_turbulence += st.seconds_turbulence;
        iterations += st.poisson_iterations;
        diffusion_iterations += st.diffusion_iterations;
        if (solver.implicit_diffusion()) ++summary.implicit_steps;
        summary.seconds_per_step_min = std::min(summary.seconds_per_step_min, step_seconds);
        summary.seconds_per_step_max = std::max(summary.seconds_per_step_max, step_seconds);

        summary.stopped_by_signal = stop_requested(comm);
        if (summary.stopped_by_signal) {
            if (root) std::printf("chute: signal %d received: stopping after step %ld, t = %.6g, writing a checkpoint\n",
                                  summary.stopped_by_signal, solver.step(), solver.time());
            break;
        }

        if (!options.quiet && root && config.progress_interval >= 0.0 &&
            since(last_progress) >= config.progress_interval) {
            last_progress = clock::now();
            const double wall = since(loop_start);
            const double done = (solver.time() - start_time) / (config.end_time - start_time);
            std::printf("step %8ld  t = %-11.5g dt = %-10.4g  |div| = %-9.2e  poisson it %3d  diffusion it %3d  wall %s  left %s\n",
                        solver.step(), solver.time(), st.dt, div, st.poisson_iterations, st.diffusion_iterations,
                        format_hms(wall).c_str(), format_hms(done > 0 ? wall * (1.0 - done) / done : NAN).c_str());
            std::fflush(stdout);
        }
    }
    summary.wall_seconds = since(loop_start);

    if (summary.steps > 0 || !options.restart) write_fields();
    summary.last_checkpoint = write_checkpoint_now();
    series.write_hdf5();
    body_series.write_hdf5();

    summary.bodies = trajectories.text();
    summary.time = solver.time();
    summary.kinetic_energy = kinetic_energy(grid, solver.velocity());
    summary.max_divergence = max_divergence(grid, solver.velocity());
    if (summary.steps > 0) {
        const double total = summary.wall_seconds;
        summary.seconds_per_step_mean = total / summary.steps;
        summary.share_momentum = t_momentum / total;
        summary.share_poisson = t_poisson / total;
        summary.share_correction = t_correction / total;
        summary.share_output = t_output / total;
        summary.share_forcing = t_forcing / total;
        summary.share_turbulence = t_turbulence / total;
        summary.mean_poisson_iterations = iterations / summary.steps;
        if (summary.implicit_steps > 0) summary.mean_diffusion_iterations = diffusion_iterations / summary.implicit_steps;
        summary.cell_steps_per_second = static_cast<double>(grid.global_cells()) * summary.steps / total;
    } else {
        summary.seconds_per_step_min = 0.0;
    }
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
        std::snprintf(buf, sizeof buf,
                      "shares: momentum %.0f %%, body forcing %.1f %%, poisson %.0f %% (%.1f iterations/step), "
                      "projection %.0f %%, turbulence %.1f %%, outputs and body forces %.0f %%\n",
                      100 * s.share_momentum, 100 * s.share_forcing, 100 * s.share_poisson,
                      s.mean_poisson_iterations, 100 * s.share_correction, 100 * s.share_turbulence,
                      100 * s.share_output);
        o << buf;
        if (s.implicit_steps > 0) {
            std::snprintf(buf, sizeof buf, "implicit diffusion in %ld of %ld steps, %.1f PCG iterations each (in the momentum share)\n",
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
