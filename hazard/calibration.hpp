#pragma once
// Calibration of the wet lumped model (trajectory.hpp) by Chute's CFD runs of one block (`chute calibrate`):
//
//   C_D  from the free fall's terminal speed v_t: the model's v_t^2 = 2 (rho_s - rho_f) g a / (rho_f C_D);
//   C_a  from its early acceleration: the least-squares fit of the model's closed form
//        v(t) = v_t tanh(g' t / v_t), g' = (rho_s - rho_f) g / (rho_s + C_a rho_f), to the CFD's speed up to
//        0.8 v_t (a window, not the first step: the run's first step is the CFL limit of water at rest);
//   kappa_n  from bounces on a bed: the lumped block leaves the bed at the CFD's impact with the wet law's
//        velocity and flies under the model; kappa_n makes its bounce height the CFD's (one value per run,
//        then their least-squares fit, weighted alike). With three or more bed runs after different falls, the
//        wake's growth too (wet_rebound.hpp): kappa_n(travel) = kappa_n + (kappa_n_start - kappa_n)
//        exp(-travel / wake_length) through the runs' own values, by least squares;
//   the ground effect  from the bed runs' approach (ground_effect.hpp): the lumped block flown from the CFD's
//        state a few block sizes above the impact point to the impact; strength and decay by least squares on its
//        speed normal to the bed against the CFD's at equally spaced clearances (a scan of the decay refined by
//        golden section, the strength by golden section for each). It then acts in every lumped flight below,
//        so the restitution coefficients are those of a block braked by the water as the CFD's is;
//   the slope's law  from bounces on one slope angle (wet_rebound.hpp): each run's own kappa_n and push, the pair
//        that gives its bounce height and its runout to the next impact; kappa_n tabulated against the impact's
//        angle from the normal, the push against travel. kappa_t is not fitted (1: Rt in water, the study's
//        assumption): the impacts' tangential velocities are too scattered (0.03-1.25 m/s on the 30 degree runs)
//        to carry what the water does along the slope.
// Runs marked `check` are not fitted to: the calibrated model's bounce height and runout are compared with
// theirs (the acceptance: within 15 %).
//
// The CFD runs measure bounces as the study ran them: a horizontal bed with gravity tilted by the slope's angle
// (the physics of a slope), impacts at the contact distance; the lumped block meets a plane along the same
// gravity at the same velocity, so both measure height and runout from their impact point.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "calibration_file.hpp"
#include "trajectory.hpp"

