#pragma once
// A free rigid body in 2D: its mass and moment of inertia (from the outline, the density and the run's depth),
// which degrees of freedom are locked, and its motion over a step under accelerations held constant.
//
// Held accelerations make the motion exact for a ballistic flight (gravity alone): x(t) = x0 + v0 t + a t^2/2.
// That is what lets dry runs match the analytic trajectory and rebound to round-off (docs/validation-targets.md).
#include <array>

#include "body.hpp"

namespace chute {

enum class Dof { x = 0, y = 1, rotation = 2 };

struct RigidInertia {
    double mass = 0.0;     // kg: density * area * depth
    double inertia = 0.0;  // kg m^2 about the centre of area: density * polar moment of area * depth
    double volume = 0.0;   // m^3: area * depth
    std::array<bool, 3> locked{false, false, false};  // indexed by Dof

    bool free(Dof d) const { return !locked[static_cast<int>(d)]; }
    // 1 along each free translation, 0 along a locked one: multiply a velocity or acceleration by it.
    Vec2 free_translation() const { return {free(Dof::x) ? 1.0 : 0.0, free(Dof::y) ? 1.0 : 0.0}; }
    // 1/m for each translation and 1/I for rotation, 0 where the degree of freedom is locked.
    Vec2 inverse_mass() const { return {free(Dof::x) ? 1.0 / mass : 0.0, free(Dof::y) ? 1.0 / mass : 0.0}; }
    double inverse_inertia() const { return free(Dof::rotation) ? 1.0 / inertia : 0.0; }
};

RigidInertia rigid_inertia(const Outline& outline, double density, double depth, std::array<bool, 3> locked);

// Force (N) at the centre of area and torque (N m) about it.
struct Wrench {
    Vec2 force = Vec2::Zero();
    double torque = 0.0;
};

// Sets the state's accelerations to those the wrench gives the body (zero along locked degrees of freedom).
void set_accelerations(BodyState& s, const Wrench& w, const RigidInertia& m);

// The state after dt with the state's accelerations held: exact for uniformly accelerated motion.
BodyState drift(const BodyState& s, double dt);

}  // namespace chute
