#include "following_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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
        // The quantum: 2^-36 of the narrowest followed cell, rounded down to a power of two (place()).
        double narrowest = std::numeric_limits<double>::max();
        for (int axis = 0; axis < 2; ++axis) {
            if (!bodies[b].follow[axis]) continue;
            const std::vector<double> lines = axis_lines(axis == 0 ? config.x : config.y);
            for (std::size_t k = 0; k + 1 < lines.size(); ++k) narrowest = std::min(narrowest, lines[k + 1] - lines[k]);
        }
        frame.emplace(b, bodies[b].follow, bodies[b].centre, std::array<double, 2>{config.x.start, config.y.start},
                      translate, std::ldexp(1.0, std::ilogb(narrowest) - 36));
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

void FollowingFrame::snap_lines(FlowSolver& flow) const {
    const auto snapped = [&](double l) { return quantum_ * std::round(l / quantum_); };
    const auto on_multiples = [&](int axis) {
        const std::vector<double>& lines = along(flow, axis).lines();
        return !axes_[axis] || std::all_of(lines.begin(), lines.end(), [&](double l) { return snapped(l) == l; });
    };
    if (on_multiples(0) && on_multiples(1)) return;  // every call but the first of a run
    std::array<std::vector<double>, 2> lines = {flow.grid().x_axis().lines(), flow.grid().y_axis().lines()};
    for (int axis = 0; axis < 2; ++axis)
        if (axes_[axis])
            for (double& l : lines[axis]) l = snapped(l);
    // Moved by at most half a quantum (1e-11 of a cell): the fields stay on their lines, the pressure history holds.
    flow.set_grid_lines(std::move(lines[0]), std::move(lines[1]), true);
}

void FollowingFrame::place(FlowSolver& flow, const Body& body) const {
    if (!translate_) return;
    // The lines moved by what separates the body from its place on them; the fields stay on their lines. The place
    // is kept to round-off, not to a drift of microns: a side on a grid line stays on it (a side jittering across a
    // line switched its faces between shut and open: the window's free fall spiked to 6 times its weight with a
    // drift taken back by the grid's velocity, and rippled by 3 % at its terminal speed with the body's predicted
    // place a dt^2 a / 2 off the lines).
    // The move is a multiple of the quantum (2^-36 of a cell, rounded to a power of two), the lines sit on its
    // multiples, so every line moves exactly, without round-off: the spacings stay the same bit for bit, and so
    // does everything a body that keeps its place computes from them (its cut faces, the pressure matrix, the
    // response of the exact coupling, which ibm/immersed_boundary.cpp then keeps from step to step). Exact while
    // the lines lie within 2^53 quanta (2^17 cells) of the origin. A move is made when the body is more than 3/4 of
    // a quantum off its place, and leaves it within half a quantum and round-off: a second call leaves the lines as
    // they are, so a restart, which calls it once more, repeats the straight run bit for bit (up to 2^14 cells from
    // the origin, where the round-off of the body's place reaches a quarter of a quantum).
    snap_lines(flow);
    std::array<double, 2> shift{0.0, 0.0};
    for (int axis = 0; axis < 2; ++axis) {
        if (!axes_[axis]) continue;
        const double drift = offset(flow, body, axis);
        if (std::abs(drift) > 0.75 * quantum_) shift[axis] = quantum_ * std::round(drift / quantum_);
    }
    if (shift[0] != 0.0 || shift[1] != 0.0) flow.translate_grid(shift[0], shift[1]);
}

}  // namespace chute
