#include "rebound.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace chute {

namespace {

Vec2 point_velocity(const BodyState& s, const Vec2& X) { return s.velocity + s.angular_velocity * perp(X - s.centre); }

}  // namespace

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
        // Locked translations stay locked.
        s.velocity = Vec2(m.free(Dof::x) ? after.x() : 0.0, m.free(Dof::y) ? after.y() : 0.0);
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
    const Vec2 W = point_velocity(s, X);
    e.normal_restitution = -W.dot(n) / Vn;
    e.tangential_restitution = std::abs(Vt) > 1e-12 * std::abs(Vn) ? W.dot(t) / Vt
                                                                     : std::numeric_limits<double>::quiet_NaN();
    return e;
}

}  // namespace chute
