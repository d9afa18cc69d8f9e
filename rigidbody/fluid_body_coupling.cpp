#include "fluid_body_coupling.hpp"

#include <cmath>
#include <limits>

namespace chute {

std::vector<Obstacle> obstacles_of(const CaseConfig& c) {
    // A plane body's normal points out of its solid (on the right of its direction (cos a, sin a)).
    std::vector<Obstacle> out;
    for (const BodyConfig& b : c.bodies)
        if (b.shape == BodyShape::plane)
            out.push_back({b.name, Vec2(b.point[0], b.point[1]), Vec2(-std::sin(b.angle), std::cos(b.angle))});
    const Vec2 lo(c.x.start, c.y.start), hi(c.x.end, c.y.end);
    const Obstacle sides[4] = {{"left", lo, Vec2::UnitX()},
                               {"right", hi, -Vec2::UnitX()},
                               {"bottom", lo, Vec2::UnitY()},
                               {"top", hi, -Vec2::UnitY()}};
    for (int s = 0; s < 4; ++s)
        if (c.boundary[s].type == BoundaryType::wall || c.boundary[s].type == BoundaryType::slip)
            out.push_back(sides[s]);
    // Impacts happen `contact.distance` away from each surface: move the planes out by it.
    for (Obstacle& ob : out) ob.point += c.contact.distance * ob.normal;
    return out;
}

FreeBodies::FreeBodies(const CaseConfig& config, ImmersedBoundary& ibm)
    : config_(config), ibm_(ibm), obstacles_(obstacles_of(config)), forces_(ibm.bodies().size()) {
    const Vec2 g(config.gravity[0], config.gravity[1]);
    for (std::size_t b = 0; b < ibm.bodies().size(); ++b) {
        const Body& body = ibm.bodies()[b];
        if (!body.free()) continue;
        Free f;
        f.index = b;
        f.inertia = rigid_inertia(body.outline(), body.config().density, config.depth, body.config().motion.locked);
        f.fluid_mass = config.density * body.area() * config.depth;
        f.fluid_inertia = config.density * body.polar_moment() * config.depth;
        f.start = body.state();
        // First prediction: gravity and buoyancy against the body's and the virtual mass.
        const double cv = config.ibm.virtual_mass;
        f.acceleration = (f.inertia.mass - f.fluid_mass) * g / (f.inertia.mass + cv * f.fluid_mass);
        f.acceleration = f.acceleration.cwiseProduct(f.inertia.free_translation());
        for (const Obstacle& ob : obstacles_)
            if (gap(body.outline(), body.state(), ob).distance < 0.0)
                throw std::invalid_argument("bodies." + body.name() + ": the body starts inside the obstacle `" +
                                            ob.name + "` (or within contact.distance of it)");
        free_.push_back(f);
    }
}

double FreeBodies::max_dt(double cfl) const {
    double dt = std::numeric_limits<double>::infinity();
    for (const Free& f : free_) {
        const Body& body = ibm_.bodies()[f.index];
        const double h = cfl * ibm_.forcing().cell_size(f.index);
        // Fastest point of the outline: the centre's speed plus the spin times the reach; same for the
        // acceleration. Largest dt with v dt + a dt^2 / 2 <= h.
        const double reach = body.outline().reach();
        const double v = body.state().velocity.norm() + std::abs(body.state().angular_velocity) * reach;
        const double a = f.acceleration.norm() + std::abs(f.angular_acceleration) * reach;
        const double step = a > 0.0 ? 2.0 * h / (v + std::sqrt(v * v + 2.0 * a * h)) : (v > 0.0 ? h / v : dt);
        dt = std::min(dt, step);
    }
    return dt;
}

void FreeBodies::predict(double t, double dt, const Velocity& vel) {
    for (Free& f : free_) {
        Body& body = ibm_.body(f.index);
        if (!momentum_known_) f.momentum = enclosed_momentum(ibm_.grid(), vel, body);
        f.start = body.state();
        f.contact_at_start = f.contact;
        BodyState s = f.start;
        s.acceleration = f.acceleration;
        s.angular_acceleration = f.angular_acceleration;
        ContactState c = f.contact;
        move_with_contacts(s, c, t, dt, body.name(), body.outline(), f.inertia, obstacles_, config_.contact);
        body.set_state(s);
    }
    momentum_known_ = true;
}

void FreeBodies::correct(double t, double dt, const Velocity& vel) {
    events_.clear();
    const Grid& grid = ibm_.grid();
    const double rho = config_.density, depth = config_.depth, cv = config_.ibm.virtual_mass;
    const Vec2 g(config_.gravity[0], config_.gravity[1]);
    for (Free& f : free_) {
        Body& body = ibm_.body(f.index);
        const BodyForcing& forcing = ibm_.forcing().forcing()[f.index];
        const EnclosedMomentum P = enclosed_momentum(grid, vel, body);  // at the predicted place
        FreeBodyForces& out = forces_[f.index];
        out.hydrodynamic.force = rho * depth * (-forcing.momentum_rate + (P.linear - f.momentum.linear) / dt);
        out.hydrodynamic.torque = rho * depth * (-forcing.torque_rate + (P.angular - f.momentum.angular) / dt);
        out.gravity.force = f.inertia.mass * g;
        out.buoyancy.force = -f.fluid_mass * g;

        const Vec2 force = out.hydrodynamic.force + out.gravity.force + out.buoyancy.force;
        BodyState s = f.start;
        s.acceleration = (force + cv * f.fluid_mass * f.acceleration) / (f.inertia.mass + cv * f.fluid_mass);
        s.acceleration = s.acceleration.cwiseProduct(f.inertia.free_translation());
        s.angular_acceleration = f.inertia.free(Dof::rotation)
                                     ? (out.hydrodynamic.torque + cv * f.fluid_inertia * f.angular_acceleration) /
                                           (f.inertia.inertia + cv * f.fluid_inertia)
                                     : 0.0;
        f.acceleration = s.acceleration;
        f.angular_acceleration = s.angular_acceleration;
        f.contact = f.contact_at_start;
        // Contact force over the step: what the impacts (and a resting reaction) changed against free flight.
        const BodyState free_flight = drift(s, dt);
        const auto ev = move_with_contacts(s, f.contact, t, dt, body.name(), body.outline(), f.inertia, obstacles_,
                                           config_.contact);
        out.contact.force = f.inertia.mass * (s.velocity - free_flight.velocity) / dt;
        out.contact.torque = f.inertia.inertia * (s.angular_velocity - free_flight.angular_velocity) / dt;
        events_.insert(events_.end(), ev.begin(), ev.end());
        body.set_state(s);
        f.momentum = enclosed_momentum(grid, vel, body);  // P^{n+1} at the body's final place
    }
}

void FreeBodies::report(std::vector<BodyForces>& forces) const {
    for (const Free& f : free_) {
        const FreeBodyForces& in = forces_[f.index];
        BodyForces& out = forces[f.index];
        out.forcing = in.hydrodynamic.force;
        out.forcing_torque = in.hydrodynamic.torque;
        out.gravity = in.gravity.force;
        out.buoyancy = in.buoyancy.force;
        out.contact = in.contact.force;
        out.contact_torque = in.contact.torque;
    }
}

namespace {

// The layout of a free body's checkpoint array; one list so that saving and restoring cannot disagree.
template <class Visit>
void each_value(Visit&& v, BodyState& s, Vec2& acceleration, double& angular_acceleration, ContactState& c,
                EnclosedMomentum& P, double& momentum_known) {
    for (double* x : {&s.centre.x(), &s.centre.y(), &s.angle, &s.velocity.x(), &s.velocity.y(),
                      &s.angular_velocity, &s.acceleration.x(), &s.acceleration.y(), &s.angular_acceleration,
                      &acceleration.x(), &acceleration.y(), &angular_acceleration, &P.linear.x(), &P.linear.y(),
                      &P.angular, &c.pressed_since, &c.touch.time, &c.touch.point.x(), &c.touch.point.y(),
                      &c.touch.centre.x(), &c.touch.centre.y(), &c.touch.velocity_before.x(),
                      &c.touch.velocity_before.y(), &c.touch.angular_velocity_before, &momentum_known})
        v(*x);
    double resting = c.resting_on, pressed = c.pressed_on;
    v(resting);
    v(pressed);
    c.resting_on = static_cast<int>(resting);
    c.pressed_on = static_cast<int>(pressed);
}

}  // namespace

std::vector<CheckpointArray> FreeBodies::checkpoint_arrays() const {
    std::vector<CheckpointArray> out;
    for (const Free& f : free_) {
        Free copy = f;
        BodyState s = ibm_.bodies()[f.index].state();
        double known = momentum_known_ ? 1.0 : 0.0;
        CheckpointArray a{"free_body_" + ibm_.bodies()[f.index].name(), {}};
        each_value([&](double& x) { a.values.push_back(x); }, s, copy.acceleration, copy.angular_acceleration,
                   copy.contact, copy.momentum, known);
        out.push_back(std::move(a));
    }
    return out;
}

void FreeBodies::restore(const std::filesystem::path& checkpoint) {
    for (Free& f : free_) {
        Body& body = ibm_.body(f.index);
        const auto values = read_checkpoint_array(checkpoint, "free_body_" + body.name());
        if (!values)
            throw std::runtime_error("checkpoint '" + checkpoint.string() + "' has no state for the free body `" +
                                     body.name() + "` (written by a run without it?)");
        BodyState s = body.state();
        double known = 0.0;
        std::size_t k = 0, count = 0;
        each_value([&](double&) { ++count; }, s, f.acceleration, f.angular_acceleration, f.contact, f.momentum, known);
        if (values->size() != count)
            throw std::runtime_error("checkpoint '" + checkpoint.string() + "': the state of free body `" +
                                     body.name() + "` has " + std::to_string(values->size()) + " values, expected " +
                                     std::to_string(count));
        each_value([&](double& x) { x = (*values)[k++]; }, s, f.acceleration, f.angular_acceleration, f.contact,
                   f.momentum, known);
        f.contact.touch.body = body.name();
        if (f.contact.pressed_on >= 0) f.contact.touch.obstacle = obstacles_[f.contact.pressed_on].name;
        momentum_known_ = known != 0.0;
        body.set_state(s);
    }
}

}  // namespace chute
