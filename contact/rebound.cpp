#include "rebound.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace chute {

namespace {

Vec2 point_velocity(const BodyState& s, const Vec2& X) { return s.velocity + s.angular_velocity * perp(X - s.centre); }

// -V_n'/V_n and V_t'/V_t of the contact point's velocity before and after (NaN when V_t = 0: under a millionth of
// V_n, a body that falls straight carries only round-off across, and a ratio of round-off means nothing).
std::pair<double, double> restitution(const Vec2& before, const Vec2& after, const Vec2& n) {
    const Vec2 t = -perp(n);
    const double Vn = before.dot(n), Vt = before.dot(t);
    return {-after.dot(n) / Vn,
            std::abs(Vt) > 1e-6 * std::abs(Vn) ? after.dot(t) / Vt : std::numeric_limits<double>::quiet_NaN()};
}

}  // namespace

void set_effective_restitution(ContactEvent& e, const Vec2& before, const Vec2& after, const Vec2& n) {
    e.normal = n;
    std::tie(e.normal_restitution, e.tangential_restitution) = restitution(before, after, n);
    e.velocity_wet = e.velocity_after;
    e.angular_velocity_wet = e.angular_velocity_after;
    e.wet_normal_restitution = e.normal_restitution;
    e.wet_tangential_restitution = e.tangential_restitution;
}

void set_wet_rebound(ContactEvent& e, const Vec2& velocity, double angular_velocity) {
    const Vec2 arm = perp(e.point - e.centre);
    e.velocity_wet = velocity;
    e.angular_velocity_wet = angular_velocity;
    std::tie(e.wet_normal_restitution, e.wet_tangential_restitution) =
        restitution(e.velocity_before + e.angular_velocity_before * arm, velocity + angular_velocity * arm, e.normal);
}

ContactEvent rebound(BodyState& s, const Vec2& X, const Vec2& n, const RigidInertia& m, const ContactConfig& c) {
    ContactEvent e;
    e.point = X;
    e.centre = s.centre;
    e.velocity_before = s.velocity;
    e.angular_velocity_before = s.angular_velocity;
    const Vec2 t = -perp(n);  // tangent; any orientation works, the law treats both alike
    const Vec2 V = point_velocity(s, X);
    const double Vn = V.dot(n), Vt = V.dot(t);

    if (c.law == ReboundLaw::lumped) {
        const double vn = s.velocity.dot(n), vt = s.velocity.dot(t);
        const Vec2 after = -c.normal_restitution * vn * n + c.tangential_restitution * vt * t;
        s.velocity = after.cwiseProduct(m.free_translation());  // locked translations stay locked
    } else {
        const Vec2 target = -c.normal_restitution * Vn * n + c.tangential_restitution * Vt * t;
        const Vec2 p = perp(X - s.centre);
        Eigen::Matrix2d K = m.inverse_mass().asDiagonal();
        K += m.inverse_inertia() * p * p.transpose();
        // A locked direction leaves K singular there: the least-squares impulse is the one that can act.
        const Vec2 J = K.completeOrthogonalDecomposition().solve(target - V);
        s.velocity += J.cwiseProduct(m.inverse_mass());
        s.angular_velocity += cross(X - s.centre, J) * m.inverse_inertia();
    }

    e.velocity_after = s.velocity;
    e.angular_velocity_after = s.angular_velocity;
    set_effective_restitution(e, V, point_velocity(s, X), n);
    return e;
}

}  // namespace chute
