#include "calibration_file.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <numbers>
#include <sstream>
#include <tuple>
#include <vector>

#include "case_reader.hpp"
#include "hdf5_file.hpp"

namespace chute {

namespace {

const std::vector<CaseKey>& calibration_keys() {
    using K = KeyType;
    static const std::vector<CaseKey> keys{
        {.path = "model", .type = K::section, .required = true, .meaning = "The fitted constants."},
        {.path = "model.drag_coefficient", .type = K::number, .required = true, .min = above(0.0)},
        {.path = "model.added_mass_coefficient", .type = K::number, .required = true, .min = at_least(0.0)},
        {.path = "model.kappa_n", .type = K::number, .required = true, .min = above(0.0), .max = at_most(2.0)},
        {.path = "model.kappa_t", .type = K::number, .required = true, .min = above(0.0), .max = at_most(2.0)},
        {.path = "model.beta", .type = K::number, .required = true, .min = at_least(0.0)},
        {.path = "model.kappa_n_start", .type = K::number, .min = above(0.0), .max = at_most(2.0)},
        {.path = "model.wake_length", .type = K::number, .default_value = "0.0", .min = at_least(0.0)},
        {.path = "model.slope", .type = K::section, .meaning = "The slope's law (wet_rebound.hpp), if measured."},
        {.path = "model.slope.angle",
         .type = K::number,
         .required = true,
         .min = above(0.0),
         .max = at_most(90.0),
         .units = "degrees"},
        {.path = "model.slope.impact_angle",
         .type = K::number_list,
         .required = true,
         .min = at_least(0.0),
         .max = at_most(90.0),
         .units = "degrees"},
        {.path = "model.slope.travel",
         .type = K::number_list,
         .required = true,
         .min = at_least(0.0),
         .units = "block sizes"},
        {.path = "model.slope.kappa_n",
         .type = K::number_list,
         .required = true,
         .min = above(0.0),
         .max = at_most(2.0)},
        {.path = "model.slope.push",
         .type = K::number_list,
         .required = true,
         .min = at_least(-2.0),
         .max = at_most(2.0)},
        {.path = "model.ground_effect",
         .type = K::section,
         .meaning = "The squeezed water's drag near the ground (ground_effect.hpp), if measured."},
        {.path = "model.ground_effect.strength",
         .type = K::number,
         .required = true,
         .min = at_least(0.0),
         .max = at_most(100.0)},
        {.path = "model.ground_effect.decay",
         .type = K::number,
         .required = true,
         .min = above(0.0),
         .max = at_most(10.0),
         .units = "block sizes"},
        {.path = "block", .type = K::section, .required = true},
        {.path = "block.size", .type = K::number, .required = true, .min = above(0.0), .units = "m"},
        {.path = "block.density", .type = K::number, .required = true, .min = above(0.0), .units = "kg/m^3"},
        {.path = "provenance", .type = K::section},
        {.path = "provenance.date", .type = K::string, .default_value = "''"},
        {.path = "provenance.command", .type = K::string, .default_value = "''"},
        {.path = "provenance.runs", .type = K::string, .default_value = "''"},
        {.path = "provenance.grid", .type = K::string, .default_value = "''"},
        {.path = "provenance.points", .type = K::string, .default_value = "''"},
    };
    return keys;
}

}  // namespace

CalibrationFile read_calibration_file(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw CaseError(file.string() + ": calibration file not found");
    std::stringstream text;
    text << in.rdbuf();
    static const std::vector<Placeholder> none;
    CaseReader r(calibration_keys(), none, file.string());
    r.add_text(text.str());
    r.check_presence();
    CalibrationFile c;
    c.drag_coefficient = r.number("model.drag_coefficient");
    c.added_mass_coefficient = r.number("model.added_mass_coefficient");
    c.wet_rebound.kappa_n = r.number("model.kappa_n");
    c.wet_rebound.kappa_t = r.number("model.kappa_t");
    c.wet_rebound.beta = r.number("model.beta");
    c.wet_rebound.wake_length = r.number("model.wake_length");
    c.wet_rebound.kappa_n_start =
        r.present("model.kappa_n_start") ? r.number("model.kappa_n_start") : c.wet_rebound.kappa_n;
    if (r.present("model.slope")) {
        SlopeRebound& slope = c.wet_rebound.slope;
        slope.angle = r.number("model.slope.angle") * std::numbers::pi / 180.0;
        for (const double degrees : r.number_list("model.slope.impact_angle"))
            slope.impact_angle.push_back(degrees * std::numbers::pi / 180.0);
        slope.kappa_n = r.number_list("model.slope.kappa_n");
        slope.travel = r.number_list("model.slope.travel");
        slope.push = r.number_list("model.slope.push");
        // Two tables: kappa_n against the impact angle, the push against travel.
        for (const auto& [x_key, x, y_key, y] :
             {std::tuple{"model.slope.impact_angle", &slope.impact_angle, "model.slope.kappa_n", &slope.kappa_n},
              std::tuple{"model.slope.travel", &slope.travel, "model.slope.push", &slope.push}}) {
            if (x->empty()) r.fail(x_key, "give at least one value");
            for (std::size_t i = 1; i < x->size(); ++i)
                if ((*x)[i] <= (*x)[i - 1]) r.fail(x_key, "the values must increase");
            if (y->size() != x->size()) r.fail(y_key, std::string("give one value per entry of ") + x_key);
        }
    }
    if (r.present("model.ground_effect"))
        c.ground_effect = {r.number("model.ground_effect.strength"), r.number("model.ground_effect.decay")};
    c.block_size = r.number("block.size");
    c.block_density = r.number("block.density");
    c.date = r.string("provenance.date");
    c.command = r.string("provenance.command");
    c.runs = r.string("provenance.runs");
    c.grid = r.string("provenance.grid");
    c.points = r.string("provenance.points");
    return c;
}

void write_calibration_file(const std::filesystem::path& file, const CalibrationFile& c) {
    YAML::Emitter y;
    y.SetDoublePrecision(6);
    y << YAML::Comment(
        "The wet lumped model's constants for one block, fitted to Chute's CFD runs by "
        "`chute calibrate` (hazard/calibration.hpp); read by a hazard case's model.calibration.");
    y << YAML::BeginMap;
    y << YAML::Key << "model" << YAML::Value << YAML::BeginMap;
    y << YAML::Key << "drag_coefficient" << YAML::Value << c.drag_coefficient;
    y << YAML::Key << "added_mass_coefficient" << YAML::Value << c.added_mass_coefficient;
    y << YAML::Key << "kappa_n" << YAML::Value << c.wet_rebound.kappa_n;
    y << YAML::Key << "kappa_t" << YAML::Value << c.wet_rebound.kappa_t;
    y << YAML::Key << "beta" << YAML::Value << c.wet_rebound.beta;
    if (c.wet_rebound.wake_length > 0.0) {
        y << YAML::Key << "kappa_n_start" << YAML::Value << c.wet_rebound.kappa_n_start;
        y << YAML::Key << "wake_length" << YAML::Value << c.wet_rebound.wake_length;
    }
    if (const SlopeRebound& slope = c.wet_rebound.slope; slope.measured()) {
        y << YAML::Key << "slope" << YAML::Value << YAML::BeginMap;
        y << YAML::Key << "angle" << YAML::Value << slope.angle * 180.0 / std::numbers::pi;
        std::vector<double> degrees;
        for (const double a : slope.impact_angle) degrees.push_back(a * 180.0 / std::numbers::pi);
        y << YAML::Key << "impact_angle" << YAML::Value << YAML::Flow << degrees;
        y << YAML::Key << "kappa_n" << YAML::Value << YAML::Flow << slope.kappa_n;
        y << YAML::Key << "travel" << YAML::Value << YAML::Flow << slope.travel;
        y << YAML::Key << "push" << YAML::Value << YAML::Flow << slope.push;
        y << YAML::EndMap;
    }
    if (c.ground_effect.active()) {
        y << YAML::Key << "ground_effect" << YAML::Value << YAML::Flow << YAML::BeginMap;
        y << YAML::Key << "strength" << YAML::Value << c.ground_effect.strength;
        y << YAML::Key << "decay" << YAML::Value << c.ground_effect.decay << YAML::EndMap;
    }
    y << YAML::EndMap;
    y << YAML::Key << "block" << YAML::Value << YAML::Flow << YAML::BeginMap;
    y << YAML::Key << "size" << YAML::Value << c.block_size;
    y << YAML::Key << "density" << YAML::Value << c.block_density << YAML::EndMap;
    y << YAML::Key << "provenance" << YAML::Value << YAML::BeginMap;
    y << YAML::Key << "date" << YAML::Value << c.date;
    y << YAML::Key << "command" << YAML::Value << c.command;
    y << YAML::Key << "runs" << YAML::Value << c.runs;
    y << YAML::Key << "grid" << YAML::Value << c.grid;
    y << YAML::Key << "points" << YAML::Value << c.points;
    y << YAML::EndMap << YAML::EndMap;
    write_text_atomically(file, std::string(y.c_str()) + "\n");
}

}  // namespace chute
