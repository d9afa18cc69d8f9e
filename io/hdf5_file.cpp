#include "hdf5_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>
#include <utility>

#include "output_error.hpp"

namespace chute {

namespace {

// Silences HDF5's automatic error printing for the lifetime of the guard (the exception carries the message).
class QuietErrors {
public:
    QuietErrors() {
        H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    }
    ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;

private:
    H5E_auto2_t func_ = nullptr;
    void* data_ = nullptr;
};

// Closes an HDF5 identifier when it goes out of scope.
class Handle {
public:
    Handle(hid_t id, herr_t (*closer)(hid_t)) : id_(id), closer_(closer) {}
    ~Handle() {
        if (id_ >= 0) closer_(id_);
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    hid_t get() const { return id_; }
    bool ok() const { return id_ >= 0; }

private:
    hid_t id_;
    herr_t (*closer_)(hid_t);
};

// The most specific message on HDF5's error stack, or "" if there is none. Where a system call failed (a full
// disk, a file size limit, a read-only folder), HDF5's file driver puts the system's own message in the
// description ("..., errno = 28, error message = 'No space left on device', ..."): that one is returned.
std::string hdf5_reason() {
    struct Found {
        std::string innermost, system;
    } found;
    H5Ewalk2(
        H5E_DEFAULT, H5E_WALK_UPWARD,
        [](unsigned n, const H5E_error2_t* err, void* client) -> herr_t {
            if (err == nullptr || err->desc == nullptr) return 0;
            auto& f = *static_cast<Found*>(client);
            const std::string desc = err->desc;
            if (n == 0) f.innermost = desc;
            const std::string key = "error message = '";
            const std::size_t at = desc.find(key);
            if (f.system.empty() && at != std::string::npos) {
                const std::size_t end = desc.find('\'', at + key.size());
                f.system = desc.substr(at + key.size(), end == std::string::npos ? end : end - at - key.size());
            }
            return 0;
        },
        &found);
    return found.system.empty() ? found.innermost : found.system;
}

std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

// Creates (truncating) `path` holding `size` bytes; throws the system's reason (write_atomically names the
// file). close() is checked too: some file systems (NFS) report a full disk only there.
void write_bytes(const std::filesystem::path& path, const char* data, std::size_t size) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw std::runtime_error(errno_text(errno) + " (creating '" + path.filename().string() + "')");
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::write(fd, data + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : ENOSPC;  // a write of 0 bytes: nothing more fits
            ::close(fd);
            throw std::runtime_error(errno_text(error));
        }
        done += static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0) throw std::runtime_error(errno_text(errno) + " (closing '" + path.filename().string() + "')");
}

void check_dims(const std::string& where, std::size_t expected, std::size_t got) {
    if (expected != got)
        throw std::invalid_argument(where + ": " + std::to_string(got) + " values given for " +
                                    std::to_string(expected) + " elements");
}

}  // namespace

Hdf5File Hdf5File::create(const std::filesystem::path& path) {
    QuietErrors quiet;
    // HDF5's core driver without a backing store: the file is built in memory and written by close().
    Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    if (!access.ok() || H5Pset_fapl_core(access.get(), std::size_t{1} << 20, 0) < 0)
        throw std::runtime_error("HDF5: cannot set up the in-memory file for " + quoted(path));
    const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get());
    if (id < 0) {
        const std::string reason = hdf5_reason();
        throw std::runtime_error("HDF5: cannot create file " + quoted(path) + (reason.empty() ? "" : ": " + reason));
    }
    Hdf5File file(id, path);
    file.in_memory_ = true;
    return file;
}

Hdf5File Hdf5File::open_read(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw std::runtime_error("HDF5: cannot open file " + quoted(path) + ": no such file");
    QuietErrors quiet;
    const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id < 0) {
        const std::string reason = hdf5_reason();
        throw std::runtime_error("HDF5: cannot open file " + quoted(path) + " (not a readable HDF5 file?)" +
                                 (reason.empty() ? "" : ": " + reason));
    }
    return Hdf5File(id, path);
}

Hdf5File::Hdf5File(Hdf5File&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)), in_memory_(other.in_memory_), path_(std::move(other.path_)) {}

Hdf5File& Hdf5File::operator=(Hdf5File&& other) noexcept {
    if (this != &other) {
        if (id_ >= 0) {
            QuietErrors quiet;
            H5Fclose(id_);
        }
        id_ = std::exchange(other.id_, H5I_INVALID_HID);
        in_memory_ = other.in_memory_;
        path_ = std::move(other.path_);
    }
    return *this;
}

