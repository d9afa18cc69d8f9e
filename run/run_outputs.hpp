#pragma once
// What a run writes, and when (docs/design.md, "Outputs a user gets from one run"):
//   every `timeseries_every` steps   timeseries.csv (step, dt, energy, divergence, solver iterations, probes),
//                                    body_<name>.csv (kinematics and the force record), the trajectory summary
//   at each impact                   contacts.csv
//   every output.field_interval      fields_<step>.h5 + fields.xdmf (u, v, p in Pa, vorticity, k, eps, nu_t)
//   every output.checkpoint_interval a checkpoint, and the series' HDF5 copies
//   at the start                     case.yaml as run, lumped_<body>.csv (the lumped models of the release)
// After a restart the series continue from the checkpoint's time. Every file is written atomically. A file
// that cannot be written (full disk, file size limit, unwritable folder) stops the run with an OutputError
// naming it, the results folder and the newest checkpoint to continue from.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "body_series.hpp"
#include "contact_log.hpp"
#include "diagnostics.hpp"
#include "field_output.hpp"
#include "health_check.hpp"
#include "model.hpp"
#include "simulation.hpp"
#include "timeseries.hpp"
#include "trajectory_summary.hpp"

namespace chute {

class RunOutputs {
public:
    // Collective. Creates the output folder and checks it takes files (OutputError naming it if not, before
    // anything is written); after a restart (options.restart) continues the series.
    RunOutputs(Model& model, const RunOptions& options);

    // A fresh run's first record and fields (t = 0), and the lumped comparison.
    void start(const FlowHealth& health, const std::vector<BodyForces>& forces);
    // After each step: contact events; the series when due; fields and a checkpoint when their time has come.
    void after_step(const StepStats& step, const FlowHealth& health, const std::vector<BodyForces>& forces);
    // The end of a run (or a stop on a signal): last fields (if any step was taken or the run is fresh), a
    // checkpoint, the series' HDF5 copies. Returns the checkpoint's path.
    std::filesystem::path finish(bool stepped);
    // Before a run stops on an error: the series' HDF5 copies (the CSV files are always whole).
    void flush();

    const std::filesystem::path& last_checkpoint() const { return last_checkpoint_; }
    std::string trajectories() const { return trajectories_.text(); }

private:
    // Runs `work`, adding to an OutputError where the run can continue from.
    template <class Work>
    void writing(Work&& work);
    void start_outputs(const FlowHealth& health, const std::vector<BodyForces>& forces);
    void write_due(const StepStats& step, const FlowHealth& health, const std::vector<BodyForces>& forces);
    void write_final(bool stepped);
    void write_series_hdf5();
    void record(const StepStats& step, const FlowHealth& health, const std::vector<BodyForces>& forces);
    void write_fields();
    void write_checkpoint();

    Model& model_;
    RunOptions options_;
    TimeSeries series_;
    BodySeries body_series_;
    FieldOutput fields_;
    ContactLog contacts_;
    TrajectorySummary trajectories_;
    Probes probes_;
    HaloExchange halo_;
    Field2D uc_, vc_, omega_, pressure_pa_;
    double next_field_time_, next_checkpoint_time_;
    std::filesystem::path last_checkpoint_;
};

}  // namespace chute
