#pragma once
// The wet lumped model's constants for one block, as `chute calibrate` fits them to Chute's CFD runs
// (calibration.hpp) and a hazard case reads them (`model.calibration`): C_D, C_a and the wet rebound law's
// kappa_n, kappa_t and beta, with the block they were fitted for and where they came from. YAML:
//   model: {drag_coefficient: 1.87, added_mass_coefficient: 0.61, kappa_n: 0.78, kappa_t: 0.95, beta: 35,
//           slope: {angle: 30, impact_angle: [3, 24], kappa_n: [0.82, 1.03],      (optional; degrees)
//                   travel: [3.1, 6.0], push: [0.03, -0.96]},
//           ground_effect: {strength: 2.1, decay: 0.29}}                              (optional; ground_effect.hpp)
//   block: {size: 0.3, density: 2500}
//   provenance: {date: ..., command: ..., runs: ..., grid: ..., points: calibration_points.csv}
#include <filesystem>
#include <string>

#include "ground_effect.hpp"
#include "wet_rebound.hpp"

namespace chute {

struct CalibrationFile {
    double drag_coefficient = 2.0, added_mass_coefficient = 0.5;
    WetRebound wet_rebound;
    GroundEffect ground_effect;
    double block_size = 0.0, block_density = 0.0;
    std::string date, command, runs, grid, points;
};

// Throws CaseError naming the file and key of a mistake.
CalibrationFile read_calibration_file(const std::filesystem::path& file);
// Atomically (write to a temporary, then rename).
void write_calibration_file(const std::filesystem::path& file, const CalibrationFile& c);

}  // namespace chute
