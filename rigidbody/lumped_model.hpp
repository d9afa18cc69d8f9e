#pragma once
// Lumped trajectory models: the block as a rigid point mass carrying its outline for contact; no fluid is
// solved. They run in milliseconds and are what the CFD runs are compared with.
//
//   dry (what RocFall computes):  m dv/dt = m g
//   Beranger et al. (1998), as Turmel & Locat (2008) used it (C_D = 2.0 for the block, C_a = 0.5):
//     (m + C_a rho_f V) dv/dt = (m - rho_f V) g - 1/2 rho_f C_D A |v - u_c| (v - u_c)
//   with V the block's volume, A its frontal area (side times depth) and u_c the current.
//
// SUNDIALS CVODE integrates between impacts; its root finding locates each impact (the gap to each obstacle)
// and the rebound law restarts the integration. The block keeps its angle (the lumped models do not rotate).
#include <vector>

#include "impacts.hpp"

namespace chute {

struct LumpedModelConfig {
    double mass = 0.0;                    // kg
    double volume = 0.0;                  // m^3
    double fluid_density = 0.0;           // kg/m^3; 0: dry
    double drag_coefficient = 2.0;        // C_D
    double added_mass_coefficient = 0.5;  // C_a
    double frontal_area = 0.0;            // m^2
    Vec2 gravity{0.0, -9.81};
    Vec2 current = Vec2::Zero();
    double relative_tolerance = 1e-11, absolute_tolerance = 1e-13;
};

// The model's acceleration at velocity v (the equation above; dry: g). The hazard analysis (hazard/) flies its
// blocks with it too, so that its dry limit is this model's.
Vec2 lumped_acceleration(const LumpedModelConfig& model, const Vec2& v);

struct LumpedSample {
    double t = 0.0;
    Vec2 position = Vec2::Zero(), velocity = Vec2::Zero();
};

struct LumpedTrajectory {
    std::vector<LumpedSample> samples;  // every output interval, and at each impact (before and after)
    std::vector<ContactEvent> events;
    bool rests = false;  // the run ended with the block at rest on an obstacle
};

LumpedTrajectory run_lumped_model(const LumpedModelConfig& model, const Outline& outline, const BodyState& start,
                                  const std::vector<Obstacle>& obstacles, const ContactConfig& contact, double t_end,
                                  double output_interval);

// The Beranger model's free fall from rest in still fluid, in closed form (along g):
//   v(t) = v_t tanh(g' t / v_t),  s(t) = (v_t^2 / g') ln cosh(g' t / v_t),
//   g' = (m - rho_f V) g / (m + C_a rho_f V),  v_t = sqrt(2 (m - rho_f V) g / (rho_f C_D A)).
struct BerangerFreeFall {
    double reduced_gravity, terminal_speed;
    double speed(double t) const;
    double distance(double t) const;
};
BerangerFreeFall beranger_free_fall(const LumpedModelConfig& model);

}  // namespace chute
