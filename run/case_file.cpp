// Case files (case_file.hpp): the schema assembled from the modules' sections, and the case from their reads.
//
//   section                                                               owner, where its keys are declared
//   name, output                                                          run/ (here)
//   domain, fluid, initial, boundaries, numerics (not numerics.ibm),      core/flow_keys.cpp
//   time, parallel
//   bodies                                                                body/body_keys.cpp
//   numerics.ibm                                                          ibm/ibm_keys.cpp
//   contact                                                               contact/contact_keys.cpp
//   gravity, lumped                                                       rigidbody/rigidbody_keys.cpp
//   turbulence                                                            turbulence/turbulence_keys.cpp
//
// Reading a case: the reader (io/case_reader.hpp) files every key against the whole schema (unknown keys,
// duplicates, --set overrides) and checks presence and `when` conditions; then each module reads its section
// with the checks inside it; then the checks across sections, here: every body and every probe inside the
// domain.
#include "case_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace chute {

namespace {

std::vector<CaseKey> name_keys() {
    using K = KeyType;
    return {
        {.path = "name",
         .type = K::string,
         .default_doc = "file stem",
         .meaning = "Run name; output files are named after it. Default: the case file's name without "
                    "its extension."},
    };
}

std::vector<CaseKey> output_keys() {
    using K = KeyType;
    return {
        {.path = "output", .type = K::section, .meaning = "What is written, and how often."},
        {.path = "output.fields_interval",
         .type = K::number,
         .default_value = "0.0",
         .min = at_least(0),
         .units = "s",
         .meaning = "Simulated time between field snapshots; 0: first and last only."},
        {.path = "output.checkpoint_interval",
         .type = K::number,
         .default_value = "0.0",
         .min = at_least(0),
         .units = "s",
         .meaning = "Simulated time between checkpoints; 0: at the end only."},
        {.path = "output.checkpoints_kept",
         .type = K::integer,
         .default_value = "2",
         .min = at_least(1),
         .meaning = "Number of newest checkpoints kept; older ones are deleted."},
        {.path = "output.timeseries_every",
         .type = K::integer,
         .default_value = "1",
         .min = at_least(1),
         .units = "steps",
         .meaning = "Steps between rows of the time series."},
        {.path = "output.progress_interval",
         .type = K::number,
         .default_value = "2.0",
         .min = at_least(0),
         .units = "s (wall)",
         .meaning = "Wall-clock time between progress lines."},
        {.path = "output.probes",
         .type = K::point_list,
         .default_value = "[]",
         .units = "m",
         .meaning = "Points [x, y] sampled into the time series; each must lie inside the domain."},
        {.path = "output.plots", .type = K::boolean, .default_value = "true", .meaning = "Write plots of the results."},
    };
}

// The order of the key table in docs/case-file.md and of `chute keys` (the order the schema had as one table),
// whichever module declares each key: a key goes with the longest entry its path is or starts with, and the
// keys of one entry keep the order of their module's section.
constexpr std::array<std::string_view, 18> kDocumentedOrder = {
    "name",       "domain",   "fluid",      "gravity",          "initial",
    "boundaries", "bodies",   "numerics",   "numerics.ibm",     "numerics.coupling",
    "contact",    "lumped",   "turbulence", "numerics.poisson", "numerics.divergence_limit",
    "time",       "parallel", "output"};

std::size_t documented_rank(std::string_view path) {
    std::size_t rank = kDocumentedOrder.size(), length = 0;
    for (std::size_t i = 0; i < kDocumentedOrder.size(); ++i) {
        const std::string_view entry = kDocumentedOrder[i];
        const bool under = path == entry || (path.starts_with(entry) && path[entry.size()] == '.');
        if (under && entry.size() > length) rank = i, length = entry.size();
    }
    if (rank == kDocumentedOrder.size())
        throw std::logic_error("case_file: key '" + std::string(path) + "' has no place in the documented order");
    return rank;
}

std::vector<CaseKey> make_schema() {
    std::vector<CaseKey> keys;
    for (const std::vector<CaseKey>& section : {name_keys(), flow_keys(), body_keys(), ibm_keys(), contact_keys(),
                                                rigidbody_keys(), turbulence_keys(), output_keys()})
        keys.insert(keys.end(), section.begin(), section.end());
    std::stable_sort(keys.begin(), keys.end(), [](const CaseKey& a, const CaseKey& b) {
        return documented_rank(a.path) < documented_rank(b.path);
    });
    return keys;
}

const std::vector<Placeholder>& case_placeholders() {
    static const std::vector<Placeholder> placeholders = [] {
        std::vector<Placeholder> all = flow_placeholders();
        for (Placeholder& p : body_placeholders()) all.push_back(std::move(p));
        return all;
    }();
    return placeholders;
}

std::string domain_text(const FlowConfig& c) {
    return "[" + exact_text(c.x.start) + ", " + exact_text(c.x.end) + "] x [" + exact_text(c.y.start) + ", " +
           exact_text(c.y.end) + "]";
}

bool outside(const FlowConfig& c, double x, double y) {
    return x < c.x.start || x > c.x.end || y < c.y.start || y > c.y.end;
}

// The run's outputs; the probes must lie in the domain.
void read_outputs(const CaseReader& r, CaseConfig& c) {
    c.field_interval = r.number("output.fields_interval");
    c.checkpoint_interval = r.number("output.checkpoint_interval");
    c.checkpoints_kept = static_cast<int>(r.integer("output.checkpoints_kept"));
    c.timeseries_every = static_cast<int>(r.integer("output.timeseries_every"));
    c.progress_interval = r.number("output.progress_interval");
    c.probes = r.point_list("output.probes");
    for (std::size_t i = 0; i < c.probes.size(); ++i) {
        const auto [px, py] = c.probes[i];
        if (outside(c, px, py))
            r.fail(CaseReader::indexed("output.probes", i),
                   "point [" + exact_text(px) + ", " + exact_text(py) + "] lies outside the domain " + domain_text(c));
    }
    c.plots = r.boolean("output.plots");
}

CaseConfig read_case(const CaseReader& r, const std::string& default_name) {
    r.check_presence();
    CaseConfig c;

    c.name = r.present("name") ? r.string("name") : default_name;
    if (c.name.empty()) r.fail("name", "must not be empty");
    if (c.name.find_first_of("/\\") != std::string::npos)
        r.fail("name", "must not contain '/' or '\\' (output files are named after it), got '" + c.name + "'");
    // The results go to results/<name> by default: '.' and '..' would put them in results/ or beside it.
    if (c.name == "." || c.name == "..")
        r.fail("name", "must not be '.' or '..' (the results folder is results/<name>), got '" + c.name + "'");
    if (std::any_of(c.name.begin(), c.name.end(), [](char ch) { return static_cast<unsigned char>(ch) < 0x20; }))
        r.fail("name", "must not contain control characters (a file name is made of it)");

    static_cast<FlowConfig&>(c) = read_flow(r);
    c.gravity = read_gravity(r);
    // A plane crosses the domain: its force coefficients' default length is the domain's diagonal.
    c.bodies = read_bodies(r, std::hypot(c.x.end - c.x.start, c.y.end - c.y.start));
    for (const BodyConfig& b : c.bodies)
        for (const auto& [x, y] : placement_points(b))
            if (outside(c, x, y))
                r.fail(placement_key(b), "the body reaches outside the domain " + domain_text(c) + ": point [" +
                                             exact_text(x) + ", " + exact_text(y) + "]");
    c.ibm = read_ibm(r);
    c.contact = read_contact(r);
    c.lumped = read_lumped(r);
    c.coupling = read_coupling(r);
    c.turbulence = read_turbulence(r);
    read_outputs(r, c);
    return c;
}

}  // namespace

const std::vector<CaseKey>& case_schema() {
    static const std::vector<CaseKey> schema = make_schema();
    return schema;
}

CaseConfig parse_case(const YAML::Node& root) {
    CaseReader reader(case_schema(), case_placeholders());
    reader.add_document(root);
    return read_case(reader, "case");
}

CaseConfig parse_case_text(const std::string& yaml_text, const std::vector<std::string>& overrides) {
    CaseReader reader(case_schema(), case_placeholders());
    reader.add_text(yaml_text);
    for (const std::string& o : overrides) reader.add_override(o);
    return read_case(reader, "case");
}

CaseConfig load_case(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
    const std::string name = file.string();
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw CaseError(name + ": case file not found");
    if (std::filesystem::is_directory(file, ec)) throw CaseError(name + ": is a directory, not a case file");
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) throw CaseError(name + ": cannot read the case file");
    CaseReader reader(case_schema(), case_placeholders(), name);
    reader.add_text(text.str());
    for (const std::string& o : overrides) reader.add_override(o);
    return read_case(reader, file.stem().string());
}

std::string schema_markdown() { return markdown_table(case_schema()); }

}  // namespace chute
