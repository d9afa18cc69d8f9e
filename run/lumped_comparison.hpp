#pragma once
// Beside a CFD run with free bodies, the lumped models of the same release (rigidbody/lumped_model): for each
// free body, out_dir/lumped_<body>.csv with the dry (RocFall) and the Beranger trajectories, so that plots and
// users compare them with body_<name>.csv directly. They take milliseconds.
//   columns: model (0 dry, 1 Beranger), t, x, y, u, v
// The frontal area is the body's width across gravity times the depth; the current is the initial uniform
// velocity of the fluid.
#include <filesystem>

#include "case_config.hpp"
#include "free_bodies.hpp"

namespace chute {

void write_lumped_comparison(const CaseConfig& config, const std::vector<Body>& bodies, const FreeBodies& free_bodies,
                             const std::filesystem::path& out_dir);

}  // namespace chute
