#pragma once
// What an impact does to a body's velocities, and the record the contact-event log keeps of it.
//
// At the impact point X on an obstacle with normal n (into the fluid), with v_n < 0 approaching:
//   lumped  (RocFall's lumped-mass law; Turmel & Locat 2008 used Rn = Rt = 0.8): on the centre's velocity,
//           v_n' = -Rn v_n, v_t' = Rt v_t; the spin is left as it was;
//   impulse on the contact point's velocity V = v + omega perp(r), r = X - x_c: V_n' = -Rn V_n, V_t' = Rt V_t,
//           reached by one impulse J at X: dv = J / m, d omega = (r x J) / I, so dV = K J with
//           K = diag(1/m) + perp(r) perp(r)^T / I (locked degrees of freedom have 1/m = 0 or 1/I = 0).
#include <string>

#include "contact_config.hpp"
#include "rigid_body.hpp"

namespace chute {

struct ContactEvent {
    double time = 0.0;
    std::string body, obstacle;
    Vec2 point = Vec2::Zero();   // contact point
    Vec2 normal = Vec2::Zero();  // the obstacle's, towards the body
    Vec2 centre = Vec2::Zero();  // the body's centre at the impact
    Vec2 velocity_before = Vec2::Zero(), velocity_after = Vec2::Zero();
    double angular_velocity_before = 0.0, angular_velocity_after = 0.0;
    // Effective coefficients at the contact point: -V_n'/V_n and V_t'/V_t (NaN when V_t = 0).
    double normal_restitution = 0.0, tangential_restitution = 0.0;
    bool rests = false;  // the rebound was slower than the rest speed: the body now rests on the obstacle
    // In a fluid (rigidbody/free_bodies.hpp): the body's velocity once the water it carries has been reversed
    // too, and the effective coefficients of that rebound (the wet restitution). In a vacuum: the law's.
    Vec2 velocity_wet = Vec2::Zero();
    double angular_velocity_wet = 0.0;
    double wet_normal_restitution = 0.0, wet_tangential_restitution = 0.0;
};

// Fills the event's effective coefficients from the contact point's velocity before and after the impact
// (and the wet rebound with them: the same until set_wet_rebound).
void set_effective_restitution(ContactEvent& e, const Vec2& before, const Vec2& after, const Vec2& n);
// The body's velocity once the water it carries has been reversed too, and its effective coefficients.
void set_wet_rebound(ContactEvent& e, const Vec2& velocity, double angular_velocity);

// Applies the case's rebound law at the impact point X (world) of an obstacle with normal n. Returns the event
// (time, names and `rests` are left for the caller).
ContactEvent rebound(BodyState& s, const Vec2& X, const Vec2& n, const RigidInertia& m, const ContactConfig& c);

}  // namespace chute
