#include "obstacle.hpp"

#include <cmath>

namespace chute {

Gap gap(const Outline& outline, const BodyState& s, const Obstacle& obstacle) {
    // The nearest point is the outline's support point in the direction -n (in the body frame).
    const Vec2 r = outline.support_point(rotated(-obstacle.normal, -s.angle));
    const Vec2 X = s.centre + rotated(r, s.angle);
    return {(X - obstacle.point).dot(obstacle.normal), X};
}

std::vector<Obstacle> obstacles_of(const FlowConfig& flow, const std::vector<BodyConfig>& bodies,
                                   const ContactConfig& contact) {
    // A plane body's normal points out of its solid (on the right of its direction (cos a, sin a)).
    std::vector<Obstacle> out;
    for (const BodyConfig& b : bodies)
        if (b.shape == BodyShape::plane)
            out.push_back({b.name, Vec2(b.point[0], b.point[1]), Vec2(-std::sin(b.angle), std::cos(b.angle))});
    const Vec2 lo(flow.x.start, flow.y.start), hi(flow.x.end, flow.y.end);
    const Obstacle sides[4] = {{"left", lo, Vec2::UnitX()},
                               {"right", hi, -Vec2::UnitX()},
                               {"bottom", lo, Vec2::UnitY()},
                               {"top", hi, -Vec2::UnitY()}};
    for (int s = 0; s < 4; ++s)
        if (flow.boundary[s].type == BoundaryType::wall || flow.boundary[s].type == BoundaryType::slip)
            out.push_back(sides[s]);
    // Impacts happen `contact.distance` away from each surface: move the planes out by it.
    for (Obstacle& ob : out) ob.point += contact.distance * ob.normal;
    return out;
}

}  // namespace chute
