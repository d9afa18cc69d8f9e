#include "field_output.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <set>
#include <sstream>
#include <stdexcept>

#include "exact_text.hpp"
#include "gather.hpp"
#include "hdf5_file.hpp"

namespace chute {

namespace {

std::string xml_escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

void check_names(const std::vector<NamedField>& fields) {
    std::set<std::string> seen;
    for (const NamedField& f : fields) {
        if (f.name.empty() || f.name == "x" || f.name == "y" || f.name.find('/') != std::string::npos)
            throw std::invalid_argument("FieldOutput: field name '" + f.name +
                                        "' is not allowed (empty, 'x', 'y' or containing '/')");
        if (!seen.insert(f.name).second) throw std::invalid_argument("FieldOutput: field '" + f.name + "' given twice");
        if (f.field == nullptr) throw std::invalid_argument("FieldOutput: field '" + f.name + "' is null");
    }
}

}  // namespace

FieldOutput::FieldOutput(const Grid& grid, std::filesystem::path out_dir, long restart_step)
    : grid_(grid), out_dir_(std::move(out_dir)) {
    run_on_root(grid_.comm(), [&] {
        std::filesystem::create_directories(out_dir_);
        if (restart_step >= 0) index_existing(restart_step);
    });
}

void FieldOutput::index_existing(long restart_step) {
    std::vector<std::pair<long, std::filesystem::path>> found;
    for (const auto& entry : std::filesystem::directory_iterator(out_dir_)) {
        const std::string name = entry.path().filename().string();
        if (name.size() <= 10 || !name.starts_with("fields_") || !name.ends_with(".h5")) continue;
        const std::string digits = name.substr(7, name.size() - 10);
        if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) continue;
        const long step = std::stol(digits);
        if (step <= restart_step) found.emplace_back(step, entry.path());
    }
    std::sort(found.begin(), found.end());
    for (const auto& [step, path] : found) {
        try {  // a file that is not one of ours is skipped
            const Hdf5File file = Hdf5File::open_read(path);
            const std::vector<std::size_t> x = file.shape("x"), y = file.shape("y");
            if (x.size() != 1 || y.size() != 1 || x[0] < 2 || y[0] < 2) continue;
            Snapshot snap{path.filename().string(),           step,
                          file.double_attribute("/", "time"), static_cast<int>(x[0] - 1),
                          static_cast<int>(y[0] - 1),         {}};
            for (const std::string& member : file.members("/")) {
                if (member == "x" || member == "y") continue;
                const std::vector<std::size_t> shape = file.shape(member);
                if (shape.size() == 2 && shape[0] == y[0] - 1 && shape[1] == x[0] - 1) snap.names.push_back(member);
            }
            snapshots_.push_back(std::move(snap));
        } catch (const std::runtime_error&) {
        }
    }
}

std::filesystem::path FieldOutput::snapshot_path(long step) const {
    char name[64];
    std::snprintf(name, sizeof name, "fields_%06ld.h5", step);
    return out_dir_ / name;
}

void FieldOutput::write(long step, double time, const std::vector<NamedField>& fields) {
    check_names(fields);
    std::vector<std::vector<double>> global;
    global.reserve(fields.size());
    for (const NamedField& f : fields) global.push_back(gather_global(grid_, *f.field));

    run_on_root(grid_.comm(), [&] {
        const int nx = grid_.global_nx(), ny = grid_.global_ny();
        const std::filesystem::path path = snapshot_path(step);
        write_atomically(path, [&](const std::filesystem::path& tmp) {
            Hdf5File file = Hdf5File::create(tmp);
            file.set_double_attribute("/", "time", time);
            file.set_int_attribute("/", "step", step);
            file.write("x", grid_.x_axis().lines());
            file.write("y", grid_.y_axis().lines());
            for (std::size_t k = 0; k < fields.size(); ++k)
                file.write(fields[k].name, global[k], static_cast<std::size_t>(ny), static_cast<std::size_t>(nx));
            file.close();
        });

        Snapshot snap{path.filename().string(), step, time, nx, ny, {}};
        for (const NamedField& f : fields) snap.names.push_back(f.name);
        std::erase_if(snapshots_, [&](const Snapshot& s) { return s.file == snap.file; });
        snapshots_.push_back(std::move(snap));
        write_xdmf();
    });
}

void FieldOutput::write_xdmf() const {
    std::ostringstream out;
    out << "<?xml version=\"1.0\" ?>\n"
        << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
        << "<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">\n"
        << "  <Domain>\n"
        << "    <Grid Name=\"fields\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const Snapshot& s : snapshots_) {
        const std::string file = xml_escape(s.file);
        const std::string points = std::to_string(s.ny + 1) + " " + std::to_string(s.nx + 1);
        const std::string cells = std::to_string(s.ny) + " " + std::to_string(s.nx);
        out << "      <Grid Name=\"step " << s.step << "\" GridType=\"Uniform\">\n"
            << "        <Time Value=\"" << exact_text(s.time) << "\"/>\n"
            << "        <Topology TopologyType=\"2DRectMesh\" Dimensions=\"" << points << "\"/>\n"
            << "        <Geometry GeometryType=\"VXVY\">\n"
            << "          <DataItem Dimensions=\"" << s.nx + 1
            << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << file << ":/x</DataItem>\n"
            << "          <DataItem Dimensions=\"" << s.ny + 1
            << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << file << ":/y</DataItem>\n"
            << "        </Geometry>\n";
        for (const std::string& name : s.names) {
            const std::string n = xml_escape(name);
            out << "        <Attribute Name=\"" << n << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
                << "          <DataItem Dimensions=\"" << cells
                << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << file << ":/" << n << "</DataItem>\n"
                << "        </Attribute>\n";
        }
        out << "      </Grid>\n";
    }
    out << "    </Grid>\n"
        << "  </Domain>\n"
        << "</Xdmf>\n";
    write_text_atomically(xdmf_path(), out.str());
}

}  // namespace chute
