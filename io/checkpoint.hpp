#pragma once
// Checkpoints: everything a run needs to continue bit for bit, in one HDF5 file written atomically.
//
// Layout of a checkpoint file (rank 0 writes it after a gather, serial HDF5):
//   /                root attributes: format = "chute checkpoint 1", step (int64), time, dt, dt_previous
//   /grid/x_lines    the nx + 1 x grid lines (grid.x_axis().lines())
//   /grid/y_lines    the ny + 1 y grid lines
//   /fields/<name>   each field as a global 2D dataset of (ny + extra_y) x (nx + extra_x) values,
//                    with attributes extra_x and extra_y
//   /arrays/<name>   small 1D arrays the same on every rank (the state of free bodies)
// Values are stored as IEEE doubles, so a round trip is exact.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "field.hpp"
#include "grid.hpp"

namespace chute {

struct CheckpointField {
    std::string name;
    Field2D* field;
    int extra_x = 0, extra_y = 0;  // 1: include the boundary face column (row), as in gather_global
    bool optional = false;         // read if the file has it (newer checkpoints), else left as it is and listed
};

struct CheckpointArray {
    std::string name;
    std::vector<double> values;
};

struct CheckpointHeader {
    long step = 0;
    double time = 0.0;
    double dt = 0.0;
    double dt_previous = 0.0;
    bool implicit_diffusion = false;    // the last step's diffusion scheme (absent in older files: false)
    std::vector<std::string> absent{};  // optional fields the file does not have
};

// Collective. Writes `path` atomically (path.tmp, then rename): an older file of that name stays intact
// if anything fails. Every rank throws std::runtime_error if the write fails.
void write_checkpoint(const Grid& grid, const std::filesystem::path& path, const CheckpointHeader& header,
                      const std::vector<CheckpointField>& fields, const std::vector<CheckpointArray>& arrays = {});

// Not collective: the array /arrays/<name>, or nothing if the checkpoint has none of that name.
std::optional<std::vector<double>> read_checkpoint_array(const std::filesystem::path& path, const std::string& name);

// Collective. Every rank opens the file read-only and reads its own part of each field (ghost slot at
// i = nx / j = ny included where the field has an extra column / row and the patch touches that side).
// The grid's lines are not changed: rebuild the grid from read_checkpoint_lines() first.
// Throws std::runtime_error on every rank, naming the file and the reason, if the file is missing or
// unreadable, a field is missing or has the wrong shape, or the stored grid size differs from the grid's.
CheckpointHeader read_checkpoint(const Grid& grid, const std::filesystem::path& path,
                                 const std::vector<CheckpointField>& fields);

// Not collective: the stored x and y grid lines, so the caller can build the grid before reading fields.
std::pair<std::vector<double>, std::vector<double>> read_checkpoint_lines(const std::filesystem::path& path);

// out_dir / "checkpoint_<step, 6 digits>.h5".
std::filesystem::path checkpoint_path(const std::filesystem::path& out_dir, long step);

// The checkpoint of out_dir with the highest step, if there is one.
std::optional<std::filesystem::path> latest_checkpoint(const std::filesystem::path& out_dir);

// Not collective: throws std::runtime_error naming the file and the reason unless `path` opens as a whole
// Chute checkpoint: the format mark, the header, the grid lines, every field and array read back.
void check_checkpoint_readable(const std::filesystem::path& path);

// The checkpoint of out_dir with the highest step among those that pass check_checkpoint_readable(); each
// one passed over is added to `skipped` (if given) as "<file>: <reason>".
std::optional<std::filesystem::path> newest_readable_checkpoint(const std::filesystem::path& out_dir,
                                                                std::vector<std::string>* skipped = nullptr);

// Deletes all but the `keep` newest (highest step) checkpoint_<step>.h5 files of out_dir; keep <= 0 keeps
// all. Safe to call on every rank: only rank 0 of MPI_COMM_WORLD deletes.
void prune_checkpoints(const std::filesystem::path& out_dir, int keep);

}  // namespace chute
