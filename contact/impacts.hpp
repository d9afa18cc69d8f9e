#pragma once
// A body's motion over one step among static obstacles: each impact is located inside the step, the rebound
// law applied there, and the motion continued from it, so nothing tunnels through a plane and a body that
// touches a plane after a rebound (gap 0, moving away) is not hit twice.
//
// Within the step the body's accelerations are held (rigid_body.hpp): for a ballistic flight the impact time
// and the rebound are exact to round-off. A rebound slower than `rest_speed` leaves the body resting on the
// obstacle: its normal velocity, spin and normal acceleration are removed while the obstacle pushes back, and
// it slides with Coulomb friction. Without that, Rn < 1 gives infinitely many ever smaller bounces.
//
// The soft law instead presses the body into the obstacle: from the first touch (located as above) a linear
// spring-dashpot acts at the deepest point, F_n = k d - c V_n while the overlap d > 0, V_n the contact
// point's normal speed, with Coulomb friction mu F_n against its sliding; sub-stepped (midpoint rule, 100
// sub-steps per contact time) with the step's other accelerations held. For contact time T and restitution e
// (Rn), with m* the contact point's effective mass: c = -2 m* ln(e) / T, k = m* (pi^2 + ln(e)^2) / T^2, so
// that a free impact lasts T and rebounds at e = exp(-pi xi / sqrt(1 - xi^2)) (docs/validation-targets.md). The
// event is written when the body leaves; one pressed longer than 10 T is taken as resting.
#include <optional>
#include <string>
#include <vector>

#include "obstacle.hpp"
#include "rebound.hpp"

namespace chute {

struct ContactState {
    int resting_on = -1;  // obstacle index, -1: in flight
    // Soft law: the obstacle being pressed (-1: none), since when, and the event opened at first touch.
    int pressed_on = -1;
    double pressed_since = 0.0;
    ContactEvent touch;
};

// The first time in (0, T] (or 0 itself, if the body already overlaps while approaching) at which the body,
// drifting from s, touches the obstacle while its nearest point moves towards it.
std::optional<double> time_of_impact(const Outline& outline, const BodyState& s, const Obstacle& obstacle, double T);

// Moves s from t to t + dt; returns the impacts in time order (event.time absolute).
std::vector<ContactEvent> move_with_contacts(BodyState& s, ContactState& contact, double t, double dt,
                                             const std::string& body_name, const Outline& outline,
                                             const RigidInertia& m, const std::vector<Obstacle>& obstacles,
                                             const ContactConfig& config);

}  // namespace chute
