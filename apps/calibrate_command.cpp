#include "calibrate_command.hpp"

#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <numbers>

#include "calibration.hpp"
#include "case_file.hpp"
#include "case_reader.hpp"
#include "hdf5_file.hpp"
#include "run_command.hpp"
#include "text_file.hpp"

namespace {

const std::vector<chute::CaseKey>& spec_keys() {
    using K = chute::KeyType;
    static const std::vector<chute::CaseKey> keys{
        {.path = "name",
         .type = K::string,
         .default_doc = "file stem",
         .meaning = "The calibration's name: DIR/<name>.yaml is written."},
        {.path = "beta",
         .type = K::number,
         .default_value = "35.0",
         .min = chute::at_least(0.0),
         .meaning = "The wet law's viscous exponent, not fitted (Legendre et al. 2006)."},
        {.path = "free_fall", .type = K::section, .required = true, .meaning = "The block falling from rest."},
        {.path = "free_fall.case", .type = K::string, .required = true, .meaning = "Case file (relative to SPEC)."},
        {.path = "free_fall.set", .type = K::string_list, .default_value = "[]", .meaning = "Its --set overrides."},
        {.path = "bounces", .type = K::section, .required = true, .meaning = "Bounces on beds and slopes."},
        {.path = "bounces.<run>", .type = K::section, .meaning = "One bounce run, named by the spec."},
        {.path = "bounces.<run>.case", .type = K::string, .required = true, .meaning = "Case file (relative to SPEC)."},
        {.path = "bounces.<run>.set", .type = K::string_list, .default_value = "[]", .meaning = "Its --set overrides."},
        {.path = "bounces.<run>.use",
         .type = K::choice,
         .default_value = "fit",
         .choices = {"fit", "check"},
         .meaning = "fit: the constants are fitted to it (a horizontal bed: kappa_n and the wake's growth; a slope: "
                    "the slope's law, kappa_n and push against travel, all fitted slopes on one angle); check: only "
                    "compared with the calibrated model."},
    };
    return keys;
}

const std::vector<chute::Placeholder>& spec_placeholders() {
    static const std::vector<chute::Placeholder> p{{"<run>"}};
    return p;
}

struct RunSpec {
    std::string name;
    std::filesystem::path case_file;
    std::vector<std::string> overrides;
    bool fitted = true;
};

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    return text;
}

// The run's free body (the first one).
const chute::BodyConfig& free_body(const chute::CaseConfig& c, const std::string& run) {
    for (const chute::BodyConfig& b : c.bodies)
        if (b.motion.type == chute::MotionType::free) return b;
    throw chute::CaseError(run + ": the case has no free body");
}

struct Series {
    std::vector<double> t, x, y, u, v;
};

Series read_body_series(const std::filesystem::path& file) {
    Series s;
    io::CSVReader<5> in(file.string());
    in.read_header(io::ignore_extra_column, "t", "x", "y", "u", "v");
    double t, x, y, u, v;
    while (in.read_row(t, x, y, u, v))
        s.t.push_back(t), s.x.push_back(x), s.y.push_back(y), s.u.push_back(u), s.v.push_back(v);
    return s;
}

struct ContactRow {
    double t, x, y, u, v;
    std::string obstacle;
};

// The approach to the first impact (BounceObservation::approach_*): the CFD's velocity at 13 equally spaced
// clearances above the impact point, from 2 block sizes up (or the release, if lower) to the impact itself.
void approach_of(const Series& s, const ContactRow& impact, chute::BounceObservation& o) {
    std::vector<double> c;  // before the impact, clearance falling
    std::vector<chute::Vec2> velocity;
    for (std::size_t k = 0; k < s.t.size() && s.t[k] < impact.t; ++k)
        c.push_back(s.y[k] - impact.y), velocity.emplace_back(s.u[k], s.v[k]);
    if (c.size() < 2) return;
    const double top = std::min(2.0 * o.size, c.front());
    constexpr int intervals = 12;
    for (int i = 0; i <= intervals; ++i) {
        const double target = top * (1.0 - static_cast<double>(i) / intervals);
        if (i == intervals) {
            o.approach_clearance.push_back(0.0);
            o.approach_velocity.emplace_back(impact.u, impact.v);
            break;
        }
        o.approach_clearance.push_back(target);
        o.approach_velocity.push_back(chute::bracket_falling(c, target).at(velocity));
    }
}

