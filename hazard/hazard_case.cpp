// A hazard case's schema and its reading (hazard_case.hpp).
#include "hazard_case.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "calibration_file.hpp"
#include "case_reader.hpp"
#include "text_file.hpp"

namespace chute {

namespace {

struct Schema {
    std::deque<std::string> storage;  // the generated keys' text
    std::vector<CaseKey> keys;
    std::vector<Placeholder> placeholders{{"<material>"}, {"<collector>"}};
};

const Schema& schema() {
    static const Schema s = [] {
        Schema s;
        using K = KeyType;
        auto& k = s.keys;
        const auto add = [&](std::vector<CaseKey> more) { k.insert(k.end(), more.begin(), more.end()); };
        const auto dist = [&](const std::string& path, const std::string& units, const std::string& meaning,
                              const std::string& dflt = {}) {
            add(distribution_keys(s.storage, path, units, meaning, dflt));
        };
        add({
            {.path = "name",
             .type = K::string,
             .default_doc = "file stem",
             .meaning = "Analysis name; the results go to results/<name> by default."},
            {.path = "seed",
             .type = K::integer,
             .default_value = "1",
             .min = at_least(0),
             .meaning = "Seed of the random draws: a run is reproducible, on any number of ranks."},
            {.path = "trajectories",
             .type = K::integer,
             .default_value = "1000",
             .min = at_least(1),
             .meaning = "Number of blocks released (Monte Carlo trajectories)."},
            {.path = "gravity", .type = K::number, .default_value = "9.81", .min = above(0.0), .units = "m/s^2"},
            {.path = "water", .type = K::section, .meaning = "The water over the lower part of the profile."},
            {.path = "water.level",
             .type = K::number,
             .default_value = "-1.0e30",
             .default_doc = "none (all dry)",
             .units = "m",
             .meaning = "z of the water surface: segments and flight below it are wet."},
            {.path = "water.density",
             .type = K::number,
             .default_value = "1000.0",
             .min = above(0.0),
             .units = "kg/m^3"},
            {.path = "water.viscosity",
             .type = K::number,
             .default_value = "1.0e-3",
             .min = above(0.0),
             .units = "Pa s",
             .meaning = "Dynamic viscosity (the impact Stokes number's)."},
            {.path = "profile", .type = K::section, .required = true, .meaning = "The slope: points or a file."},
            {.path = "profile.points",
             .type = K::point_list,
             .units = "m",
             .meaning = "Vertices [x, z], x increasing (the ground lies below)."},
            {.path = "profile.material",
             .type = K::string,
             .meaning = "Material of every segment of profile.points (default: the only one defined)."},
            {.path = "profile.file",
             .type = K::string,
             .meaning = "CSV file with columns x, z, material (the material of the segment starting at that "
                        "row), relative to the case file."},
            {.path = "materials", .type = K::section, .required = true, .meaning = "The ground's materials."},
            {.path = "materials.<material>", .type = K::section, .meaning = "One material, named by the case."},
        });
        dist("materials.<material>.normal_restitution", "",
             "Dry normal coefficient of restitution Rn, drawn at "
             "each impact.",
             "0.8");
        dist("materials.<material>.tangential_restitution", "",
             "Dry tangential coefficient of restitution Rt, "
             "drawn at each impact.",
             "0.8");
        dist("materials.<material>.friction_angle", "degrees",
             "Friction angle of a sliding block, drawn when a "
             "slide starts.",
             "30");
        add({{.path = "materials.<material>.roughness",
              .type = K::number,
              .default_value = "0.0",
              .min = at_least(0.0),
              .max = at_most(45.0),
              .units = "degrees",
              .meaning = "Standard deviation of the segment's angle at an impact (RocFall's slope roughness)."},
             {.path = "block", .type = K::section, .required = true, .meaning = "The blocks (cubes of side `size`)."}});
        dist("block.size", "m", "Side of the block.");
        dist("block.density", "kg/m^3", "Density of the block.", "2650");
        add({{.path = "release", .type = K::section, .required = true, .meaning = "Where blocks start."}});
        dist("release.x", "m", "x of the release point.");
        dist("release.height", "m", "Height of the block's lowest point above the ground at release.", "0");
        dist("release.velocity_x", "m/s", "Horizontal release velocity.", "0");
        dist("release.velocity_z", "m/s", "Vertical release velocity.", "0");
        add({
            {.path = "model", .type = K::section, .meaning = "The wet lumped model (hazard/trajectory.hpp)."},
            {.path = "model.calibration",
             .type = K::string,
             .meaning = "A calibration file written by `chute calibrate` (relative to the case file): its C_D, C_a, "
                        "kappa_n, kappa_t, beta and the wake's growth are the defaults of the keys below, and its "
                        "slope law and ground effect are used (`model.slope_law`, `model.ground_effect`)."},
            {.path = "model.drag_coefficient",
             .type = K::number,
             .default_value = "2.0",
             .default_doc = "calibration's, else `2.0`",
             .min = at_least(0.0),
             .meaning = "C_D on the frontal area a^2 (Beranger et al. 1998; Turmel & Locat 2008: 2.0)."},
            {.path = "model.added_mass_coefficient",
             .type = K::number,
             .default_value = "0.5",
             .default_doc = "calibration's, else `0.5`",
             .min = at_least(0.0),
             .meaning = "C_a on the displaced mass (Turmel & Locat 2008: 0.5)."},
            {.path = "model.kappa_n",
             .type = K::number,
             .default_value = "1.0",
             .default_doc = "calibration's, else `1.0`",
             .min = above(0.0),
             .max = at_most(2.0),
             .meaning = "Wet normal restitution over the viscous law's, after a developed wake: e_n = Rn kappa_n "
                        "exp(-beta/St) (hazard/wet_rebound.hpp)."},
            {.path = "model.kappa_n_start",
             .type = K::number,
             .default_value = "1.0",
             .default_doc = "calibration's, else `1.0`",
             .min = above(0.0),
             .max = at_most(2.0),
             .meaning = "kappa_n of an impact right after the flight began (no wake yet); used when "
                        "`model.wake_length` > 0."},
            {.path = "model.wake_length",
             .type = K::number,
             .default_value = "0.0",
             .default_doc = "calibration's, else `0.0`",
             .min = at_least(0.0),
             .units = "block sizes",
             .meaning = "Travel over which the wake grows: kappa_n(travel) = kappa_n + (kappa_n_start - kappa_n) "
                        "exp(-travel / wake_length), travel in block sizes since the flight began in water (release, "
                        "water entry, last impact, end of a slide). 0: kappa_n at every impact."},
            {.path = "model.kappa_t",
             .type = K::number,
             .default_value = "1.0",
             .default_doc = "calibration's, else `1.0`",
             .min = above(0.0),
             .max = at_most(2.0),
             .meaning = "Wet tangential restitution over the dry one: e_t = Rt kappa_t."},
            {.path = "model.slope_law",
             .type = K::boolean,
             .default_value = "true",
             .meaning = "Use the calibration's slope law, if it has one: on inclined ground kappa_n against the "
                        "impact's angle from the normal and the water's push along the slope against travel (v_t' = "
                        "Rt kappa_t v_t + push |v_n|), measured by the CFD on one slope angle, interpolated in the "
                        "ground's angle from the bed's law (hazard/wet_rebound.hpp). false: the bed's law on every "
                        "slope, no push."},
            {.path = "model.ground_effect",
             .type = K::boolean,
             .default_value = "true",
             .meaning =
                 "Use the calibration's ground effect, if it has one: in water the squeezed water's drag on the "
                 "block's velocity normal to the ground, 1/2 rho C_D A G(c) |v_n| v_n with G(c) = strength "
                 "exp(-c / (decay a)) at clearance c (hazard/ground_effect.hpp), fitted to the CFD's approach to "
                 "the bed. false: the free-stream drag down to the ground."},
            {.path = "model.beta",
             .type = K::number,
             .default_value = "35.0",
             .default_doc = "calibration's, else `35.0`",
             .min = at_least(0.0),
             .meaning = "Viscous loss exponent (Legendre et al. 2006: 35)."},
            {.path = "model.sliding_speed",
             .type = K::number,
             .default_value = "0.1",
             .min = above(0.0),
             .units = "m/s",
             .meaning = "A rebound slower than this normal to the ground turns into a slide."},
            {.path = "model.end_time",
             .type = K::number,
             .default_value = "600.0",
             .min = above(0.0),
             .units = "s",
             .meaning = "A block still moving then is counted as such (end: time_limit)."},
            {.path = "model.relative_tolerance",
             .type = K::number,
             .default_value = "1.0e-8",
             .min = above(0.0),
             .max = at_most(1e-3),
             .meaning = "CVODE's relative tolerance (absolute: 1e-2 of it, in m and m/s)."},
            {.path = "collectors",
             .type = K::section,
             .meaning = "Stations where passing blocks are counted: a pipeline, a cable, a barrier."},
            {.path = "collectors.<collector>", .type = K::section, .meaning = "One collector, named by the case."},
            {.path = "collectors.<collector>.x", .type = K::number, .required = true, .units = "m"},
            {.path = "collectors.<collector>.height",
             .type = K::number,
             .default_value = "0.0",
             .min = at_least(0.0),
             .units = "m",
             .meaning = "A block passing with its lowest point below this height above the ground hits it."},
            {.path = "output", .type = K::section},
            {.path = "output.stations",
             .type = K::integer,
             .default_value = "200",
             .min = at_least(2),
             .max = at_most(100000),
             .meaning = "Stations along the profile for the envelopes and the reach probability."},
            {.path = "output.paths",
             .type = K::integer,
             .default_value = "40",
             .min = at_least(0),
             .meaning = "Trajectories written whole (for the plots)."},
            {.path = "output.plots", .type = K::boolean, .default_value = "true"},
        });
        return s;
    }();
    return s;
}

double model_number(const CaseReader& r, const char* key, const CalibrationFile* calibration, double from_file) {
    return r.present(key) || calibration == nullptr ? r.number(key) : from_file;
}

HazardCase read_hazard_case(const CaseReader& r, const std::string& default_name, const std::filesystem::path& folder) {
    r.check_presence();
    HazardCase c;
    c.name = r.present("name") ? r.string("name") : default_name;
    if (c.name.empty() || c.name.find_first_of("/\\") != std::string::npos || c.name == "." || c.name == "..")
        r.fail("name", "must be a plain file name (the results folder is results/<name>), got '" + c.name + "'");
    c.seed = static_cast<unsigned long long>(r.integer("seed"));
    c.trajectories = r.integer("trajectories");
    c.settings.gravity = r.number("gravity");
    c.water_level = r.number("water.level");
    c.water.density = r.number("water.density");
    c.water.viscosity = r.number("water.viscosity");

    // Materials, in name order; the profile refers to them by name.
    std::map<std::string, int> index;
    for (const std::string& section : r.instances("materials.<material>")) {
        Material m;
        m.name = section.substr(section.find('.') + 1);
        m.normal_restitution = read_distribution(r, section + ".normal_restitution", {.at_least = 0.0, .at_most = 1.0});
        m.tangential_restitution =
            read_distribution(r, section + ".tangential_restitution", {.at_least = 0.0, .at_most = 1.0});
        m.friction_angle = read_distribution(r, section + ".friction_angle", {.at_least = 0.0, .at_most = 89.0});
        m.roughness = r.number(section + ".roughness");
        index[m.name] = static_cast<int>(c.materials.size());
        c.materials.push_back(m);
    }
    if (c.materials.empty()) r.fail("materials", "define at least one material (e.g. materials.rock)");

    // The profile: points and one material, or a file.
    const bool points = r.present("profile.points"), file = r.present("profile.file");
    if (points == file) r.fail("profile", "give either profile.points or profile.file");
    const auto material_of = [&](const std::string& name, const std::string& key) {
        const auto it = index.find(name);
        if (it == index.end()) {
            std::string known;
            for (const auto& [n, i] : index) known += (known.empty() ? "" : ", ") + n;
            r.fail(key, "unknown material '" + name + "' (defined: " + known + ")");
        }
        return it->second;
    };
    if (points) {
        for (const auto& [x, z] : r.point_list("profile.points")) c.profile_points.emplace_back(x, z);
        if (!r.present("profile.material") && c.materials.size() > 1)
            r.fail("profile.material", "missing (several materials are defined: name the profile's)");
        const int m = r.present("profile.material") ? material_of(r.string("profile.material"), "profile.material") : 0;
        c.segment_materials.assign(c.profile_points.empty() ? 0 : c.profile_points.size() - 1, m);
    } else {
        if (r.present("profile.material"))
            r.fail("profile.material", "not used with profile.file (its material column)");
        const std::filesystem::path csv = folder / r.string("profile.file");
        ProfileTable table;
        try {
            table = read_profile_csv(csv);
        } catch (const std::runtime_error& e) {
            r.fail("profile.file", e.what());
        }
        c.profile_points = table.points;
        for (std::size_t i = 0; i + 1 < table.materials.size(); ++i)
            c.segment_materials.push_back(
                material_of(table.materials[i], "profile.file (row " + std::to_string(i + 2) + ")"));
    }
    SlopeProfile profile = [&] {
        try {
            return c.profile();
        } catch (const std::invalid_argument& e) {
            r.fail(points ? "profile.points" : "profile.file", e.what());
        }
    }();

    // The model: the calibration's constants unless the case gives its own.
    std::optional<CalibrationFile> calibration;
    if (r.present("model.calibration")) {
        c.calibration = (folder / r.string("model.calibration")).string();
        try {
            calibration = read_calibration_file(c.calibration);
        } catch (const CaseError& e) {
            r.fail("model.calibration", e.what());
        }
    }
    const CalibrationFile* cal = calibration ? &*calibration : nullptr;
    c.settings.drag_coefficient = model_number(r, "model.drag_coefficient", cal, cal ? cal->drag_coefficient : 0.0);
    c.settings.added_mass_coefficient =
        model_number(r, "model.added_mass_coefficient", cal, cal ? cal->added_mass_coefficient : 0.0);
    c.settings.wet_rebound.kappa_n = model_number(r, "model.kappa_n", cal, cal ? cal->wet_rebound.kappa_n : 0.0);
    c.settings.wet_rebound.kappa_t = model_number(r, "model.kappa_t", cal, cal ? cal->wet_rebound.kappa_t : 0.0);
    c.settings.wet_rebound.beta = model_number(r, "model.beta", cal, cal ? cal->wet_rebound.beta : 0.0);
    c.settings.wet_rebound.kappa_n_start =
        model_number(r, "model.kappa_n_start", cal, cal ? cal->wet_rebound.kappa_n_start : 0.0);
    c.settings.wet_rebound.wake_length =
        model_number(r, "model.wake_length", cal, cal ? cal->wet_rebound.wake_length : 0.0);
    if (cal && r.boolean("model.slope_law")) c.settings.wet_rebound.slope = cal->wet_rebound.slope;
    if (cal && r.boolean("model.ground_effect")) c.settings.ground_effect = cal->ground_effect;
    c.settings.sliding_speed = r.number("model.sliding_speed");
    c.settings.end_time = r.number("model.end_time");
    c.settings.relative_tolerance = r.number("model.relative_tolerance");
    c.settings.absolute_tolerance = 1e-2 * c.settings.relative_tolerance;

    // Blocks and their release.
    c.block.size = read_distribution(r, "block.size", {.above = 0.0}, true);
    c.block.density = read_distribution(r, "block.density", {.above = 0.0});
    const bool any_water =
        c.water_level >
        std::min_element(c.profile_points.begin(), c.profile_points.end(), [](const Vec2& a, const Vec2& b) {
            return a.y() < b.y();
        })->y();
    if (any_water && !(c.block.density.lowest() > c.water.density))
        r.fail("block.density", "a block no denser than the water (" + exact_text(c.water.density) +
                                    " kg/m^3) floats: every draw must be denser");
    c.release.x = read_distribution(r, "release.x", {.above = profile.x_min()}, true);
    if (!(c.release.x.highest() < profile.x_max()))
        r.fail("release.x", "must lie inside the profile (x below " + exact_text(profile.x_max()) + ")");
    c.release.height = read_distribution(r, "release.height", {.at_least = 0.0});
    c.release.velocity_x = read_distribution(r, "release.velocity_x", {});
    c.release.velocity_z = read_distribution(r, "release.velocity_z", {});

    for (const std::string& section : r.instances("collectors.<collector>")) {
        Collector k;
        k.name = section.substr(section.find('.') + 1);
        k.x = r.number(section + ".x");
        if (!(k.x > profile.x_min() && k.x < profile.x_max()))
            r.fail(section + ".x", "must lie inside the profile (" + exact_text(profile.x_min()) + " < x < " +
                                       exact_text(profile.x_max()) + ")");
        k.height = r.number(section + ".height");
        c.collectors.push_back(k);
    }
    c.stations = static_cast<int>(r.integer("output.stations"));
    c.paths = static_cast<int>(r.integer("output.paths"));
    c.plots = r.boolean("output.plots");
    return c;
}

}  // namespace

HazardCase load_hazard_case(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw CaseError(file.string() + ": case file not found");
    CaseReader r(schema().keys, schema().placeholders, file.string());
    r.add_text(read_text_file(file));
    for (const std::string& o : overrides) r.add_override(o);
    return read_hazard_case(r, file.stem().string(), file.parent_path().empty() ? "." : file.parent_path());
}

HazardCase hazard_case_from_text(const std::string& yaml_text, const std::filesystem::path& folder) {
    CaseReader r(schema().keys, schema().placeholders);
    r.add_text(yaml_text);
    return read_hazard_case(r, "hazard", folder);
}

std::string hazard_keys_markdown() { return markdown_table(schema().keys); }

}  // namespace chute
