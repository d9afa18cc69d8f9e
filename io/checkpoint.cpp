#include "checkpoint.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "gather.hpp"
#include "hdf5_file.hpp"

namespace chute {

namespace {

constexpr const char* kFormat = "chute checkpoint 1";

std::string field_dataset(const std::string& name) { return "fields/" + name; }

std::string grid_size(std::size_t nx, std::size_t ny) { return std::to_string(nx) + "x" + std::to_string(ny); }

// Step of a file named checkpoint_<digits>.h5, or -1.
long checkpoint_step(const std::filesystem::path& p) {
    const std::string name = p.filename().string();
    const std::string prefix = "checkpoint_", suffix = ".h5";
    if (name.size() <= prefix.size() + suffix.size() || !name.starts_with(prefix) || !name.ends_with(suffix)) return -1;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) return -1;
    return std::stol(digits);
}

std::vector<std::pair<long, std::filesystem::path>> list_checkpoints(const std::filesystem::path& out_dir) {
    std::vector<std::pair<long, std::filesystem::path>> found;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(out_dir, ec)) {
        const long step = checkpoint_step(entry.path());
        if (step >= 0 && entry.is_regular_file(ec)) found.emplace_back(step, entry.path());
    }
    std::sort(found.begin(), found.end());
    return found;
}

}  // namespace

void write_checkpoint(const Grid& grid, const std::filesystem::path& path, const CheckpointHeader& header,
                      const std::vector<CheckpointField>& fields, const std::vector<CheckpointArray>& arrays) {
    std::vector<std::vector<double>> global;
    global.reserve(fields.size());
    for (const CheckpointField& f : fields)  // collective: every rank gathers every field in the same order
        global.push_back(gather_global(grid, *f.field, f.extra_x, f.extra_y));

    run_on_root(grid.comm(), [&] {
        write_atomically(path, [&](const std::filesystem::path& tmp) {
            Hdf5File file = Hdf5File::create(tmp);
            file.set_string_attribute("/", "format", kFormat);
            file.set_int_attribute("/", "step", header.step);
            file.set_double_attribute("/", "time", header.time);
            file.set_double_attribute("/", "dt", header.dt);
            file.set_double_attribute("/", "dt_previous", header.dt_previous);
            file.set_int_attribute("/", "implicit_diffusion", header.implicit_diffusion ? 1 : 0);
            file.write("grid/x_lines", grid.x_axis().lines());
            file.write("grid/y_lines", grid.y_axis().lines());
            for (std::size_t k = 0; k < fields.size(); ++k) {
                const CheckpointField& f = fields[k];
                const std::string name = field_dataset(f.name);
                file.write(name, global[k], static_cast<std::size_t>(grid.global_ny() + f.extra_y),
                           static_cast<std::size_t>(grid.global_nx() + f.extra_x));
                file.set_int_attribute(name, "extra_x", f.extra_x);
                file.set_int_attribute(name, "extra_y", f.extra_y);
            }
            for (const CheckpointArray& a : arrays) file.write("arrays/" + a.name, a.values);
            file.close();
        });
    });
}

std::optional<std::vector<double>> read_checkpoint_array(const std::filesystem::path& path, const std::string& name) {
    Hdf5File file = Hdf5File::open_read(path);
    if (!file.has("arrays/" + name)) return std::nullopt;
    return file.read("arrays/" + name);
}

std::pair<std::vector<double>, std::vector<double>> read_checkpoint_lines(const std::filesystem::path& path) {
    Hdf5File file = Hdf5File::open_read(path);
    if (!file.has_attribute("/", "format") || file.string_attribute("/", "format") != kFormat)
        throw std::runtime_error("checkpoint '" + path.string() + "' is not a Chute checkpoint (no format '" + kFormat +
                                 "')");
    std::vector<double> x = file.read("grid/x_lines");
    std::vector<double> y = file.read("grid/y_lines");
    if (x.size() < 2 || y.size() < 2)
        throw std::runtime_error("checkpoint '" + path.string() + "': fewer than two grid lines");
    return {std::move(x), std::move(y)};
}

