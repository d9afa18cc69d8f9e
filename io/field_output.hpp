#pragma once
// Field snapshots for viewing: one HDF5 file per snapshot plus an XDMF index that ParaView opens as is.
//
// out_dir/fields_<step, 6 digits>.h5 holds
//   /x, /y          the grid lines of this snapshot (nx + 1 and ny + 1 values; lines may move between
//   snapshots)
//   /<name>         one dataset per field, cell-centred, shape ny x nx (row-major, x fastest)
//   root attributes time (double) and step (int64)
// out_dir/fields.xdmf is an XDMF 3 temporal collection of every snapshot written by this FieldOutput (and,
// after a restart, the earlier ones it was told to keep): per
// snapshot a 2DRectMesh with VXVY geometry read from /x and /y, and one Cell attribute per field. Both files
// are written atomically by rank 0 after a gather.
#include <filesystem>
#include <string>
#include <vector>

#include "field.hpp"
#include "grid.hpp"

namespace chute {

struct NamedField {
    std::string name;      // dataset name: not "x" or "y", no '/'
    const Field2D* field;  // cell-centred values
};

class FieldOutput {
public:
    // Collective: rank 0 creates out_dir if needed. restart_step >= 0 (a run continued from a checkpoint):
    // the snapshots already in out_dir with step <= restart_step are listed in fields.xdmf too, so the
    // index covers the whole history; later ones (from the run that stopped) are left out.
    FieldOutput(const Grid& grid, std::filesystem::path out_dir, long restart_step = -1);

    // Collective: call on all ranks with the same fields in the same order. Writing the same step again
    // replaces that snapshot. Throws std::runtime_error on every rank if the write fails.
    void write(long step, double time, const std::vector<NamedField>& fields);

    std::filesystem::path snapshot_path(long step) const;
    std::filesystem::path xdmf_path() const { return out_dir_ / "fields.xdmf"; }

private:
    struct Snapshot {
        std::string file;  // relative to out_dir
        long step;
        double time;
        int nx, ny;
        std::vector<std::string> names;
    };
    void index_existing(long restart_step);
    void write_xdmf() const;

    const Grid& grid_;
    std::filesystem::path out_dir_;
    std::vector<Snapshot> snapshots_;  // rank 0 only
};

}  // namespace chute
