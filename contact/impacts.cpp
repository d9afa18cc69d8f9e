#include "impacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "run_failure.hpp"

namespace chute {

namespace {

double normal_speed(const BodyState& s, const Vec2& X, const Vec2& n) {
    return (s.velocity + s.angular_velocity * perp(X - s.centre)).dot(n);
}

// While resting on an obstacle: no normal velocity or spin, the normal acceleration into the obstacle taken
// by its reaction, and Coulomb friction against the sliding. Returns false when the body lifts off.
bool hold_on(BodyState& s, const Obstacle& ob, const RigidInertia& m, const ContactConfig& c) {
    const Vec2 n = ob.normal, t = -perp(n);
    const double an = s.acceleration.dot(n);
    if (an > 0.0) return false;
    double vt = s.velocity.dot(t), at = s.acceleration.dot(t);
    const double friction = c.friction * -an;
    if (vt != 0.0)
        at -= std::copysign(friction, vt);
    else
        at = std::abs(at) <= friction ? 0.0 : at - std::copysign(friction, at);
    s.velocity = vt * t;
    s.acceleration = at * t;
    s.angular_velocity = 0.0;
    s.angular_acceleration = 0.0;
    s.velocity = s.velocity.cwiseProduct(m.free_translation());
    s.acceleration = s.acceleration.cwiseProduct(m.free_translation());
    return true;
}

// The contact point's effective mass along n: 1 / (n . K n), K = diag(1/m) + perp(r) perp(r)^T / I.
double effective_mass(const BodyState& s, const Vec2& X, const Vec2& n, const RigidInertia& m) {
    const Vec2 p = perp(X - s.centre);
    const double inverse = n.cwiseProduct(m.inverse_mass()).dot(n) + m.inverse_inertia() * p.dot(n) * p.dot(n);
    return inverse > 0.0 ? 1.0 / inverse : 0.0;
}

// Accelerations of a body pressed into an obstacle: the held ones plus the spring-dashpot and friction.
void soft_accelerations(const BodyState& s, const Vec2& held, double held_alpha, const Outline& outline,
                        const Obstacle& ob, const RigidInertia& m, const ContactConfig& c, Vec2& a, double& alpha) {
    a = held;
    alpha = held_alpha;
    const Gap g = gap(outline, s, ob);
    if (g.distance >= 0.0) return;
    const Vec2 n = ob.normal, t = -perp(n);
    const Vec2 V = s.velocity + s.angular_velocity * perp(g.point - s.centre);
    const double m_eff = effective_mass(s, g.point, n, m), log_e = std::log(std::max(c.normal_restitution, 1e-6));
    const double k = m_eff * (std::numbers::pi * std::numbers::pi + log_e * log_e) / (c.duration * c.duration);
    const double damping = -2.0 * m_eff * log_e / c.duration;
    // The linear model acts until the overlap closes (its dashpot may pull slightly at the end): that is the
    // model whose restitution is exp(-pi xi / sqrt(1 - xi^2)); clipping it at zero force rebounds ~1 % faster.
    const double fn = -k * g.distance - damping * V.dot(n);
    Vec2 F = fn * n;
    const double vt = V.dot(t);
    if (c.friction > 0.0 && fn > 0.0 && std::abs(vt) > 1e-9) F -= std::copysign(c.friction * fn, vt) * t;
    a += F.cwiseProduct(m.inverse_mass());
    alpha += cross(g.point - s.centre, F) * m.inverse_inertia();
}

// Moves a pressed body by dt with the soft law (midpoint sub-steps); stops early if it leaves the obstacle.
// Returns the time taken.
double press(BodyState& s, double dt, const Outline& outline, const Obstacle& ob, const RigidInertia& m,
             const ContactConfig& c) {
    const Vec2 held = s.acceleration;
    const double held_alpha = s.angular_acceleration;
    const int n = std::max(1, static_cast<int>(std::ceil(dt / (c.duration / 100.0))));
    const double h = dt / n;
    auto step = [&](const BodyState& from, const BodyState& rate_at, double tau) {
        Vec2 a;
        double alpha;
        soft_accelerations(rate_at, held, held_alpha, outline, ob, m, c, a, alpha);
        BodyState r = from;
        r.centre += rate_at.velocity * tau;
        r.angle += rate_at.angular_velocity * tau;
        r.velocity += a * tau;
        r.angular_velocity += alpha * tau;
        return r;
    };
    for (int k = 0; k < n; ++k) {
        const BodyState mid = step(s, s, 0.5 * h);
        s = step(s, mid, h);
        const Gap g = gap(outline, s, ob);
        if (g.distance > 0.0 && normal_speed(s, g.point, ob.normal) > 0.0) {
            s.acceleration = held;
            s.angular_acceleration = held_alpha;
            return (k + 1) * h;
        }
    }
    s.acceleration = held;
    s.angular_acceleration = held_alpha;
    return dt;
}

std::string stuck_in_contact(const std::string& body, double t, double done, double dt, int passes,
                             const ContactState& contact, const std::vector<Obstacle>& obstacles) {
    const int on = contact.pressed_on >= 0 ? contact.pressed_on : contact.resting_on;
    std::ostringstream m;
    m << "contact: body '" << body << "' went through " << passes << " contact events in one step of " << dt
      << " s without reaching its end (stuck at t = " << t + done;
    if (on >= 0) m << ", on '" << obstacles[on].name << "'";
    m << "); check contact.law, contact.duration, contact.rest_speed and contact.distance";
    return m.str();
}

}  // namespace

std::optional<double> time_of_impact(const Outline& outline, const BodyState& s, const Obstacle& ob, double T) {
    auto distance = [&](double tau) { return gap(outline, drift(s, tau), ob).distance; };
    auto approaching = [&](double tau) {
        const BodyState d = drift(s, tau);
        return normal_speed(d, gap(outline, d, ob).point, ob.normal) < 0.0;
    };
    if (distance(0.0) <= 0.0 && approaching(0.0)) return 0.0;
    // Bracket the first crossing by sampling (finer when the body turns, since the nearest corner may change),
    // then bisect to round-off. A start at gap <= 0 moving away (just after a rebound) counts as outside.
    const double turn = std::abs(s.angular_velocity) * T + 0.5 * std::abs(s.angular_acceleration) * T * T;
    const int samples = std::clamp(static_cast<int>(std::ceil(turn / 0.01)), 64, 4096);
    double left = 0.0;
    for (int k = 1; k <= samples; ++k) {
        const double right = T * k / samples;
        if (distance(right) > 0.0) {
            left = right;
            continue;
        }
        double a = left, b = right;
        for (int it = 0; it < 200 && b - a > 4 * std::numeric_limits<double>::epsilon() * T; ++it) {
            const double mid = 0.5 * (a + b);
            (distance(mid) > 0.0 ? a : b) = mid;
        }
        if (approaching(b)) return b;
        left = right;
    }
    return std::nullopt;
}

std::vector<ContactEvent> move_with_contacts(BodyState& s, ContactState& contact, double t, double dt,
                                             const std::string& body_name, const Outline& outline,
                                             const RigidInertia& m, const std::vector<Obstacle>& obstacles,
                                             const ContactConfig& config) {
    std::vector<ContactEvent> events;
    double done = 0.0;
    // Each pass ends the step or reaches an event (an impact, a slide stopped by friction, a soft contact
    // opened or closed); impulse laws settle a body after 1000 impacts in a step (below), so a step that
    // needs more passes than this is caught in a loop of events that do not advance time.
    constexpr int kMaxPasses = 10000;
    int passes = 0;
    while (done < dt) {
        if (++passes > kMaxPasses)
            throw RunFailure(stuck_in_contact(body_name, t, done, dt, kMaxPasses, contact, obstacles));
        const double remaining = dt - done;
        if (contact.pressed_on >= 0) {  // soft law: press on until the body leaves or the step ends
            const Obstacle& ob = obstacles[contact.pressed_on];
            const double used = press(s, remaining, outline, ob, m, config);
            done = used >= remaining ? dt : done + used;
            const bool left = used < remaining || gap(outline, s, ob).distance > 0.0;
            const bool rests = !left && t + done - contact.pressed_since > 10.0 * config.duration;
            if (left || rests) {
                ContactEvent e = contact.touch;
                e.velocity_after = s.velocity;
                e.angular_velocity_after = s.angular_velocity;
                const Vec2 n = ob.normal;
                const Vec2 before = e.velocity_before + e.angular_velocity_before * perp(e.point - e.centre);
                const Gap g = gap(outline, s, ob);
                const Vec2 after = s.velocity + s.angular_velocity * perp(g.point - s.centre);
                set_effective_restitution(e, before, after, n);
                e.rests = rests || after.dot(n) < config.rest_speed;
                if (e.rests) {
                    // Settle it on the surface and hold it there as the impulse laws do.
                    s.centre += -g.distance * n;
                    contact.resting_on = contact.pressed_on;
                }
                contact.pressed_on = -1;
                events.push_back(e);
            }
            continue;
        }
        if (contact.resting_on >= 0 && !hold_on(s, obstacles[contact.resting_on], m, config)) contact.resting_on = -1;
        // Sliding that friction stops inside the step: stop there, then hold.
        double until = remaining;
        if (contact.resting_on >= 0 && s.velocity.dot(s.acceleration) < 0.0)
            until = std::min(until, s.velocity.norm() / s.acceleration.norm());
        int hit = -1;
        for (std::size_t k = 0; k < obstacles.size(); ++k) {
            if (static_cast<int>(k) == contact.resting_on) continue;
            if (const auto tau = time_of_impact(outline, s, obstacles[k], until); tau && *tau < until) {
                until = *tau;
                hit = static_cast<int>(k);
            }
        }
        s = drift(s, until);
        done = until == remaining ? dt : done + until;
        if (hit < 0) {
            if (contact.resting_on >= 0 && done < dt) s.velocity.setZero();  // friction stopped the slide
            continue;
        }
        const Obstacle& ob = obstacles[hit];
        if (config.law == ReboundLaw::soft) {  // open the event; the pressing happens on the next pass
            ContactEvent& e = contact.touch;
            e = ContactEvent{};
            e.time = t + done;
            e.body = body_name;
            e.obstacle = ob.name;
            e.point = gap(outline, s, ob).point;
            e.centre = s.centre;
            e.velocity_before = s.velocity;
            e.angular_velocity_before = s.angular_velocity;
            contact.pressed_on = hit;
            contact.pressed_since = t + done;
            continue;
        }
        ContactEvent e = rebound(s, gap(outline, s, ob).point, ob.normal, m, config);
        e.time = t + done;
        e.body = body_name;
        e.obstacle = ob.name;
        if (normal_speed(s, e.point, ob.normal) < config.rest_speed || events.size() >= 1000) {
            e.rests = true;
            contact.resting_on = hit;
        }
        events.push_back(e);
    }
    return events;
}

}  // namespace chute
