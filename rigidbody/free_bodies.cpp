#include "free_bodies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace chute {

FreeBodies::FreeBodies(const FreeBodySettings& settings, std::vector<Body>& bodies, Carrier& carrier)
    : settings_(settings), bodies_(bodies), carrier_(carrier), loads_(bodies.size()) {
    const Vec2 g = settings_.gravity;
    const double rho = settings_.fluid_density, depth = settings_.depth;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const Body& body = bodies_[b];
        if (!body.free()) continue;
        Free f;
        f.index = b;
        f.inertia = rigid_inertia(body.outline(), body.config().density, depth, body.config().motion.locked);
        f.fluid_mass = rho * body.area() * depth;
        f.fluid_inertia = rho * body.polar_moment() * depth;
        f.start = body.state();
        // A neutrally buoyant body: the scale is g itself.
        f.weight_acceleration =
            std::max(std::abs(f.inertia.mass - f.fluid_mass), 1e-3 * f.inertia.mass) * g.norm() / f.inertia.mass;
        // First prediction: gravity and buoyancy against the body's and the virtual mass.
        const double cv = settings_.virtual_mass;
        f.acceleration = (f.inertia.mass - f.fluid_mass) * g / (f.inertia.mass + cv * f.fluid_mass);
        f.acceleration = f.acceleration.cwiseProduct(f.inertia.free_translation());
        for (const Obstacle& ob : settings_.obstacles)
            if (gap(body.outline(), body.state(), ob).distance < 0.0)
                throw std::invalid_argument("bodies." + body.name() + ": the body starts inside the obstacle `" +
                                            ob.name + "` (or within contact.distance of it)");
        free_.push_back(f);
    }
}