std::vector<ContactRow> read_contacts(const std::filesystem::path& file) {
    std::vector<ContactRow> rows;
    io::CSVReader<6> in(file.string());
    in.read_header(io::ignore_extra_column, "t", "obstacle", "x_centre", "y_centre", "u_before", "v_before");
    ContactRow r;
    while (in.read_row(r.t, r.obstacle, r.x, r.y, r.u, r.v)) rows.push_back(r);
    return rows;
}

}  // namespace

std::string calibration_spec_keys_markdown() { return chute::markdown_table(spec_keys()); }

int calibrate_command(const std::filesystem::path& spec_file, const std::filesystem::path& out_dir, bool redo) {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (!std::filesystem::exists(spec_file))
        throw chute::CaseError(spec_file.string() + ": calibration spec not found");
    chute::CaseReader r(spec_keys(), spec_placeholders(), spec_file.string());
    r.add_text(chute::read_text_file(spec_file));
    r.check_presence();
    const std::filesystem::path folder = spec_file.parent_path().empty() ? "." : spec_file.parent_path();
    const std::string name = r.present("name") ? r.string("name") : spec_file.stem().string();
    const std::filesystem::path out = out_dir.empty() ? std::filesystem::path("results/calibration") / name : out_dir;
    std::vector<RunSpec> runs{{"free_fall", folder / r.string("free_fall.case"), r.string_list("free_fall.set"), true}};
    for (const std::string& section : r.instances("bounces.<run>"))
        runs.push_back({section.substr(section.find('.') + 1), folder / r.string(section + ".case"),
                        r.string_list(section + ".set"), r.choice(section + ".use") == "fit"});
    if (runs.size() < 2) r.fail("bounces", "give at least one bounce run");
    std::vector<chute::CaseConfig> configs;
    for (const RunSpec& run : runs) {  // every case is read and checked before the first run
        try {
            configs.push_back(chute::load_case(run.case_file, run.overrides));
        } catch (const chute::CaseError& e) {
            r.fail(run.name == "free_fall" ? "free_fall.case" : "bounces." + run.name + ".case", e.what());
        }
    }

    // The runs: made, or reused when their folder holds the same case run to the end.
    std::string provenance_runs, grids;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const RunSpec& run = runs[i];
        const std::filesystem::path dir = out / "runs" / run.name;
        const std::string text = case_as_run(run.case_file, run.overrides);
        const bool done = !redo && std::filesystem::exists(dir / "summary.txt") &&
                          std::filesystem::exists(dir / "case.yaml") &&
                          chute::read_text_file(dir / "case.yaml") == text;
        if (rank == 0)
            std::printf("chute calibrate: %s (%zu of %zu): %s\n", run.name.c_str(), i + 1, runs.size(),
                        done ? "reusing the run already made" : "running");
        std::fflush(stdout);
        if (!done) {
            const int code = run_command(run.case_file, dir, run.overrides, "", true);
            if (code != 0) return code;
        }
        std::string sets;
        for (const std::string& o : run.overrides) sets += " --set " + o;
        provenance_runs += (i ? "; " : "") + run.name + " = " + run.case_file.lexically_normal().string() + sets;
        grids += (i ? "; " : "") + run.name + " " + std::to_string(configs[i].x.cells) + " x " +
                 std::to_string(configs[i].y.cells);
    }
    if (rank != 0) return 0;

    // The observations.
    const chute::CaseConfig& fall_case = configs[0];
    const chute::BodyConfig& block = free_body(fall_case, "free_fall");
    if (block.shape != chute::BodyShape::rectangle || block.size[0] != block.size[1])
        throw chute::CaseError("free_fall: the free body must be a square block (a rectangle of equal sides)");
    const double size = block.size[0], density = block.density;
    chute::BlockFluid fluid;
    fluid.fluid_density = fall_case.density;
    fluid.viscosity = fall_case.density * fall_case.viscosity;  // the case's is kinematic
    fluid.gravity = std::hypot(fall_case.gravity[0], fall_case.gravity[1]);

    chute::FreeFallObservation fall;
    {
        const Series s = read_body_series(out / "runs/free_fall/body_block.csv");
        const chute::Vec2 down = chute::Vec2(fall_case.gravity[0], fall_case.gravity[1]).normalized();
        for (std::size_t k = 0; k < s.t.size(); ++k)
            fall.t.push_back(s.t[k]), fall.speed.push_back(down.dot(chute::Vec2(s.u[k], s.v[k])));
        if (!read_contacts(out / "runs/free_fall/contacts.csv").empty())
            throw chute::CaseError("free_fall: the block meets an obstacle; the fall must end before it");
        double sum = 0.0;
        int n = 0;
        for (std::size_t k = 0; k < fall.t.size(); ++k)
            if (fall.t[k] >= fall.t.back() - fall.terminal_window) sum += fall.speed[k], ++n;
        fall.terminal_speed = sum / n;
    }
    std::vector<chute::BounceObservation> bounces;
    for (std::size_t i = 1; i < runs.size(); ++i) {
        const chute::CaseConfig& c = configs[i];
        const chute::BodyConfig& b = free_body(c, runs[i].name);
        const std::filesystem::path dir = out / "runs" / runs[i].name;
        std::vector<ContactRow> impacts;
        for (const ContactRow& row : read_contacts(dir / "contacts.csv"))
            if (row.obstacle == "bottom") impacts.push_back(row);
        if (impacts.empty()) throw chute::CaseError(runs[i].name + ": the block never meets the bed (the bottom wall)");
        chute::BounceObservation o;
        o.name = runs[i].name;
        o.fitted = runs[i].fitted;
        o.slope_angle = std::atan2(c.gravity[0], -c.gravity[1]);
        o.impact_velocity = chute::Vec2(impacts[0].u, impacts[0].v);
        o.size = b.size[0];
        o.density = b.density;
        o.normal_restitution = c.contact.normal_restitution;
        o.tangential_restitution = c.contact.tangential_restitution;
        const double t_next = impacts.size() > 1 ? impacts[1].t : 1e300;
        o.runout = impacts.size() > 1 ? impacts[1].x - impacts[0].x : std::nan("");
        const Series s = read_body_series(dir / "body_block.csv");
        o.travel = std::hypot(impacts[0].x - s.x.front(), impacts[0].y - s.y.front()) / o.size;
        for (std::size_t k = 0; k < s.t.size(); ++k)
            if (s.t[k] > impacts[0].t && s.t[k] < t_next)
                o.rebound_height = std::max(o.rebound_height, s.y[k] - impacts[0].y);
        approach_of(s, impacts[0], o);
        o.release_offset = chute::Vec2(s.x.front() - impacts[0].x, s.y.front() - impacts[0].y);
        o.release_velocity = chute::Vec2(s.u.front(), s.v.front());
        bounces.push_back(o);
    }

    const chute::Calibration cal = chute::calibrate(fall, size, density, bounces, fluid, r.number("beta"));
    chute::CalibrationFile file = cal.constants;
    file.date = utc_now();
    file.command = "chute calibrate " + spec_file.lexically_normal().string();
    file.runs = provenance_runs;
    file.grid = grids;
    file.points = name + "_points.csv";
    std::filesystem::create_directories(out);
    chute::write_calibration_file(out / (name + ".yaml"), file);
    chute::write_text_atomically(out / (name + "_points.csv"), chute::calibration_points_csv(cal));
    const std::string table = chute::calibration_markdown(cal);
    chute::write_text_atomically(out / (name + ".md"), "# Calibration " + name + "\n\n" + table);
    std::printf("%s\nchute calibrate: written %s\n", table.c_str(), (out / (name + ".yaml")).string().c_str());
    return 0;
}