Hdf5File::~Hdf5File() {
    if (id_ >= 0) {
        QuietErrors quiet;
        H5Fclose(id_);
    }
}

void Hdf5File::close() {
    if (id_ < 0) return;
    QuietErrors quiet;
    std::vector<char> image;
    if (in_memory_) {
        const ssize_t size = H5Fflush(id_, H5F_SCOPE_GLOBAL) < 0 ? -1 : H5Fget_file_image(id_, nullptr, 0);
        if (size >= 0) image.resize(static_cast<std::size_t>(size));
        if (size < 0 || H5Fget_file_image(id_, image.data(), image.size()) != size) {
            const std::string reason = hdf5_reason();
            H5Fclose(std::exchange(id_, H5I_INVALID_HID));
            throw std::runtime_error("HDF5 file " + quoted(path_) + ": cannot make the file's image" +
                                     (reason.empty() ? "" : " (" + reason + ")"));
        }
    }
    const hid_t id = std::exchange(id_, H5I_INVALID_HID);
    if (H5Fclose(id) < 0) fail("cannot close (flush) the file");
    if (in_memory_) write_bytes(path_, image.data(), image.size());
}

void Hdf5File::fail(const std::string& what) const {
    const std::string reason = hdf5_reason();
    throw std::runtime_error("HDF5 file " + quoted(path_) + ": " + what + (reason.empty() ? "" : " (" + reason + ")"));
}

