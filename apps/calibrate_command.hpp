#pragma once
// chute calibrate SPEC.yaml [--out DIR] [--redo]: the CFD runs a calibration of the wet lumped model needs (a
// free fall, bounces on beds and slopes; SPEC lists their case files and --set overrides), made on
// MPI_COMM_WORLD into DIR/runs/<run> or reused when that folder holds the same case already run; then the fit
// (hazard/calibration.hpp) on rank 0, written as DIR/<name>.yaml (a hazard case's model.calibration), with
// DIR/<name>_points.csv and DIR/<name>.md (the table of points fitted to and checked against).
#include <filesystem>

int calibrate_command(const std::filesystem::path& spec_file, const std::filesystem::path& out_dir, bool redo);

// The key table of a calibration spec (docs/hazard-case-file.md).
#include <string>
std::string calibration_spec_keys_markdown();
