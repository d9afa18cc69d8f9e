#include "free_bodies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

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
        dt = std::min(dt,
                      longest_step(body.state().velocity, body.state().angular_velocity, f.acceleration,
                                   f.angular_acceleration, body.outline().reach(), cfl * carrier_.cell_size(f.index)));
    }
    return dt;
}

namespace {
double contraction(double change, double previous) { return std::min(change / previous, 0.99); }

// (m + M) x = b on the free degrees of freedom of an exactly coupled body (x, y, rotation; m = diag(m, m, I), M its
// added mass); a locked one stays 0.
Eigen::Vector3d solve_with_added_mass(const RigidInertia& inertia, const Eigen::Matrix3d& added, Eigen::Vector3d b) {
    Eigen::Matrix3d A = Eigen::Vector3d(inertia.mass, inertia.mass, inertia.inertia).asDiagonal();
    A += added;
    const std::array<Dof, 3> dofs{Dof::x, Dof::y, Dof::rotation};
    for (int k = 0; k < 3; ++k)
        if (!inertia.free(dofs[k])) {
            A.row(k).setZero();
            A(k, k) = 1.0;
            b[k] = 0.0;
        }
    return A.partialPivLu().solve(b);
}
Eigen::Vector3d motion(const Vec2& linear, double angular) { return {linear.x(), linear.y(), angular}; }
}  // namespace

double remaining_change(double change, double previous) {
    if (previous <= 0.0) return change;
    const double r = contraction(change, previous);
    return change * std::max(1.0, r / (1.0 - r));
}

double passes_to_tolerance(double change, double previous, double tolerance) {
    const double remaining = remaining_change(change, previous);
    if (previous <= 0.0 || remaining <= tolerance) return 0.0;
    // remaining_change after n more passes at the ratio r is remaining r^n.
    return std::ceil(std::log(tolerance / remaining) / std::log(contraction(change, previous)));
}

void FreeBodies::predict(double t, double dt) {
    impulsive_ = false;
    coupling_change_ = -1.0;  // no correct() yet in this step
    for (Free& f : free_) {
        Body& body = bodies_[f.index];
        f.start = body.state();
        f.contact_at_start = f.contact;
        f.held_acceleration = f.acceleration;
        f.held_angular_acceleration = f.angular_acceleration;
        BodyState s = f.start;
        s.acceleration = f.acceleration;
        s.angular_acceleration = f.angular_acceleration;
        ContactState c = f.contact;
        const auto events = move_with_contacts(s, c, t, dt, body.name(), body.outline(), f.inertia, settings_.obstacles,
                                               settings_.contact);
        f.impact = settings_.contact.law != ReboundLaw::soft && !events.empty();
        impulsive_ = impulsive_ || f.impact || !f.started;
        f.rebound_velocity = s.velocity;  // the law's, as predicted: the first pass forces the water to it
        f.rebound_angular_velocity = s.angular_velocity;
        f.started = true;
        body.set_state(s);
    }
}

