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
    std::string spacing = "uniform";       // uniform | tanh | geometric | clustered | lines
    double beta = 2.0;                     // tanh clustering strength
    double ratio = 1.05;                   // geometric growth ratio
    std::vector<double> lines;             // explicit lines (spacing: lines)
    std::array<double, 2> core{0.0, 0.0};  // clustered: the uniform window
    int core_cells = 0;                    // clustered: cells in the window
};

enum class BoundaryType { wall, slip, inflow, outflow, periodic };
enum class OutflowKind { convective, zero_stress };
enum class InflowProfile { uniform, parabolic };

struct BoundaryConfig {
    BoundaryType type = BoundaryType::wall;
    std::array<double, 2> velocity{0.0, 0.0};  // wall: wall velocity; inflow (uniform): inflow velocity
    InflowProfile profile = InflowProfile::uniform;
    double peak = 0.0;  // parabolic inflow: peak normal speed into the domain
    OutflowKind outflow = OutflowKind::convective;
};

// ---- Immersed bodies (ibm/) ----
enum class BodyShape { circle, rectangle, polygon, plane, segment };
enum class MotionType { fixed, constant_velocity, oscillation, uniform_acceleration, free };
enum class DeltaKernel { roma3, peskin4 };

// Prescribed motion of a body's reference point (its centre of area) and angle, from its initial place:
//   fixed; constant_velocity: x0 + V t; oscillation: x0 + A sin(2 pi f t + phase);
//   uniform_acceleration (from rest): x0 + a t^2 / 2.  Angles likewise.
//   free: moved by the forces on it (rigidbody/), starting with `velocity` and `angular_velocity`.
struct MotionConfig {
    MotionType type = MotionType::fixed;
    std::array<double, 2> velocity{0.0, 0.0}, amplitude{0.0, 0.0}, acceleration{0.0, 0.0};
    double angular_velocity = 0.0, angular_amplitude = 0.0, angular_acceleration = 0.0;  // rad, s
    double frequency = 0.0, phase = 0.0;                                                 // Hz, rad
    std::array<bool, 3> locked{false, false, false};                                     // free: x, y, rotation held
};

struct BodyConfig {
    std::string name;
    BodyShape shape = BodyShape::circle;
    std::array<double, 2> centre{0.0, 0.0};              // circle, rectangle
    double diameter = 0.0;                               // circle
    std::array<double, 2> size{0.0, 0.0};                // rectangle: width, height (before rotation)
    double angle = 0.0;                                  // rad: rectangle/polygon rotation, plane inclination
    std::vector<std::array<double, 2>> vertices;         // polygon
    std::array<double, 2> point{0.0, 0.0};               // plane: a point on it
    std::array<double, 2> from{0.0, 0.0}, to{0.0, 0.0};  // segment
    MotionConfig motion;
    double density = 0.0;                                     // kg/m^3, free bodies
    double reference_velocity = 1.0, reference_length = 1.0;  // force coefficients
};

struct IbmConfig {
    DeltaKernel kernel = DeltaKernel::roma3;
    int forcing_iterations = 3;                     // multi-direct forcing (Breugem 2012)
    double marker_spacing = 1.0;                    // in grid cells
    double retraction = 0.3;                        // markers moved inwards by this many cells
    std::array<double, 2> stress_probes{1.5, 2.5};  // probe distances along the normal, in cells
    double virtual_mass = 1.0;                      // C_V of the free-body update (Schwarz et al. 2015)
};

// ---- Free bodies (rigidbody/) and contact (contact/) ----
// Rebound laws at an impact (contact/rebound.hpp):
//   lumped (RocFall's lumped mass, Turmel & Locat 2008): the centre's velocity, v_n' = -Rn v_n, v_t' = Rt v_t;
//   impulse: the same coefficients on the contact point's velocity, by an impulse that also turns the body;
//   soft: a spring-dashpot at the contact point over a finite contact time, sub-stepped inside the step.
enum class ReboundLaw { lumped, impulse, soft };

