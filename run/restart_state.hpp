#pragma once
// Everything a run needs to continue bit for bit (CaNS's start-stop test, tests/unit/test_run.cpp): the flow
// fields and scheme history, k and epsilon, and each free body's state (rigidbody/free_bodies), in one
// checkpoint file (core/checkpoint.hpp, written atomically).
#include <filesystem>

#include "model.hpp"

namespace chute {

// Writes out_dir/checkpoint_<step>.h5 and keeps the newest `kept`; returns its path.
std::filesystem::path write_run_checkpoint(Model& model, const std::filesystem::path& out_dir, int kept);

// The checkpoint that --restart names: the file itself, or for a results folder its newest readable
// checkpoint (damaged ones passed over, each with a note on stdout when `report`). CaseError if there is no
// such file, or no readable checkpoint in the folder.
std::filesystem::path restart_checkpoint(const std::filesystem::path& given, bool report);

// Continues the model from a checkpoint: grid lines, fields, free bodies, then the bodies placed at its time
// and the turbulence model's derived fields. std::runtime_error naming the file for a checkpoint of another
// grid or without a free body's state.
void restore_run(Model& model, const std::filesystem::path& checkpoint);

}  // namespace chute