void FreeBodies::correct(double t, double dt, const Velocity& vel) {
    events_.clear();
    previous_change_ = coupling_change_;
    coupling_change_ = 0.0;
    const double cv = settings_.virtual_mass;
    const Vec2 g = settings_.gravity;
    for (Free& f : free_) {
        Body& body = bodies_[f.index];
        const Wrench hydrodynamic = carrier_.hydrodynamic_wrench(f.index, vel, dt);  // at the predicted place
        const std::optional<Eigen::Matrix3d> exact = carrier_.added_mass(f.index);
        // An exactly coupled body (body-fitted) at an impact: the rebound law sets its velocity; with `obstacle` the
        // obstacle takes the water's share of the impulse, with `body` block and water share their momentum at once
        // (below); body_moved() brings the water to the body's final velocity exactly.
        BodyLoads& out = loads_[f.index];
        const BodyLoads last_pass = out;
        out = BodyLoads{};
        out.gravity = f.inertia.mass * g;
        out.buoyancy = -f.fluid_mass * g;
        const Vec2 free_translation = f.inertia.free_translation();
        const bool turns = f.inertia.free(Dof::rotation);
        const double reach = body.outline().reach();

        BodyState s = f.start;
        double change = 0.0;  // of this pass against the last, in units of the net weight's acceleration
        if (f.impact) {
            // The held accelerations stand for the regular forces (m a* = F_regular + W); the rest of the wrench
            // over the step is the water's impulse at the impact.
            s.acceleration = f.held_acceleration;
            s.angular_acceleration = f.held_angular_acceleration;
            const Vec2 regular = f.inertia.mass * f.held_acceleration - (out.gravity + out.buoyancy);
            out.water_impulse = ((hydrodynamic.force - regular) * dt).cwiseProduct(free_translation);
            out.water_angular_impulse =
                turns ? (hydrodynamic.torque - f.inertia.inertia * f.held_angular_acceleration) * dt : 0.0;
            const double scale = std::max(out.water_impulse.norm(), f.inertia.mass * f.weight_acceleration * dt);
            change = ((out.water_impulse - last_pass.water_impulse).norm() +
                      std::abs(out.water_angular_impulse - last_pass.water_angular_impulse) / reach) /
                     scale;
        } else if (exact) {
            // F(a) = F(a*) - M (a - a*) exactly, so m a = F(a) + W is (m + M) a = F(a*) + W + M a*, solved on the
            // free degrees of freedom (a locked one stays 0); the carrier then brings the flow to it (body_moved).
            const Eigen::Vector3d rhs = motion(hydrodynamic.force + out.gravity + out.buoyancy, hydrodynamic.torque) +
                                        *exact * motion(f.held_acceleration, f.held_angular_acceleration);
            const Eigen::Vector3d a = solve_with_added_mass(f.inertia, *exact, rhs);
            s.acceleration = Vec2(a[0], a[1]);
            s.angular_acceleration = a[2];
            f.acceleration = s.acceleration;
            f.angular_acceleration = s.angular_acceleration;
        } else {
            const Vec2 force = hydrodynamic.force + out.gravity + out.buoyancy;
            s.acceleration = (force + cv * f.fluid_mass * f.acceleration) / (f.inertia.mass + cv * f.fluid_mass);
            s.acceleration = s.acceleration.cwiseProduct(free_translation);
            s.angular_acceleration = turns ? (hydrodynamic.torque + cv * f.fluid_inertia * f.angular_acceleration) /
                                                 (f.inertia.inertia + cv * f.fluid_inertia)
                                           : 0.0;
            if (f.weight_acceleration > 0.0)
                change = ((s.acceleration - f.acceleration).norm() +
                          std::abs(s.angular_acceleration - f.angular_acceleration) * reach) /
                         f.weight_acceleration;
            f.acceleration = s.acceleration;
            f.angular_acceleration = s.angular_acceleration;
        }
        f.contact = f.contact_at_start;
        // Contact over the step: what the impacts (and a resting reaction) changed against free flight.
        const BodyState free_flight = drift(s, dt);
        auto ev = move_with_contacts(s, f.contact, t, dt, body.name(), body.outline(), f.inertia, settings_.obstacles,
                                     settings_.contact);
        const Vec2 contact = f.inertia.mass * (s.velocity - free_flight.velocity);
        const double contact_angular = f.inertia.inertia * (s.angular_velocity - free_flight.angular_velocity);
        if (f.impact && settings_.contact.water_impulse == WaterImpulse::obstacle) {
            // The obstacle stops the water's share too: J_contact = m dv - J_water.
            out.contact_impulse = contact - out.water_impulse;
            out.contact_angular_impulse = contact_angular - out.water_angular_impulse;
        } else if (f.impact && !ev.empty() && !ev.back().rests) {
            out.contact_impulse = contact;
            out.contact_angular_impulse = contact_angular;
            Vec2 v;
            double w = s.angular_velocity;
            if (exact) {
                // Coupled exactly: the law reverses the block alone, then block and water share their momentum at
                // once, (m + M) V = m V_law + M v_free (M the added mass, v_free the velocity the water moved with:
                // the block's without the impact), on the free translations; the water's impulse is m (V - V_law).
                const Eigen::Vector3d own = motion(f.inertia.mass * s.velocity, f.inertia.inertia * s.angular_velocity);
                const Eigen::Vector3d shared = solve_with_added_mass(
                    f.inertia, *exact, own + *exact * motion(free_flight.velocity, free_flight.angular_velocity));
                v = Vec2(shared[0], shared[1]);
                w = shared[2];
                out.water_impulse = f.inertia.mass * (v - s.velocity);
                out.water_angular_impulse = f.inertia.inertia * (w - s.angular_velocity);
                change = 0.0;  // exact: the next pass finds the same V
            } else {
                // The water takes its momentum back from the body at the impact: m (V - V_law) = J_w(V), relaxed
                // with the virtual mass (J_w of this pass is the water's answer to the last pass's V).
                const double c = cv * f.fluid_mass, ci = cv * f.fluid_inertia;
                v = (f.inertia.mass * s.velocity + out.water_impulse + c * f.rebound_velocity) / (f.inertia.mass + c);
                if (turns)
                    w = (f.inertia.inertia * s.angular_velocity + out.water_angular_impulse +
                         ci * f.rebound_angular_velocity) /
                        (f.inertia.inertia + ci);
            }
            const double scale = std::max(out.water_impulse.norm() / f.inertia.mass, f.weight_acceleration * dt);
            change = std::max(
                change, ((v - f.rebound_velocity).norm() + std::abs(w - f.rebound_angular_velocity) * reach) / scale);
            f.rebound_velocity = v;
            f.rebound_angular_velocity = w;
            // Water that would push the body back into the obstacle presses it on it: the obstacle holds that.
            const Vec2 n = ev.back().normal;
            if (v.dot(n) < 0.0) {
                out.contact_impulse -= f.inertia.mass * v.dot(n) * n;
                v -= v.dot(n) * n;
            }
            // From the (last) impact on, the body moves with the water's impulse added.
            ContactEvent& last = ev.back();
            const double after = t + dt - last.time;
            set_wet_rebound(last, last.velocity_after + (v - s.velocity),
                            last.angular_velocity_after + (w - s.angular_velocity));
            s.centre += (v - s.velocity) * after;
            s.angle += (w - s.angular_velocity) * after;
            s.velocity = v;
            s.angular_velocity = w;
        } else {
            out.contact = contact / dt;
            out.contact_torque = contact_angular / dt;
        }
        coupling_change_ = std::max(coupling_change_, change);
        events_.insert(events_.end(), ev.begin(), ev.end());
        body.set_state(s);
        if (exact) carrier_.body_moved(f.index, dt);
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
