#include "impacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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
    if (vt != 0.0) at -= std::copysign(friction, vt);
    else at = std::abs(at) <= friction ? 0.0 : at - std::copysign(friction, at);
    s.velocity = vt * t;
    s.acceleration = at * t;
    s.angular_velocity = 0.0;
    s.angular_acceleration = 0.0;
    s.velocity = s.velocity.cwiseProduct(Vec2(m.free(Dof::x), m.free(Dof::y)));
    s.acceleration = s.acceleration.cwiseProduct(Vec2(m.free(Dof::x), m.free(Dof::y)));
    return true;
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
    while (done < dt) {
        const double remaining = dt - done;
        if (contact.resting_on >= 0 && !hold_on(s, obstacles[contact.resting_on], m, config))
            contact.resting_on = -1;
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
