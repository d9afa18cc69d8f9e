#include "obstacle.hpp"

namespace chute {

Gap gap(const Outline& outline, const BodyState& s, const Obstacle& obstacle) {
    // The nearest point is the outline's support point in the direction -n (in the body frame).
    const Vec2 r = outline.support_point(rotated(-obstacle.normal, -s.angle));
    const Vec2 X = s.centre + rotated(r, s.angle);
    return {(X - obstacle.point).dot(obstacle.normal), X};
}

}  // namespace chute
