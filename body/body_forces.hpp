#pragma once
// The force record of one body after a step, whoever carries it (N for the case's depth, N m about the
// body's centre). Two sources fill it, each its own part:
//   the carrier (carrier.hpp): the hydrodynamic force measured two independent ways,
//     (a) `forcing`: what the carrier imposed on the flow to move it with the body (immersed boundary: the
//         forcing sum plus the fluid momentum inside the body, Uhlmann 2005 eq. 23);
//     (b) `surface`: the stress integrated over the surface, split into pressure, viscous and turbulent parts
//         (Turmel & Locat 2008, eq. 10-15);
//   free-body dynamics (rigidbody/free_bodies.hpp): gravity, buoyancy and contact (zero for fixed and
//     prescribed bodies).
#include "outline.hpp"

namespace chute {

struct SurfaceForces {
    Vec2 pressure = Vec2::Zero(), viscous = Vec2::Zero(), turbulent = Vec2::Zero();  // N (per body: times depth)
    double pressure_torque = 0.0, viscous_torque = 0.0, turbulent_torque = 0.0;      // N m
    Vec2 total() const { return pressure + viscous + turbulent; }
    double total_torque() const { return pressure_torque + viscous_torque + turbulent_torque; }
};

// What moved a free body besides the fluid over the last step. An impact is an impulse (N s), recorded as
// one rather than as a force impulse / dt that would scale with 1/dt: the obstacle's on the body and the
// water's, the jump of the fluid's momentum the body reverses with it (rigidbody/free_bodies.hpp). `contact` is
// what the obstacles push with between impacts (resting, sliding, the soft law).
struct BodyLoads {
    Vec2 gravity = Vec2::Zero(), buoyancy = Vec2::Zero(), contact = Vec2::Zero();
    double contact_torque = 0.0;
    Vec2 contact_impulse = Vec2::Zero(), water_impulse = Vec2::Zero();  // N s, in a step with an impact
    double contact_angular_impulse = 0.0, water_angular_impulse = 0.0;  // N m s
};

struct BodyForces {
    Vec2 forcing = Vec2::Zero();            // (a); an impact's water impulse left out (loads.water_impulse)
    double forcing_torque = 0.0;            // (a)
    SurfaceForces surface;                  // (b)
    double max_slip = 0.0, rms_slip = 0.0;  // m/s: how far the fluid at the surface is from the body's velocity
    BodyLoads loads;                        // free bodies only

    Vec2 total() const { return forcing + loads.gravity + loads.buoyancy + loads.contact; }
    double total_torque() const { return forcing_torque + loads.contact_torque; }
};

}  // namespace chute