double FreeBodies::max_dt(double cfl) const {
    double dt = std::numeric_limits<double>::infinity();
    for (const Free& f : free_) {
        const Body& body = bodies_[f.index];
        const double h = cfl * carrier_.cell_size(f.index);
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

void FreeBodies::predict(double t, double dt) {
    first_step_ = false;
    for (Free& f : free_) {
        Body& body = bodies_[f.index];
        f.start = body.state();
        f.contact_at_start = f.contact;
        BodyState s = f.start;
        s.acceleration = f.acceleration;
        s.angular_acceleration = f.angular_acceleration;
        ContactState c = f.contact;
        move_with_contacts(s, c, t, dt, body.name(), body.outline(), f.inertia, settings_.obstacles, settings_.contact);
        first_step_ = first_step_ || !f.started;
        f.started = true;
        body.set_state(s);
    }
}

void FreeBodies::correct(double t, double dt, const Velocity& vel) {
    events_.clear();
    coupling_change_ = 0.0;
    const double cv = settings_.virtual_mass;
    const Vec2 g = settings_.gravity;
    for (Free& f : free_) {
        Body& body = bodies_[f.index];
        const Wrench hydrodynamic = carrier_.hydrodynamic_wrench(f.index, vel, dt);  // at the predicted place
        BodyLoads& out = loads_[f.index];
        out.gravity = f.inertia.mass * g;
        out.buoyancy = -f.fluid_mass * g;

        const Vec2 force = hydrodynamic.force + out.gravity + out.buoyancy;
        BodyState s = f.start;
        s.acceleration = (force + cv * f.fluid_mass * f.acceleration) / (f.inertia.mass + cv * f.fluid_mass);
        s.acceleration = s.acceleration.cwiseProduct(f.inertia.free_translation());
        s.angular_acceleration = f.inertia.free(Dof::rotation)
                                     ? (hydrodynamic.torque + cv * f.fluid_inertia * f.angular_acceleration) /
                                           (f.inertia.inertia + cv * f.fluid_inertia)
                                     : 0.0;
        if (f.weight_acceleration > 0.0) {
            const double change = (s.acceleration - f.acceleration).norm() +
                                  std::abs(s.angular_acceleration - f.angular_acceleration) * body.outline().reach();
            coupling_change_ = std::max(coupling_change_, change / f.weight_acceleration);
        }
        f.acceleration = s.acceleration;
        f.angular_acceleration = s.angular_acceleration;
        f.contact = f.contact_at_start;
        // Contact force over the step: what the impacts (and a resting reaction) changed against free flight.
        const BodyState free_flight = drift(s, dt);
        const auto ev = move_with_contacts(s, f.contact, t, dt, body.name(), body.outline(), f.inertia,
                                           settings_.obstacles, settings_.contact);
        out.contact = f.inertia.mass * (s.velocity - free_flight.velocity) / dt;
        out.contact_torque = f.inertia.inertia * (s.angular_velocity - free_flight.angular_velocity) / dt;
        events_.insert(events_.end(), ev.begin(), ev.end());
        body.set_state(s);
    }
}

namespace {

// The layout of a free body's checkpoint array; one list so that saving and restoring cannot disagree.
// Checkpoints written before the carrier seam also held the enclosed fluid momentum P^n (3 values after the
// held accelerations) and a flag (after the contact state); the immersed boundary now measures P^n from the
// restored velocity, to the same bits. `legacy` (null: today's layout) receives those 4 values when reading one.
template <class Visit>
void each_value(Visit&& v, BodyState& s, Vec2& acceleration, double& angular_acceleration, ContactState& c,
                double* legacy = nullptr) {
    for (double* x : {&s.centre.x(), &s.centre.y(), &s.angle, &s.velocity.x(), &s.velocity.y(), &s.angular_velocity,
                      &s.acceleration.x(), &s.acceleration.y(), &s.angular_acceleration, &acceleration.x(),
                      &acceleration.y(), &angular_acceleration})
        v(*x);
    if (legacy)
        for (int k = 0; k < 3; ++k) v(legacy[k]);
    for (double* x : {&c.pressed_since, &c.touch.time, &c.touch.point.x(), &c.touch.point.y(), &c.touch.centre.x(),
                      &c.touch.centre.y(), &c.touch.velocity_before.x(), &c.touch.velocity_before.y(),
                      &c.touch.angular_velocity_before})
        v(*x);
    if (legacy) v(legacy[3]);
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
        BodyState s = bodies_[f.index].state();
        CheckpointArray a{"free_body_" + bodies_[f.index].name(), {}};
        each_value([&](double& x) { a.values.push_back(x); }, s, copy.acceleration, copy.angular_acceleration,
                   copy.contact);
        out.push_back(std::move(a));
    }
    return out;
}

void FreeBodies::restore(const std::filesystem::path& checkpoint) {
    for (Free& f : free_) {
        Body& body = bodies_[f.index];
        const auto values = read_checkpoint_array(checkpoint, "free_body_" + body.name());
        if (!values)
            throw std::runtime_error("checkpoint '" + checkpoint.string() + "' has no state for the free body `" +
                                     body.name() + "` (written by a run without it?)");
        BodyState s = body.state();
        double legacy[4];
        std::size_t k = 0, count = 0;
        each_value([&](double&) { ++count; }, s, f.acceleration, f.angular_acceleration, f.contact);
        const bool old_layout = values->size() == count + 4;
        if (values->size() != count && !old_layout)
            throw std::runtime_error("checkpoint '" + checkpoint.string() + "': the state of free body `" +
                                     body.name() + "` has " + std::to_string(values->size()) + " values, expected " +
                                     std::to_string(count));
        each_value([&](double& x) { x = (*values)[k++]; }, s, f.acceleration, f.angular_acceleration, f.contact,
                   old_layout ? legacy : nullptr);
        f.contact.touch.body = body.name();
        f.started = true;
        if (f.contact.pressed_on >= 0) f.contact.touch.obstacle = settings_.obstacles[f.contact.pressed_on].name;
        body.set_state(s);
    }
}

}  // namespace chute
