#include "rigid_body.hpp"

namespace chute {

RigidInertia rigid_inertia(const Outline& outline, double density, double depth, std::array<bool, 3> locked) {
    RigidInertia m;
    m.volume = outline.area() * depth;
    m.mass = density * m.volume;
    m.inertia = density * outline.polar_moment() * depth;
    m.locked = locked;
    return m;
}

void set_accelerations(BodyState& s, const Wrench& w, const RigidInertia& m) {
    s.acceleration = w.force.cwiseProduct(m.inverse_mass());
    s.angular_acceleration = w.torque * m.inverse_inertia();
}

BodyState drift(const BodyState& s, double dt) {
    BodyState r = s;
    r.centre += s.velocity * dt + 0.5 * s.acceleration * dt * dt;
    r.velocity += s.acceleration * dt;
    r.angle += s.angular_velocity * dt + 0.5 * s.angular_acceleration * dt * dt;
    r.angular_velocity += s.angular_acceleration * dt;
    return r;
}

}  // namespace chute
