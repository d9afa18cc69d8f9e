#include "body.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace chute {

BodyState PrescribedMotion::at(double t) const {
    BodyState s;
    s.centre = centre0_;
    s.angle = angle0_;
    const Vec2 V(m_.velocity[0], m_.velocity[1]);
    const Vec2 A(m_.amplitude[0], m_.amplitude[1]);
    const Vec2 a(m_.acceleration[0], m_.acceleration[1]);
    switch (m_.type) {
        case MotionType::fixed:
            break;
        case MotionType::free:  // the start; later states come from the rigid-body update
            s.velocity = V;
            s.angular_velocity = m_.angular_velocity;
            break;
        case MotionType::constant_velocity:
            s.centre += V * t;
            s.velocity = V;
            s.angle += m_.angular_velocity * t;
            s.angular_velocity = m_.angular_velocity;
            break;
        case MotionType::oscillation: {
            const double w = 2.0 * std::numbers::pi * m_.frequency, ph = w * t + m_.phase;
            s.centre += A * std::sin(ph);
            s.velocity = A * w * std::cos(ph);
            s.acceleration = -A * w * w * std::sin(ph);
            s.angle += m_.angular_amplitude * std::sin(ph);
            s.angular_velocity = m_.angular_amplitude * w * std::cos(ph);
            s.angular_acceleration = -m_.angular_amplitude * w * w * std::sin(ph);
            break;
        }
        case MotionType::uniform_acceleration:
            s.centre += 0.5 * a * t * t;
            s.velocity = a * t;
            s.acceleration = a;
            s.angle += 0.5 * m_.angular_acceleration * t * t;
            s.angular_velocity = m_.angular_acceleration * t;
            s.angular_acceleration = m_.angular_acceleration;
            break;
    }
    return s;
}

double longest_step(const Vec2& velocity, double angular_velocity, const Vec2& acceleration,
                    double angular_acceleration, double reach, double distance) {
    const double v = velocity.norm() + std::abs(angular_velocity) * reach;
    const double a = acceleration.norm() + std::abs(angular_acceleration) * reach;
    if (a > 0.0) return 2.0 * distance / (v + std::sqrt(v * v + 2.0 * a * distance));
    return v > 0.0 ? distance / v : std::numeric_limits<double>::infinity();
}

namespace {

// The part of the line through p with direction d that lies inside the box [lo, hi] (Liang-Barsky).
std::pair<Vec2, Vec2> clip_line(const Vec2& p, const Vec2& d, const Vec2& lo, const Vec2& hi) {
    double t0 = -1e300, t1 = 1e300;
    for (int k = 0; k < 2; ++k) {
        if (std::abs(d[k]) < 1e-14) {
            if (p[k] < lo[k] || p[k] > hi[k]) throw std::invalid_argument("the plane lies outside the domain");
            continue;
        }
        double a = (lo[k] - p[k]) / d[k], b = (hi[k] - p[k]) / d[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    if (!(t1 > t0)) throw std::invalid_argument("the plane does not cross the domain");
    return {p + t0 * d, p + t1 * d};
}

}  // namespace

Body::Body(const BodyConfig& c, const Vec2& domain_min, const Vec2& domain_max) : config_(c) {
    Vec2 centre(c.centre[0], c.centre[1]);
    double angle = c.angle;
    switch (c.shape) {
        case BodyShape::circle:
            outline_ = Outline::circle(c.diameter);
            break;
        case BodyShape::rectangle:
            outline_ = Outline::rectangle(c.size[0], c.size[1]);
            break;
        case BodyShape::polygon: {
            std::vector<Vec2> v;
            for (const auto& p : c.vertices) v.emplace_back(p[0], p[1]);
            Vec2 centroid;
            outline_ = Outline::polygon(v, &centroid);
            centre = centroid;  // the vertices are given in place; `angle` turns them about the centroid
            break;
        }
        case BodyShape::plane: {
            const Vec2 d(std::cos(c.angle), std::sin(c.angle));
            const auto [a, b] = clip_line(Vec2(c.point[0], c.point[1]), d, domain_min, domain_max);
            outline_ = Outline::segment(a, b);
            centre = Vec2::Zero();
            angle = 0.0;
            break;
        }
        case BodyShape::segment:
            outline_ = Outline::segment(Vec2(c.from[0], c.from[1]), Vec2(c.to[0], c.to[1]));
            centre = Vec2::Zero();
            angle = 0.0;
            break;
    }
    motion_ = PrescribedMotion(c.motion, centre, angle);
    set_state(motion_.at(0.0));
}

}  // namespace chute
