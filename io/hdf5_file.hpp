#pragma once
// A small RAII wrapper over the serial HDF5 C API, and the atomic-write helper every output file uses.
//
// Datasets are double precision, 1D or 2D (row-major, x fastest, so a field of ny rows and nx columns has
// shape ny x nx). Names may be paths ("fields/u"); missing groups are created on write. Every failure throws
// std::runtime_error naming the file, the dataset or attribute, and HDF5's own reason where it gives one.
// HDF5's automatic error printing is silenced inside the wrapper: the exception carries the message.
#include <hdf5.h>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace chute {

class Hdf5File {
public:
    // Creates (truncating) a file for writing. It is built in memory and written to disk whole by close(), with
    // plain POSIX writes whose failures (a full disk, a file size limit) are reported: HDF5 1.10 left a file
    // whose flush failed half-closed and crashed at exit. It costs the file's size in memory once.
    static Hdf5File create(const std::filesystem::path& path);
    // Opens an existing file read-only; throws "no such file" if it is missing.
    static Hdf5File open_read(const std::filesystem::path& path);

    Hdf5File(Hdf5File&& other) noexcept;
    Hdf5File& operator=(Hdf5File&& other) noexcept;
    Hdf5File(const Hdf5File&) = delete;
    Hdf5File& operator=(const Hdf5File&) = delete;
    ~Hdf5File();  // closes quietly; a created file is not written without close()

    // Closes; a created file is written to disk here. Throws naming the file and the reason (the system's
    // message for a failed write) if anything fails. Further calls are no-ops.
    void close();
    const std::filesystem::path& path() const { return path_; }

    // True if a dataset or group of that name (path) exists.
    bool has(const std::string& name) const;
    // Names of the members (datasets and groups) of a group, in name order.
    std::vector<std::string> members(const std::string& group = "/") const;

    // Datasets.
    void write(const std::string& name, std::span<const double> data);  // 1D
    void write(const std::string& name, std::span<const double> data, std::size_t rows,
               std::size_t cols);                                   // 2D
    void write_double(const std::string& name, double value);       // scalar dataset
    void write_int(const std::string& name, long long value);       // scalar dataset
    std::vector<std::size_t> shape(const std::string& name) const;  // empty for a scalar
    std::vector<double> read(const std::string& name) const;        // whole dataset, row-major
    // Rows [row0, row0 + rows) and columns [col0, col0 + cols) of a 2D dataset, row-major.
    std::vector<double> read_block(const std::string& name, std::size_t row0, std::size_t col0, std::size_t rows,
                                   std::size_t cols) const;
    double read_double(const std::string& name) const;
    long long read_int(const std::string& name) const;

    // Attributes of the object `object` ("/" is the file's root group).
    void set_double_attribute(const std::string& object, const std::string& name, double value);
    void set_int_attribute(const std::string& object, const std::string& name, long long value);
    void set_string_attribute(const std::string& object, const std::string& name, const std::string& value);
    bool has_attribute(const std::string& object, const std::string& name) const;
    double double_attribute(const std::string& object, const std::string& name) const;
    long long int_attribute(const std::string& object, const std::string& name) const;
    std::string string_attribute(const std::string& object, const std::string& name) const;

private:
    Hdf5File(hid_t id, std::filesystem::path path) : id_(id), path_(std::move(path)) {}
    [[noreturn]] void fail(const std::string& what) const;
    void write_dataset(const std::string& name, const double* data, int rank, const hsize_t* dims);
    void write_attribute(const std::string& object, const std::string& name, hid_t type, const void* value);
    void read_attribute(const std::string& object, const std::string& name, hid_t mem_type, void* value) const;

    hid_t id_ = H5I_INVALID_HID;
    bool in_memory_ = false;  // created: the image goes to disk at close()
    std::filesystem::path path_;
};

// Writes `target` atomically: `write` fills `target` + ".tmp", which is then synced to disk and renamed
// over `target`. If anything fails, the temporary is removed and `target` (an older good file) is untouched;
// a std::runtime_error from `write`, the sync or the rename comes out as an OutputError (output_error.hpp)
// naming `target` and the cause (the system's message, e.g. "No space left on device (ENOSPC)").
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& tmp)>& write);
// The same for a text file.
void write_text_atomically(const std::filesystem::path& target, const std::string& text);

}  // namespace chute
