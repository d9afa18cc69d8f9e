#pragma once
// The flow's part of a case (docs/case-file.md): the domain and its grid, the fluid, the initial field, the
// condition on each side, the numerics of the projection method, the length of the run and its decomposition.
// Plain data: read_flow() fills it from the case file (flow_keys.cpp, the schema's flow section), FlowSolver
// runs it. The whole case (run/case_config.hpp) is this plus each module's own config.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "poisson_method.hpp"

namespace chute {

struct AxisConfig {
    double start = 0.0, end = 1.0;
    int cells = 32;
    std::string spacing = "uniform";       // uniform | tanh | geometric | clustered | lines
    double beta = 2.0;                     // tanh clustering strength
    double ratio = 1.05;                   // geometric growth ratio
    std::vector<double> lines;             // explicit lines (spacing: lines)
    std::array<double, 2> core{0.0, 0.0};  // clustered: the uniform window
    int core_cells = 0;                    // clustered: cells in the window
    double first = 0.0;                    // clustered: width at the window's ends (0: uniform window)
    double max_width = 0.0;                // clustered: the outer cells' cap (0: none)
};

enum class BoundaryType { wall, slip, inflow, outflow, periodic };
enum class OutflowKind { convective, zero_stress };
enum class InflowProfile { uniform, parabolic };

// The case file's names of the sides (boundaries.<side>), indexed like the boundaries: left, right, bottom, top.
inline constexpr std::array<std::string_view, 4> kSideNames = {"left", "right", "bottom", "top"};

// The first side at an end of `axis` (0: x, 1: y) that is a wall or a slip wall, or -1: what a grid translating
// along that axis cannot carry with it (its boundaries move with it: band/body_fitted, run/following_frame).
inline int wall_across(const std::array<BoundaryType, 4>& types, int axis) {
    for (int s = 2 * axis; s < 2 * axis + 2; ++s)
        if (types[s] == BoundaryType::wall || types[s] == BoundaryType::slip) return s;
    return -1;
}

struct BoundaryConfig {
    BoundaryType type = BoundaryType::wall;
    std::array<double, 2> velocity{0.0, 0.0};  // wall: wall velocity; inflow (uniform): inflow velocity
    InflowProfile profile = InflowProfile::uniform;
    double peak = 0.0;  // parabolic inflow: peak normal speed into the domain
    OutflowKind outflow = OutflowKind::convective;
};

enum class ConvectionScheme { central, van_leer, koren };
enum class InitialCondition { uniform, taylor_green };
// explicit: AB2; implicit: backward Euler (core/implicit_diffusion.hpp); automatic: explicit for laminar runs,
// with an eddy viscosity implicit for the steps the explicit diffusion limit would shorten.
enum class DiffusionScheme { explicit_ab2, implicit_euler, automatic };

struct FlowConfig {
    AxisConfig x, y;
    double density = 1000.0;                     // kg/m^3
    double viscosity = 1e-6;                     // kinematic, m^2/s
    double depth = 1.0;                          // m, span of a 2D run
    std::array<double, 2> body_force{0.0, 0.0};  // m/s^2, constant acceleration on the fluid

    InitialCondition initial = InitialCondition::uniform;
    std::array<double, 2> initial_velocity{0.0, 0.0};  // uniform current
    double taylor_green_amplitude = 1.0;
    double initial_perturbation = 0.0;  // m/s, cross-stream sine added to the uniform start

    std::array<BoundaryConfig, 4> boundary;  // indexed by Side: left, right, bottom, top

    ConvectionScheme convection = ConvectionScheme::central;
    double end_time = 1.0;
    long max_steps = -1;            // -1: no limit
    double cfl = 0.3;               // AB2 stability: central 0.5+, van_leer 0.4, koren 0.3 (docs/case-file.md)
    double diffusion_number = 0.2;  // dt <= d / (nu (1/dx^2 + 1/dy^2)); AB2 is stable up to 0.25
    DiffusionScheme diffusion = DiffusionScheme::automatic;  // time integration of the stress (flow_solver.hpp)
    std::optional<double> fixed_dt;
    double max_dt = 1e30;
    double poisson_tolerance = 1e-8;
    int poisson_max_iterations = 200;
    PoissonMethod poisson_method = PoissonMethod::automatic;
    double divergence_limit = 1e-3;  // abort if max |div u| dt exceeds this
    std::array<int, 2> ranks{0, 0};  // 0: automatic
};

// The grid lines an axis of the case describes (its spacing and their parameters), made by the generators of
// core/grid/axis.hpp. The reader makes them once to check them; the solver makes its grid from them.
std::vector<double> axis_lines(const AxisConfig& c);

// Cells a case may ask for, all axes together: a check before anything is allocated. A run takes about 700
// bytes per cell with k-epsilon and bodies (360 laminar, measured at 1.5 million cells), so this is some 70 GB,
// and it keeps every global cell index well inside hypre's 32-bit integers.
constexpr double kMaxCells = 1e8;

// The schema's flow section (io/case_reader.hpp): domain.*, fluid.*, initial.*, boundaries.*, numerics.* but
// numerics.ibm, time.*, parallel.*; the placeholders `<axis>` (x, y) and `<side>` (left, right, bottom, top);
// and the reading of it, with the checks inside the section (end > start, periodic pairs, wall velocity
// along the wall, an inflow needs an outflow, dt <= max_dt).
struct CaseKey;
struct Placeholder;
class CaseReader;
std::vector<CaseKey> flow_keys();
std::vector<Placeholder> flow_placeholders();
FlowConfig read_flow(const CaseReader& reader);

}  // namespace chute
