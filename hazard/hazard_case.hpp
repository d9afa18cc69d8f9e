#pragma once
// A hazard analysis's case (`chute hazard CASE.yaml`; its keys: docs/hazard-case-file.md): the slope profile
// and its materials, the water, the blocks and where they are released (sampled quantities, distribution.hpp),
// the wet lumped model's constants (given, or from a calibration file written by `chute calibrate`), the
// collectors (a pipeline, a cable, a barrier) and the outputs.
#include <filesystem>
#include <string>
#include <vector>

#include "distribution.hpp"
#include "material.hpp"
#include "slope_profile.hpp"
#include "trajectory.hpp"

namespace chute {

// A station along the profile where passing blocks are counted: a block hits it when it passes below `height`
// (its lowest point, above the ground).
struct Collector {
    std::string name;
    double x = 0.0;
    double height = 0.0;  // m; 0: only blocks rolling or sliding over it
};

struct BlockDraws {
    Distribution size = Distribution::fixed(0.3), density = Distribution::fixed(2650.0);
};

// Where and how fast: x along the profile, the height of the block's lowest point above the ground there, and
// the velocity.
struct ReleaseDraws {
    Distribution x = Distribution::fixed(0.0), height = Distribution::fixed(0.0);
    Distribution velocity_x = Distribution::fixed(0.0), velocity_z = Distribution::fixed(0.0);
};

struct HazardCase {
    std::string name;
    unsigned long long seed = 1;
    long trajectories = 1000;
    std::vector<Material> materials;
    std::vector<Vec2> profile_points;
    std::vector<int> segment_materials;
    double water_level = -1e30;
    WaterProperties water;
    TrajectorySettings settings;
    std::string calibration;  // the calibration file the model's constants came from (empty: the case's own)
    BlockDraws block;
    ReleaseDraws release;
    std::vector<Collector> collectors;
    int stations = 200;  // envelope stations along the profile
    int paths = 40;      // trajectories written whole (for plots)
    bool plots = true;

    SlopeProfile profile() const { return SlopeProfile(profile_points, segment_materials, water_level); }
};

// Reads a hazard case (with --set overrides "key=value"); every mistake is a CaseError naming the key.
HazardCase load_hazard_case(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
HazardCase hazard_case_from_text(const std::string& yaml_text, const std::filesystem::path& folder = ".");
// The key table of docs/hazard-case-file.md.
std::string hazard_keys_markdown();

}  // namespace chute
