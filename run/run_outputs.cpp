#include "run_outputs.hpp"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "checkpoint.hpp"
#include "gather.hpp"
#include "hdf5_file.hpp"
#include "lumped_comparison.hpp"
#include "output_error.hpp"
#include "restart_state.hpp"
#include "results_folder.hpp"

namespace chute {

namespace {

std::vector<std::string> timeseries_columns(const CaseConfig& c) {
    std::vector<std::string> cols = {"t",
                                     "step",
                                     "dt",
                                     "kinetic_energy",
                                     "max_divergence",
                                     "poisson_iterations",
                                     "poisson_residual",
                                     "coupling_passes"};
    for (std::size_t k = 0; k < c.probes.size(); ++k)
        for (const char* q : {"u", "v", "p"}) cols.push_back("probe" + std::to_string(k) + "_" + q);
    return cols;
}

// The first multiple of `interval` after t (infinity: never).
double next_time(double t, double interval) {
    return interval > 0.0 ? (std::floor(t / interval + 1e-9) + 1) * interval : std::numeric_limits<double>::infinity();
}

// The schedule's next time after t: normally one or a few additions of the interval. A schedule far
// behind t (a restart with a new interval), or an interval below the round-off of t (time.end 1e308 with
// an interval of 10 s, where adding changes nothing), jumps to the first multiple above t instead.
double advance_schedule(double next, double t, double interval) {
    for (int k = 0; k < 1000 && next <= t; ++k) next += interval;
    if (next <= t) next = std::max(std::nextafter(t, std::numeric_limits<double>::infinity()), next_time(t, interval));
    return next;
}

bool is_root(MPI_Comm comm) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    return rank == 0;
}

// Collective: rank 0 makes the folder, checks that it takes files (every rank throws OutputError if not:
// nothing is written and no step taken) and writes the case as run, before anything else is written there.
std::filesystem::path prepare(const RunOptions& options, MPI_Comm comm) {
    run_on_root(comm, [&] {
        const std::vector<std::string> removed = prepare_results_folder(options.out_dir);
        if (!removed.empty() && !options.quiet) {
            std::printf("chute: removed %zu partial file(s) left in %s by an interrupted run:", removed.size(),
                        options.out_dir.string().c_str());
            for (const std::string& name : removed) std::printf(" %s", name.c_str());
            std::printf("\n");
        }
        if (!options.case_yaml.empty()) write_text_atomically(options.out_dir / "case.yaml", options.case_yaml);
    });
    return options.out_dir;
}

}  // namespace

RunOutputs::RunOutputs(Model& model, const RunOptions& options)
    : model_(model),
      options_(options),
      series_(model.flow().grid(), prepare(options, model.flow().grid().comm()), timeseries_columns(model.config()),
              options.restart ? model.flow().time() : -1.0),
      body_series_(model.flow().grid(), options.out_dir, model.carrier(), model.config(),
                   options.restart ? model.flow().time() : -1.0),
      fields_(model.flow().grid(), options.out_dir, options.restart ? model.flow().step() : -1),
      contacts_(is_root(model.flow().grid().comm()) && !model.free_bodies().empty() ? options.out_dir / "contacts.csv"
                                                                                    : std::filesystem::path(),
                options.restart ? model.flow().time() : -1.0),
      trajectories_(model.config(), model.carrier()),  // after a restart: of the part run since
      probes_(model.flow().grid(), model.config().probes),
      halo_(model.flow().grid()),
      uc_(model.flow().grid()),
      vc_(model.flow().grid()),
      omega_(model.flow().grid()),
      pressure_pa_(model.flow().grid()),
      next_field_time_(next_time(model.flow().time(), model.config().field_interval)),
      next_checkpoint_time_(next_time(model.flow().time(), model.config().checkpoint_interval)) {}

template <class Work>
void RunOutputs::writing(Work&& work) {
    try {
        work();
    } catch (const OutputError& e) {
        const std::filesystem::path newest =
            !last_checkpoint_.empty() ? last_checkpoint_ : options_.restart.value_or(std::filesystem::path());
        throw OutputError(std::string(e.what()) + "\n  Every file written before is complete (results folder '" +
                          options_.out_dir.string() + "'). " +
                          (newest.empty() ? "No checkpoint was written yet."
                                          : "The newest checkpoint is '" + newest.string() +
                                                "': with room to write, continue with --restart '" +
                                                options_.out_dir.string() + "' (its newest readable checkpoint)."));
    }
}

void RunOutputs::start(const FlowHealth& health, const std::vector<BodyForces>& forces) {
    writing([&] { start_outputs(health, forces); });
}

void RunOutputs::after_step(const StepStats& step, const FlowHealth& health, const std::vector<BodyForces>& forces) {
    writing([&] { write_due(step, health, forces); });
}

std::filesystem::path RunOutputs::finish(bool stepped) {
    writing([&] { write_final(stepped); });
    return last_checkpoint_;
}