CheckpointHeader read_checkpoint(const Grid& grid, const std::filesystem::path& path,
                                 const std::vector<CheckpointField>& fields) {
    CheckpointHeader header;
    run_on_all(grid.comm(), [&] {
        const auto [x, y] = read_checkpoint_lines(path);
        const std::size_t nx = x.size() - 1, ny = y.size() - 1;
        if (nx != static_cast<std::size_t>(grid.global_nx()) || ny != static_cast<std::size_t>(grid.global_ny()))
            throw std::runtime_error("checkpoint '" + path.string() + "': checkpoint grid " + grid_size(nx, ny) +
                                     " does not match case grid " + grid_size(grid.global_nx(), grid.global_ny()));
        Hdf5File file = Hdf5File::open_read(path);
        header.step = static_cast<long>(file.int_attribute("/", "step"));
        header.time = file.double_attribute("/", "time");
        header.dt = file.double_attribute("/", "dt");
        header.dt_previous = file.double_attribute("/", "dt_previous");
        header.implicit_diffusion =
            file.has_attribute("/", "implicit_diffusion") && file.int_attribute("/", "implicit_diffusion") != 0;

        for (const CheckpointField& f : fields) {
            const std::string name = field_dataset(f.name);
            if (!file.has(name) && f.optional) {
                header.absent.push_back(f.name);
                continue;
            }
            if (!file.has(name))
                throw std::runtime_error("checkpoint '" + path.string() + "' has no field '" + f.name + "'");
            const std::vector<std::size_t> shape = file.shape(name);
            const std::size_t rows = ny + f.extra_y, cols = nx + f.extra_x;
            if (shape.size() != 2 || shape[0] != rows || shape[1] != cols)
                throw std::runtime_error("checkpoint '" + path.string() + "': field '" + f.name +
                                         "' does not have the expected shape " + std::to_string(rows) + " x " +
                                         std::to_string(cols));
            // The patch and its halo, as far as the file's array reaches: the halo's values are the neighbours'
            // own, which the exchange would bring, except beside a boundary face row or column (an outflow's faces,
            // in a patch's corner halo, which the exchange leaves to the boundary condition's own update there).
            const int ox = grid.lx().offset, oy = grid.ly().offset;
            const int i0 = std::max(0, ox - kGhost), j0 = std::max(0, oy - kGhost);
            const int i1 = std::min(static_cast<int>(cols), ox + grid.nx() + kGhost);
            const int j1 = std::min(static_cast<int>(rows), oy + grid.ny() + kGhost);
            const int w = i1 - i0, h = j1 - j0;
            const std::vector<double> block =
                file.read_block(name, static_cast<std::size_t>(j0), static_cast<std::size_t>(i0),
                                static_cast<std::size_t>(h), static_cast<std::size_t>(w));
            Field2D& out = *f.field;
            if (out.nx() != grid.nx() || out.ny() != grid.ny())
                throw std::invalid_argument("read_checkpoint: field '" + f.name + "' does not fit the patch");
            for (int j = j0; j < j1; ++j)
                for (int i = i0; i < i1; ++i)
                    out(i - ox, j - oy) = block[static_cast<std::size_t>(j - j0) * w + (i - i0)];
        }
    });
    return header;
}

std::filesystem::path checkpoint_path(const std::filesystem::path& out_dir, long step) {
    char name[64];
    std::snprintf(name, sizeof name, "checkpoint_%06ld.h5", step);
    return out_dir / name;
}

std::optional<std::filesystem::path> latest_checkpoint(const std::filesystem::path& out_dir) {
    const auto found = list_checkpoints(out_dir);
    if (found.empty()) return std::nullopt;
    return found.back().second;
}

void check_checkpoint_readable(const std::filesystem::path& path) {
    (void)read_checkpoint_lines(path);  // the format mark and the grid lines
    const Hdf5File file = Hdf5File::open_read(path);
    for (const char* name : {"time", "dt", "dt_previous"}) (void)file.double_attribute("/", name);
    (void)file.int_attribute("/", "step");
    for (const char* group : {"fields", "arrays"}) {
        if (!file.has(group)) continue;
        for (const std::string& member : file.members(group)) (void)file.read(std::string(group) + "/" + member);
    }
    if (!file.has("fields") || file.members("fields").empty())
        throw std::runtime_error("checkpoint '" + path.string() + "' holds no field");
}

std::optional<std::filesystem::path> newest_readable_checkpoint(const std::filesystem::path& out_dir,
                                                                std::vector<std::string>* skipped) {
    const auto found = list_checkpoints(out_dir);
    for (auto it = found.rbegin(); it != found.rend(); ++it) {
        try {
            check_checkpoint_readable(it->second);
            return it->second;
        } catch (const std::runtime_error& e) {
            if (skipped != nullptr) skipped->push_back(it->second.string() + ": " + e.what());
        }
    }
    return std::nullopt;
}

void prune_checkpoints(const std::filesystem::path& out_dir, int keep) {
    int initialised = 0;
    MPI_Initialized(&initialised);
    int rank = 0;
    if (initialised) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank != 0 || keep <= 0) return;
    const auto found = list_checkpoints(out_dir);
    const std::size_t kept = static_cast<std::size_t>(keep);
    if (found.size() <= kept) return;
    for (std::size_t k = 0; k + kept < found.size(); ++k) {
        std::error_code ec;
        std::filesystem::remove(found[k].second, ec);  // a file that cannot be deleted is not an error
    }
}

}  // namespace chute