namespace chute {

struct FreeFallObservation {
    std::vector<double> t, speed;  // the CFD block's speed along gravity
    double terminal_speed = 0.0;   // mean over the last `terminal_window` s
    double terminal_window = 0.5;
};

// One CFD bounce, in the bed's frame (x along it, y out of it; gravity tilted by the slope's angle).
struct BounceObservation {
    std::string name;
    bool fitted = true;           // false: a check
    double slope_angle = 0.0;     // rad: gravity's angle from the bed's normal (0: a horizontal bed)
    Vec2 impact_velocity;         // at the first impact
    double travel = 0.0;          // block sizes from the release to the first impact
    double rebound_height = 0.0;  // the centre's largest rise out of the bed between the first two impacts
    double runout = 0.0;          // along the bed from the first impact to the second (NaN: no second one)
    double size = 0.0, density = 0.0;
    // The approach: the CFD block's velocity (bed frame) at clearances above the impact point, falling to 0 (the
    // impact), from a few block sizes up (or the release, if lower). Empty: none measured.
    std::vector<double> approach_clearance;
    std::vector<Vec2> approach_velocity;
    // Where and how the CFD block was released, from the impact point (bed frame; NaN: not known).
    Vec2 release_offset = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
    Vec2 release_velocity = Vec2::Zero();
    double normal_restitution = 0.8, tangential_restitution = 0.8;  // the run's contact law (dry)
    bool on_bed() const { return std::abs(slope_angle) < 1e-9; }    // straight up and down: no runout
    double impact_angle() const { return impact_obliquity(impact_velocity.x(), impact_velocity.y()); }  // rad
};

struct BlockFluid {
    double fluid_density = 1000.0, viscosity = 1.0e-3, gravity = 9.81;
};

// A lumped bounce on the tilted bed: its top above the plane and the runout to its next impact.
struct LumpedBounce {
    double height = std::numeric_limits<double>::quiet_NaN(), runout = std::numeric_limits<double>::quiet_NaN();
};

struct CalibrationPoint {
    BounceObservation cfd;
    double stokes = 0.0;                              // of the first impact
    double kappa = 0.0;                               // this run's own kappa_n (NaN: checks)
    double push = 0.0;                                // a slope run's own push (wet_rebound.hpp; NaN: beds and checks)
    double law_kappa = 0.0;                           // the calibrated law's kappa_n at this run's travel and angle
    double law_push = 0.0;                            // and its push
    double lumped_height = 0.0, lumped_runout = 0.0;  // the calibrated model's
    // The approach flown by the calibrated model from the CFD's first approach sample: its speed normal to the bed
    // at the impact, with the ground effect and without (NaN: no approach).
    double approach_impact_speed = std::numeric_limits<double>::quiet_NaN();
    double approach_impact_speed_plain = std::numeric_limits<double>::quiet_NaN();
    // The whole bounce as a hazard run flies it: the calibrated model from the CFD's release, through its own impact
    // (the law at its own impact velocity and travel) to the next impact (NaN: no release known).
    LumpedBounce released;
    double released_impact_speed = std::numeric_limits<double>::quiet_NaN();  // normal to the bed
    // A fitted slope run's height and runout by the slope law fitted to the other slope runs (NaN: not one).
    double left_out_height = std::numeric_limits<double>::quiet_NaN();
    double left_out_runout = std::numeric_limits<double>::quiet_NaN();
};

struct Calibration {
    CalibrationFile constants;
    double terminal_speed = 0.0, early_window = 0.0;  // s: the C_a fit's window [0, early_window]
    double early_rms = 0.0;                           // m/s: the C_a fit's residual
    std::vector<CalibrationPoint> points;
};

double drag_coefficient_from_terminal_speed(double terminal_speed, double size, double density, const BlockFluid& f);

// The lumped block's bounce from the impact at `o.impact_velocity` on a plane along tilted gravity.
LumpedBounce lumped_bounce(const BounceObservation& o, const BlockFluid& f, double drag_coefficient,
                           double added_mass_coefficient, const WetRebound& law, const GroundEffect& ground = {});

// The same bounce flown from the CFD's release (o.release_*), as a hazard run would: its own impact, the law at its
// own impact velocity and travel. `impact_speed`: its normal speed at the impact.
LumpedBounce lumped_bounce_from_release(const BounceObservation& o, const BlockFluid& f, double drag_coefficient,
                                        double added_mass_coefficient, const WetRebound& law,
                                        const GroundEffect& ground, double& impact_speed);

// Where `target` falls among the falling clearances c (c[0] > c[1] > ...): the interval [k - 1, k] and the weight
// of c[k] in a linear interpolation, held at the ends. The CFD's approach samples and the lumped block's are both
// read this way.
struct FallingBracket {
    std::size_t k = 1;
    double weight = 1.0;
    template <class V>
    V at(const std::vector<V>& y) const {
        return y[k - 1] + weight * (y[k] - y[k - 1]);
    }
};
FallingBracket bracket_falling(const std::vector<double>& c, double target);

// The lumped block's approach: flown from the CFD's first approach sample (o.approach_*) to the plane, its speed
// normal to the plane (positive towards it) at each sample's clearance; the last is the impact's.
std::vector<double> lumped_approach(const BounceObservation& o, const BlockFluid& f, double drag_coefficient,
                                    double added_mass_coefficient, const GroundEffect& ground);

Calibration calibrate(const FreeFallObservation& fall, double size, double density,
                      const std::vector<BounceObservation>& bounces, const BlockFluid& f, double beta = 35.0);

// The points as a CSV table (calibration_points.csv) and as Markdown.
std::string calibration_points_csv(const Calibration& c);
std::string calibration_markdown(const Calibration& c);

}  // namespace chute
