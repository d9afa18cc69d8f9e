#pragma once
// The parsed, validated contents of a case file (see docs/case-file.md for every key).
// Plain data: the parser (case_file.cpp) fills it, the solver reads it.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace chute {

struct AxisConfig {
    double start = 0.0, end = 1.0;
    int cells = 32;
    std::string spacing = "uniform";  // uniform | tanh | geometric | lines
    double beta = 2.0;                // tanh clustering strength
    double ratio = 1.05;              // geometric growth ratio
    std::vector<double> lines;        // explicit lines (spacing: lines)
};

enum class BoundaryType { wall, slip, inflow, outflow, periodic };
enum class OutflowKind { convective, zero_stress };
enum class InflowProfile { uniform, parabolic };

struct BoundaryConfig {
    BoundaryType type = BoundaryType::wall;
    std::array<double, 2> velocity{0.0, 0.0};  // wall: wall velocity; inflow (uniform): inflow velocity
    InflowProfile profile = InflowProfile::uniform;
    double peak = 0.0;                          // parabolic inflow: peak normal speed into the domain
    OutflowKind outflow = OutflowKind::convective;
};

enum class ConvectionScheme { central, van_leer, koren };
enum class InitialCondition { uniform, taylor_green };

struct CaseConfig {
    std::string name = "case";
    AxisConfig x, y;
    double density = 1000.0;    // kg/m^3
    double viscosity = 1e-6;    // kinematic, m^2/s
    double depth = 1.0;         // m, span of a 2D run
    std::array<double, 2> body_force{0.0, 0.0};  // m/s^2, constant acceleration on the fluid

    InitialCondition initial = InitialCondition::uniform;
    std::array<double, 2> initial_velocity{0.0, 0.0};  // uniform current
    double taylor_green_amplitude = 1.0;

    std::array<BoundaryConfig, 4> boundary;  // indexed by Side: left, right, bottom, top

    ConvectionScheme convection = ConvectionScheme::central;
    double end_time = 1.0;
    long max_steps = -1;          // -1: no limit
    double cfl = 0.3;             // AB2 stability: central 0.5+, van_leer 0.4, koren 0.3 (docs/case-file.md)
    double diffusion_number = 0.2; // dt <= d / (nu (1/dx^2 + 1/dy^2)); AB2 is stable up to 0.25
    std::optional<double> fixed_dt;
    double max_dt = 1e30;
    double poisson_tolerance = 1e-8;
    int poisson_max_iterations = 200;
    double divergence_limit = 1e-3;   // abort if max |div u| dt exceeds this
    std::array<int, 2> ranks{0, 0};   // 0: automatic

    // Outputs
    double field_interval = 0.0;       // s between field snapshots; 0: first and last only
    double checkpoint_interval = 0.0;  // s between checkpoints; 0: last only
    int checkpoints_kept = 2;
    int timeseries_every = 1;          // steps
    double progress_interval = 2.0;    // wall seconds between progress lines
    std::vector<std::array<double, 2>> probes;
    bool plots = true;
};

}  // namespace chute