bool Hdf5File::has(const std::string& name) const {
    QuietErrors quiet;
    // H5Lexists needs every intermediate link to exist, so test the path one component at a time.
    if (name == "/") return true;
    std::string prefix = !name.empty() && name[0] == '/' ? "/" : "";
    bool any = false;
    std::size_t start = 0;
    while (start < name.size()) {
        std::size_t end = name.find('/', start);
        if (end == std::string::npos) end = name.size();
        if (end > start) {
            if (any) prefix += '/';
            prefix += name.substr(start, end - start);
            any = true;
            if (H5Lexists(id_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
        }
        start = end + 1;
    }
    return any;
}

std::vector<std::string> Hdf5File::members(const std::string& group) const {
    if (group != "/" && !has(group)) fail("no group '" + group + "'");
    QuietErrors quiet;
    Handle g(H5Gopen2(id_, group.c_str(), H5P_DEFAULT), H5Gclose);
    if (!g.ok()) fail("cannot open group '" + group + "'");
    std::vector<std::string> names;
    hsize_t index = 0;
    const herr_t status = H5Literate(
        g.get(), H5_INDEX_NAME, H5_ITER_INC, &index,
        [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t {
            static_cast<std::vector<std::string>*>(out)->emplace_back(name);
            return 0;
        },
        &names);
    if (status < 0) fail("cannot list group '" + group + "'");
    return names;
}

void Hdf5File::write_dataset(const std::string& name, const double* data, int rank, const hsize_t* dims) {
    QuietErrors quiet;
    Handle space(rank == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(rank, dims, nullptr), H5Sclose);
    if (!space.ok()) fail("cannot create a dataspace for dataset '" + name + "'");
    Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    if (!lcpl.ok() || H5Pset_create_intermediate_group(lcpl.get(), 1) < 0)
        fail("cannot create a property list for dataset '" + name + "'");
    Handle set(H5Dcreate2(id_, name.c_str(), H5T_IEEE_F64LE, space.get(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose);
    if (!set.ok()) fail("cannot create dataset '" + name + "'");
    hsize_t count = 1;
    for (int k = 0; k < rank; ++k) count *= dims[k];
    if (count > 0 && H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
        fail("cannot write dataset '" + name + "'");
}

void Hdf5File::write(const std::string& name, std::span<const double> data) {
    const hsize_t dims[1] = {data.size()};
    write_dataset(name, data.data(), 1, dims);
}

void Hdf5File::write(const std::string& name, std::span<const double> data, std::size_t rows, std::size_t cols) {
    check_dims("Hdf5File::write '" + name + "'", rows * cols, data.size());
    const hsize_t dims[2] = {rows, cols};
    write_dataset(name, data.data(), 2, dims);
}

void Hdf5File::write_double(const std::string& name, double value) { write_dataset(name, &value, 0, nullptr); }

void Hdf5File::write_int(const std::string& name, long long value) {
    QuietErrors quiet;
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    if (!space.ok() || !lcpl.ok() || H5Pset_create_intermediate_group(lcpl.get(), 1) < 0)
        fail("cannot prepare dataset '" + name + "'");
    Handle set(H5Dcreate2(id_, name.c_str(), H5T_STD_I64LE, space.get(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose);
    if (!set.ok()) fail("cannot create dataset '" + name + "'");
    if (H5Dwrite(set.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value) < 0)
        fail("cannot write dataset '" + name + "'");
}

std::vector<std::size_t> Hdf5File::shape(const std::string& name) const {
    if (!has(name)) fail("no dataset '" + name + "'");
    QuietErrors quiet;
    Handle set(H5Dopen2(id_, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.ok()) fail("cannot open dataset '" + name + "'");
    Handle space(H5Dget_space(set.get()), H5Sclose);
    const int rank = space.ok() ? H5Sget_simple_extent_ndims(space.get()) : -1;
    if (rank < 0) fail("cannot read the shape of dataset '" + name + "'");
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0)
        fail("cannot read the shape of dataset '" + name + "'");
    return {dims.begin(), dims.end()};
}

std::vector<double> Hdf5File::read(const std::string& name) const {
    const std::vector<std::size_t> dims = shape(name);
    std::size_t count = 1;
    for (std::size_t d : dims) count *= d;
    std::vector<double> data(count);
    if (count == 0) return data;
    QuietErrors quiet;
    Handle set(H5Dopen2(id_, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.ok() || H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
        fail("cannot read dataset '" + name + "'");
    return data;
}

std::vector<double> Hdf5File::read_block(const std::string& name, std::size_t row0, std::size_t col0, std::size_t rows,
                                         std::size_t cols) const {
    const std::vector<std::size_t> dims = shape(name);
    if (dims.size() != 2) fail("dataset '" + name + "' is not two-dimensional");
    if (row0 + rows > dims[0] || col0 + cols > dims[1])
        fail("block of " + std::to_string(rows) + " x " + std::to_string(cols) + " at (" + std::to_string(row0) + ", " +
             std::to_string(col0) + ") lies outside dataset '" + name + "' of shape " + std::to_string(dims[0]) +
             " x " + std::to_string(dims[1]));
    std::vector<double> data(rows * cols);
    if (data.empty()) return data;
    QuietErrors quiet;
    Handle set(H5Dopen2(id_, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.ok()) fail("cannot open dataset '" + name + "'");
    Handle file_space(H5Dget_space(set.get()), H5Sclose);
    const hsize_t start[2] = {row0, col0};
    const hsize_t count[2] = {rows, cols};
    if (!file_space.ok() || H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) < 0)
        fail("cannot select a block of dataset '" + name + "'");
    Handle mem_space(H5Screate_simple(2, count, nullptr), H5Sclose);
    if (!mem_space.ok() ||
        H5Dread(set.get(), H5T_NATIVE_DOUBLE, mem_space.get(), file_space.get(), H5P_DEFAULT, data.data()) < 0)
        fail("cannot read dataset '" + name + "'");
    return data;
}

double Hdf5File::read_double(const std::string& name) const {
    const std::vector<double> v = read(name);
    if (v.size() != 1) fail("dataset '" + name + "' is not a scalar");
    return v[0];
}

long long Hdf5File::read_int(const std::string& name) const {
    if (!shape(name).empty()) fail("dataset '" + name + "' is not a scalar");
    QuietErrors quiet;
    long long value = 0;
    Handle set(H5Dopen2(id_, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.ok() || H5Dread(set.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value) < 0)
        fail("cannot read dataset '" + name + "'");
    return value;
}

void Hdf5File::write_attribute(const std::string& object, const std::string& name, hid_t type, const void* value) {
    QuietErrors quiet;
    const std::string what = "attribute '" + name + "' of '" + object + "'";
    const htri_t exists = H5Aexists_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT);
    if (exists < 0) fail("cannot find the object of " + what);
    if (exists > 0 && H5Adelete_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT) < 0)
        fail("cannot replace " + what);
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Handle attr(
        H5Acreate_by_name(id_, object.c_str(), name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose);
    if (!attr.ok()) fail("cannot create " + what);
    if (H5Awrite(attr.get(), type, value) < 0) fail("cannot write " + what);
}

void Hdf5File::set_double_attribute(const std::string& object, const std::string& name, double value) {
    write_attribute(object, name, H5T_NATIVE_DOUBLE, &value);
}

void Hdf5File::set_int_attribute(const std::string& object, const std::string& name, long long value) {
    write_attribute(object, name, H5T_NATIVE_LLONG, &value);
}

void Hdf5File::set_string_attribute(const std::string& object, const std::string& name, const std::string& value) {
    QuietErrors quiet;
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    if (!type.ok() || H5Tset_size(type.get(), value.size() + 1) < 0 ||
        H5Tset_strpad(type.get(), H5T_STR_NULLTERM) < 0 || H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0)
        fail("cannot make a string type for attribute '" + name + "'");
    write_attribute(object, name, type.get(), value.c_str());
}

bool Hdf5File::has_attribute(const std::string& object, const std::string& name) const {
    if (object != "/" && !has(object)) return false;
    QuietErrors quiet;
    return H5Aexists_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

void Hdf5File::read_attribute(const std::string& object, const std::string& name, hid_t mem_type, void* value) const {
    const std::string what = "attribute '" + name + "' of '" + object + "'";
    if (!has_attribute(object, name)) fail("no " + what);
    QuietErrors quiet;
    Handle attr(H5Aopen_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!attr.ok()) fail("cannot open " + what);
    Handle space(H5Aget_space(attr.get()), H5Sclose);
    if (!space.ok() || H5Sget_simple_extent_npoints(space.get()) != 1) fail(what + " is not a scalar");
    if (H5Aread(attr.get(), mem_type, value) < 0) fail("cannot read " + what);
}

double Hdf5File::double_attribute(const std::string& object, const std::string& name) const {
    double value = 0.0;
    read_attribute(object, name, H5T_NATIVE_DOUBLE, &value);
    return value;
}

long long Hdf5File::int_attribute(const std::string& object, const std::string& name) const {
    long long value = 0;
    read_attribute(object, name, H5T_NATIVE_LLONG, &value);
    return value;
}

std::string Hdf5File::string_attribute(const std::string& object, const std::string& name) const {
    const std::string what = "attribute '" + name + "' of '" + object + "'";
    if (!has_attribute(object, name)) fail("no " + what);
    QuietErrors quiet;
    Handle attr(H5Aopen_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!attr.ok()) fail("cannot open " + what);
    Handle file_type(H5Aget_type(attr.get()), H5Tclose);
    if (!file_type.ok() || H5Tget_class(file_type.get()) != H5T_STRING) fail(what + " is not a string");
    if (H5Tis_variable_str(file_type.get()) > 0) {  // as h5py writes them
        Handle mem_type(H5Tcopy(H5T_C_S1), H5Tclose);
        H5Tset_size(mem_type.get(), H5T_VARIABLE);
        H5Tset_cset(mem_type.get(), H5Tget_cset(file_type.get()));
        char* text = nullptr;
        if (H5Aread(attr.get(), mem_type.get(), &text) < 0) fail("cannot read " + what);
        std::string value = text != nullptr ? text : "";
        H5free_memory(text);
        return value;
    }
    const std::size_t size = H5Tget_size(file_type.get());
    Handle mem_type(H5Tcopy(H5T_C_S1), H5Tclose);
    if (size == 0 || H5Tset_size(mem_type.get(), size) < 0 ||
        H5Tset_cset(mem_type.get(), H5Tget_cset(file_type.get())) < 0)
        fail("cannot read " + what);
    std::string buffer(size, '\0');
    if (H5Aread(attr.get(), mem_type.get(), buffer.data()) < 0) fail("cannot read " + what);
    return buffer.substr(0, buffer.find('\0'));
}

namespace {

// Flushes a file's (or directory's) contents to disk, so a renamed file survives a system crash too; the
// errno of the failure, or 0.
int sync_path(const std::filesystem::path& p, bool directory) {
    const int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC | (directory ? O_DIRECTORY : 0));
    if (fd < 0) return errno;
    const int error = ::fsync(fd) == 0 ? 0 : errno;
    ::close(fd);
    return error;
}

}  // namespace

void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& tmp)>& write) {
    std::filesystem::path tmp = target;
    tmp += ".tmp";
    std::error_code ec;
    try {
        write(tmp);
        if (const int error = sync_path(tmp, false))
            throw std::runtime_error("cannot sync " + quoted(tmp) + " to disk: " + errno_text(error));
        std::filesystem::rename(tmp, target);
    } catch (const OutputError&) {
        std::filesystem::remove(tmp, ec);
        throw;
    } catch (const std::runtime_error& e) {
        // Any failure to write is an output error (a full disk, a file size limit, a read-only folder), named
        // by the file that was being written; a logic error in the caller stays what it is.
        std::filesystem::remove(tmp, ec);
        throw OutputError(target, e.what());
    } catch (...) {
        std::filesystem::remove(tmp, ec);
        throw;
    }
    const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : ".";
    sync_path(dir, true);  // best effort: the rename is done either way
}

void write_text_atomically(const std::filesystem::path& target, const std::string& text) {
    write_atomically(target, [&](const std::filesystem::path& tmp) { write_bytes(tmp, text.data(), text.size()); });
}

}  // namespace chute
