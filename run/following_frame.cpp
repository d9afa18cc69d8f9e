#include "following_frame.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

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
        const bool translate = config.ibm.interface == Interface::sharp;
        frame.emplace(b, bodies[b].follow, bodies[b].centre, std::array<double, 2>{config.x.start, config.y.start},
                      translate);
        for (int axis = 0; axis < 2; ++axis) {
            if (!bodies[b].follow[axis]) continue;
            if (const int s = wall_across(types, axis); s >= 0)
                throw std::invalid_argument("boundaries." + std::string(kSideNames[s]) +
                                            ".type: a wall across the motion of the grid following bodies." +
                                            bodies[b].name + " would move with it: give `inflow` with velocity " +
                                            "[0, 0] (the water at rest ahead), `outflow`, or a periodic pair");
            // The grid moves by whole cells and keeps its spacings: every cell of the axis the same width.
            if (!translate && !uniform_axis(Axis(axis_lines(axis == 0 ? config.x : config.y), false)))
                throw std::invalid_argument(std::string("domain.") + (axis == 0 ? "x" : "y") +
                                            ": the grid following bodies." + bodies[b].name +
                                            " moves by whole cells along it with the diffuse interface, so its cells "
                                            "must be equal (give `cells` with the uniform spacing, or "
                                            "numerics.ibm.interface: sharp, whose grid translates)");
        }
    }
    return frame;
}

double FollowingFrame::offset(const FlowSolver& flow, const Body& body, int axis) const {
    // Where the body started on the grid, carried with the lines.
    const double anchor = body_start_[axis] + (along(flow, axis).start() - domain_start_[axis]);
    return body.state().centre[axis] - anchor;
}

void FollowingFrame::before_step(FlowSolver& flow, KEpsilon* turbulence, const Body& body) const {
    if (translate_) return;
    bool moved = false;
    for (int axis = 0; axis < 2; ++axis) {
        if (!axes_[axis]) continue;
        const double width = along(flow, axis).width(0);
        // The body within a cell of where it started on the grid.
        for (; offset(flow, body, axis) >= width; moved = true) flow.shift_one_cell(axis, +1);
        for (; offset(flow, body, axis) <= -width; moved = true) flow.shift_one_cell(axis, -1);
    }
    if (turbulence && moved) turbulence->shifted();
    // The window moves on average with the body: its outflow lets the wake out at the speed relative to that.
    const Vec2 v = body.state().velocity;
    flow.set_boundary_frame_velocity({axes_[0] ? v.x() : 0.0, axes_[1] ? v.y() : 0.0});
}

void FollowingFrame::after_step(FlowSolver& flow, const Body& body) const {
    if (!translate_) return;
    place(flow, body);
    const Vec2 v = body.state().velocity;
    flow.set_frame_velocity({axes_[0] ? v.x() : 0.0, axes_[1] ? v.y() : 0.0});
}

void FollowingFrame::place(FlowSolver& flow, const Body& body) const {
    if (!translate_) return;
    // The lines moved by what separates the body from its place on them; the fields stay on their lines. The place
    // is kept to round-off, not to a drift of microns: a side on a grid line stays on it (a side jittering across a
    // line switched its faces between shut and open: the window's free fall spiked to 6 times its weight with a
    // drift taken back by the grid's velocity, and rippled by 3 % at its terminal speed with the body's predicted
    // place a dt^2 a / 2 off the lines). Moves below 1e-12 of a cell are round-off left by the last one: a second
    // call leaves the lines as they are, so a restart, which calls it once more, repeats the straight run bit for
    // bit.
    std::array<double, 2> shift{0.0, 0.0};
    for (int axis = 0; axis < 2; ++axis) {
        if (!axes_[axis]) continue;
        const double drift = offset(flow, body, axis);
        const double cell = along(flow, axis).width(0);
        if (std::abs(drift) > 1e-12 * cell) shift[axis] = drift;
    }
    if (shift[0] != 0.0 || shift[1] != 0.0) flow.translate_grid(shift[0], shift[1]);
}

}  // namespace chute
