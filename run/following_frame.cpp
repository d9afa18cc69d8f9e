#include "following_frame.hpp"

#include <stdexcept>

namespace chute {

std::optional<FollowingFrame> FollowingFrame::of(const CaseConfig& config) {
    std::array<BoundaryType, 4> types{};
    for (int s = 0; s < 4; ++s) types[s] = config.boundary[s].type;
    const std::vector<BodyConfig>& bodies = config.bodies;
    std::optional<FollowingFrame> frame;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        if (!bodies[b].follow[0] && !bodies[b].follow[1]) continue;
        if (frame)
            throw std::invalid_argument("bodies." + bodies[b].name + ".follow: the grid already follows bodies." +
                                        bodies[frame->body()].name + ": one body at most");
        frame.emplace(b, bodies[b].follow);
        for (int axis = 0; axis < 2; ++axis) {
            const int s = bodies[b].follow[axis] ? wall_across(types, axis) : -1;
            if (s < 0) continue;
            throw std::invalid_argument("boundaries." + std::string(kSideNames[s]) +
                                        ".type: a wall across the motion of the grid following bodies." +
                                        bodies[b].name + " would move with it: give `inflow` with velocity [0, 0] " +
                                        "(the water at rest ahead), `outflow`, or a periodic pair");
        }
    }
    return frame;
}

void FollowingFrame::begin_step(FlowSolver& flow, const Body& body) {
    const Vec2 v = body.state().velocity;
    velocity_ = {axes_[0] ? v.x() : 0.0, axes_[1] ? v.y() : 0.0};
    flow.set_frame_velocity(velocity_);
}

void FollowingFrame::move(FlowSolver& flow, double dt) const {
    if (velocity_[0] != 0.0 || velocity_[1] != 0.0) flow.translate_grid(velocity_[0] * dt, velocity_[1] * dt);
}

}  // namespace chute