void RunOutputs::flush() {
    writing([&] { write_series_hdf5(); });
}

void RunOutputs::start_outputs(const FlowHealth& health, const std::vector<BodyForces>& forces) {
    if (options_.restart) return;
    if (is_root(model_.flow().grid().comm()) && !model_.free_bodies().empty())
        write_lumped_comparison(model_.config(), model_.bodies(), model_.free_bodies(), options_.out_dir);
    write_fields();
    record(StepStats{}, health, forces);
}

void RunOutputs::write_due(const StepStats& step, const FlowHealth& health, const std::vector<BodyForces>& forces) {
    const FlowSolver& flow = model_.flow();
    const CaseConfig& config = model_.config();
    const auto& events = model_.free_bodies().events();
    if (!events.empty()) {
        contacts_.record(events);
        trajectories_.impacts(events);
    }
    const double eps = 1e-12 * config.end_time;
    if (config.timeseries_every > 0 && flow.step() % config.timeseries_every == 0) record(step, health, forces);
    if (flow.time() >= next_field_time_ - eps) {
        write_fields();
        next_field_time_ = advance_schedule(next_field_time_, flow.time() + eps, config.field_interval);
    }
    if (flow.time() >= next_checkpoint_time_ - eps) {
        write_checkpoint();
        write_series_hdf5();
        next_checkpoint_time_ = advance_schedule(next_checkpoint_time_, flow.time() + eps, config.checkpoint_interval);
    }
}

void RunOutputs::write_final(bool stepped) {
    if (stepped || !options_.restart) write_fields();
    write_checkpoint();
    write_series_hdf5();
}

void RunOutputs::write_series_hdf5() {
    series_.write_hdf5();
    body_series_.write_hdf5();
}

void RunOutputs::write_checkpoint() {
    last_checkpoint_ = write_run_checkpoint(model_, options_.out_dir, model_.config().checkpoints_kept);
}

// The solver works with the kinematic pressure p/rho; outputs are in pascals (dynamic pressure).
void RunOutputs::record(const StepStats& step, const FlowHealth& health, const std::vector<BodyForces>& forces) {
    const FlowSolver& flow = model_.flow();
    const Grid& grid = flow.grid();
    std::vector<double> row = {flow.time(),
                               static_cast<double>(flow.step()),
                               step.dt,
                               health.kinetic_energy,
                               health.max_divergence,
                               static_cast<double>(step.poisson_iterations),
                               step.poisson_residual,
                               static_cast<double>(step.coupling_passes)};
    if (probes_.size() > 0) {
        cell_centred_velocity(grid, flow.velocity(), uc_, vc_);
        halo_.exchange(uc_);
        halo_.exchange(vc_);
        const Field2D& p = flow.pressure();
        for (int j = -kGhost; j < grid.ny() + kGhost; ++j)
            for (int i = -kGhost; i < grid.nx() + kGhost; ++i) pressure_pa_(i, j) = model_.config().density * p(i, j);
        const auto pu = probes_.sample(uc_), pv = probes_.sample(vc_), pp = probes_.sample(pressure_pa_);
        for (std::size_t k = 0; k < probes_.size(); ++k) row.insert(row.end(), {pu[k], pv[k], pp[k]});
    }
    series_.append(row);
    if (!model_.bodies().empty()) {
        body_series_.append(flow.time(), forces);
        trajectories_.observe(flow.time(), forces);
    }
}

void RunOutputs::write_fields() {
    const FlowSolver& flow = model_.flow();
    const Grid& grid = flow.grid();
    cell_centred_velocity(grid, flow.velocity(), uc_, vc_);
    vorticity(grid, flow.velocity(), omega_);
    const Field2D& p = flow.pressure();
    for (int j = -kGhost; j < grid.ny() + kGhost; ++j)
        for (int i = -kGhost; i < grid.nx() + kGhost; ++i) pressure_pa_(i, j) = model_.config().density * p(i, j);
    // A body-fitted hole holds no flow: its cells are written as NaN (blank in ParaView and the plots), not the
    // ghost values its faces carry for the stencils beside it.
    if (const Field2D* fluid = flow.fluid_cells())
        for (int j = 0; j < grid.ny(); ++j)
            for (int i = 0; i < grid.nx(); ++i)
                if ((*fluid)(i, j) == 0.0)
                    uc_(i, j) = vc_(i, j) = pressure_pa_(i, j) = omega_(i, j) =
                        std::numeric_limits<double>::quiet_NaN();
    std::vector<NamedField> out = {{"u", &uc_}, {"v", &vc_}, {"p", &pressure_pa_}, {"vorticity", &omega_}};
    if (const KEpsilon* turbulence = model_.turbulence()) {
        out.push_back({"k", &turbulence->k()});
        out.push_back({"epsilon", &turbulence->epsilon()});
        out.push_back({"nu_t", &turbulence->eddy_viscosity()});
    }
    fields_.write(flow.step(), flow.time(), out);
}

}  // namespace chute
