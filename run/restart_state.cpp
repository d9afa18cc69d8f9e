#include "restart_state.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "case_file.hpp"
#include "checkpoint.hpp"

namespace chute {

namespace {

std::vector<CheckpointField> checkpoint_fields(Model& model) {
    FlowSolver& s = model.flow();
    std::vector<CheckpointField> f = {{"u", &s.velocity().u, 1, 0},
                                      {"v", &s.velocity().v, 0, 1},
                                      {"p", &s.pressure(), 0, 0},
                                      {"p_old", &s.previous_pressure(), 0, 0},
                                      {"rhs_old_u", &s.previous_rhs().u, 1, 0},
                                      {"rhs_old_v", &s.previous_rhs().v, 0, 1}};
    if (KEpsilon* turbulence = model.turbulence()) {
        f.push_back({"k", &turbulence->k(), 0, 0});
        f.push_back({"epsilon", &turbulence->epsilon(), 0, 0});
        // The cells beside an immersed surface take the wall's eddy viscosity from samples taken with k before the
        // last update; k after it gives other values, so a restart reads them (older checkpoints lack them).
        f.push_back({"eddy_viscosity", &s.eddy_viscosity().cell, 0, 0, true});
    }
    return f;
}

}  // namespace

std::filesystem::path write_run_checkpoint(Model& model, const std::filesystem::path& out_dir, int kept) {
    const FlowSolver& s = model.flow();
    const auto path = checkpoint_path(out_dir, s.step());
    std::vector<CheckpointArray> arrays = model.free_bodies().checkpoint_arrays();
    // The grid velocities the last step's fluxes used (stretching lines: the next step's AB2 sweep counts them).
    const std::array<double, 2> w = s.previous_grid_velocity();
    arrays.push_back({"flow_previous_grid_velocity", {w[0], w[1]}});
    for (const auto& [name, values] : model.carrier().checkpoint_arrays())
        arrays.push_back({"carrier_" + name, values});
    write_checkpoint(s.grid(), path, {s.step(), s.time(), s.previous_dt(), s.previous_dt(), s.implicit_diffusion()},
                     checkpoint_fields(model), arrays);
    prune_checkpoints(out_dir, kept);
    return path;
}

std::filesystem::path restart_checkpoint(const std::filesystem::path& given, bool report) {
    std::error_code ec;
    if (!std::filesystem::is_directory(given, ec)) {
        if (!std::filesystem::exists(given, ec))
            throw CaseError("--restart: no checkpoint file '" + given.string() + "'");
        return given;
    }
    std::vector<std::string> skipped;
    const auto newest = newest_readable_checkpoint(given, &skipped);
    if (report)
        for (const std::string& note : skipped) std::printf("chute: --restart: passing over %s\n", note.c_str());
    if (!newest) throw CaseError("--restart: no readable checkpoint in the folder '" + given.string() + "'");
    if (report) std::printf("chute: --restart: continuing from %s\n", newest->string().c_str());
    return *newest;
}

void restore_run(Model& model, const std::filesystem::path& checkpoint) {
    FlowSolver& solver = model.flow();
    const Grid& grid = solver.grid();
    // Lines may have moved during the run that wrote the checkpoint: take them from the checkpoint.
    auto [xl, yl] = read_checkpoint_lines(checkpoint);
    if (static_cast<int>(xl.size()) != grid.global_nx() + 1 || static_cast<int>(yl.size()) != grid.global_ny() + 1)
        throw std::runtime_error("checkpoint " + checkpoint.string() + ": grid " + std::to_string(xl.size() - 1) + "x" +
                                 std::to_string(yl.size() - 1) + " does not match the case grid " +
                                 std::to_string(grid.global_nx()) + "x" + std::to_string(grid.global_ny()));
    solver.set_grid_lines(xl, yl);
    const CheckpointHeader h = read_checkpoint(grid, checkpoint, checkpoint_fields(model));
    const bool eddy_read = std::find(h.absent.begin(), h.absent.end(), "eddy_viscosity") == h.absent.end();
    solver.restore(h.step, h.time, h.dt_previous, h.implicit_diffusion);  // the counters; no ghost is filled
    if (const auto w = read_checkpoint_array(checkpoint, "flow_previous_grid_velocity"); w && w->size() == 2)
        solver.set_previous_grid_velocity({(*w)[0], (*w)[1]});
    model.free_bodies().restore(checkpoint);
    // The holes where the checkpoint's lines put them before anything fills their faces: filled where the case
    // first put them, they would overwrite the restored flow beside them (a grid with modifier layers).
    Carrier::NamedArrays carrier_arrays;
    for (const auto& [name, values] : model.carrier().checkpoint_arrays())
        if (auto stored = read_checkpoint_array(checkpoint, "carrier_" + name)) carrier_arrays[name] = *stored;
    model.carrier().restored(carrier_arrays);
    model.carrier().place(solver.time());
    solver.refresh_ghosts();  // a hole's faces move with its restored body
    if (KEpsilon* turbulence = model.turbulence()) turbulence->restored(eddy_read);
    model.window_after_step();
}

}  // namespace chute
