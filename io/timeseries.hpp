#pragma once
// Scalar time series (time, dt, CFL, divergence, forces, ...): one CSV line per call, plus an HDF5 copy.
//
// out_dir/timeseries.csv: a header row of column names, then one row per append(), values written as the
// shortest text that reads back as the same double (so a restart compares times exactly). The first column
// is the time. out_dir/timeseries.h5: one 1D dataset per column (a '/' in a name becomes '_'), and a root
// attribute "columns" listing the names in order.
//
// Rank 0 does all I/O; on other ranks every call is a no-op. Not collective: a failure throws on rank 0 only.
#include <filesystem>
#include <string>
#include <vector>

#include "append_file.hpp"
#include "grid.hpp"

namespace chute {

class TimeSeries {
public:
    // `columns` names every column, the first being the time. restart_time < 0: start a new file with the
    // header row. Otherwise keep the rows of the existing file with t <= restart_time (a last line cut
    // short by a crash is dropped), rewrite the file with them atomically, and append after them; with no
    // existing file, start a new one. Throws std::runtime_error if the existing header differs from
    // `columns` (move the old file away to start a new series).
    // `stem` names the files (stem.csv, stem.h5).
    TimeSeries(const Grid& grid, std::filesystem::path out_dir, std::vector<std::string> columns,
               double restart_time = -1.0, std::string stem = "timeseries");

    // One CSV line, handed to the system at once. row.size() must equal the number of columns. A failed
    // write (full disk) throws OutputError and leaves the file at its last whole line (append_file.hpp).
    void append(const std::vector<double>& row);

    // Rewrites out_dir/timeseries.h5 atomically with every row so far, kept rows from before a restart
    // included.
    void write_hdf5();

    const std::vector<std::string>& columns() const { return columns_; }
    std::size_t rows() const { return rows_.size(); }  // 0 on ranks other than 0
    std::filesystem::path csv_path() const { return out_dir_ / (stem_ + ".csv"); }
    std::filesystem::path hdf5_path() const { return out_dir_ / (stem_ + ".h5"); }

private:
    bool root_;
    std::filesystem::path out_dir_;
    std::string stem_;
    std::vector<std::string> columns_;
    std::vector<std::vector<double>> rows_;
    AppendFile csv_;
};

}  // namespace chute