struct ContactConfig {
    ReboundLaw law = ReboundLaw::lumped;
    double normal_restitution = 0.8;      // Rn
    double tangential_restitution = 0.8;  // Rt
    double rest_speed = 0.01;             // m/s: a slower rebound leaves the body resting on the obstacle
    double friction = 0.0;                // Coulomb coefficient while resting (sliding) on an obstacle
    double distance = 0.0;                // m: impacts happen at this gap (0: at the surface)
    double duration = 0.002;              // s: soft law, contact time of one impact
};

// The lumped trajectory models a run with free bodies writes beside its CFD result (rigidbody/lumped_model):
// Beranger et al. (1998) with these constants (Turmel & Locat 2008: C_D 2.0 for the block, C_a 0.5), and dry.
struct LumpedConfig {
    double drag_coefficient = 2.0;
    double added_mass_coefficient = 0.5;
};

// ---- Turbulence (turbulence/) ----
// laminar: nu only. k_epsilon: standard k-epsilon (Launder & Spalding 1974) with log-law wall functions on
// no-slip sides and immersed surfaces; nu_t = C_mu k^2 / eps enters the momentum equation.
enum class TurbulenceModelType { laminar, k_epsilon };
// explicit: AB2; implicit: backward Euler (core/implicit_diffusion.hpp); automatic: explicit for laminar runs,
// with an eddy viscosity implicit for the steps the explicit diffusion limit would shorten.
enum class DiffusionScheme { explicit_ab2, implicit_euler, automatic };

struct TurbulenceConfig {
    TurbulenceModelType model = TurbulenceModelType::laminar;
    double intensity = 0.05;         // I: inflow and initial k = 3/2 (I U)^2
    double length_scale = 0.1;       // m: inflow and initial eps = C_mu^{3/4} k^{3/2} / l
    double velocity_scale = 0.0;     // m/s: U of the initial k; 0: the largest inflow or initial speed
    double production_limit = 10.0;  // P_k <= limit * eps (0: no limiter)
    bool kato_launder = false;       // P_k = nu_t S Omega (Kato & Launder 1993) instead of nu_t S^2
    double image_distance = 2.0;     // cells: where wall functions sample the flow beside an immersed surface
};

enum class ConvectionScheme { central, van_leer, koren };
enum class InitialCondition { uniform, taylor_green };

struct CaseConfig {
    std::string name = "case";
    AxisConfig x, y;
    double density = 1000.0;                     // kg/m^3
    double viscosity = 1e-6;                     // kinematic, m^2/s
    double depth = 1.0;                          // m, span of a 2D run
    std::array<double, 2> body_force{0.0, 0.0};  // m/s^2, constant acceleration on the fluid
    std::array<double, 2> gravity{0.0, -9.81};   // m/s^2, on free bodies

    InitialCondition initial = InitialCondition::uniform;
    std::array<double, 2> initial_velocity{0.0, 0.0};  // uniform current
    double taylor_green_amplitude = 1.0;
    double initial_perturbation = 0.0;  // m/s, cross-stream sine added to the uniform start

    std::array<BoundaryConfig, 4> boundary;  // indexed by Side: left, right, bottom, top

    std::vector<BodyConfig> bodies;
    IbmConfig ibm;
    ContactConfig contact;
    LumpedConfig lumped;
    TurbulenceConfig turbulence;

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
    double divergence_limit = 1e-3;  // abort if max |div u| dt exceeds this
    std::array<int, 2> ranks{0, 0};  // 0: automatic

    // Outputs
    double field_interval = 0.0;       // s between field snapshots; 0: first and last only
    double checkpoint_interval = 0.0;  // s between checkpoints; 0: last only
    int checkpoints_kept = 2;
    int timeseries_every = 1;        // steps
    double progress_interval = 2.0;  // wall seconds between progress lines
    std::vector<std::array<double, 2>> probes;
    bool plots = true;
};

}  // namespace chute
