#include "body_fitted.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "hole.hpp"
#include "hole_stress.hpp"

namespace chute {

BodyFitted::BodyFitted(const Grid& grid, const BodyFittedSettings& settings, std::vector<Body>& bodies)
    : grid_(grid), settings_(settings), bodies_(bodies), solid_(grid) {
    std::vector<SolidBlock> blocks;
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
        const Body& body = bodies_[k];
        const MotionConfig& m = body.config().motion;
        const std::string key = "bodies." + body.name() + ".motion";
        if (body.free() && !m.locked[2])
            throw std::invalid_argument(key +
                                        ".lock_rotation: a free body_fitted body must have its rotation locked (its "
                                        "sides stay on grid lines)");
        if (m.angular_velocity != 0.0 || m.angular_amplitude != 0.0 || m.angular_acceleration != 0.0)
            throw std::invalid_argument(key + ": a body_fitted body translates only (its sides stay on grid lines)");
        if (body.moves()) {
            if (carrying_ >= 0)
                throw std::invalid_argument(key + ".type: one body_fitted body moves, and the grid with it; bodies." +
                                            bodies_[carrying_].name() + " already does");
            carrying_ = static_cast<int>(k);
            if (!body.config().layers) refuse_walls_across_motion(body);
        }
        blocks.push_back(hole_of(body, grid_));
        if (body.moves() && body.config().layers)
            for (int axis = 0; axis < 2; ++axis) {
                if (!moves_along(body, axis)) continue;
                const Axis& a = axis == 0 ? grid_.x_axis() : grid_.y_axis();
                layers_[axis].emplace(a.lines(), body.state().centre[axis], blocks.back().lower[axis],
                                      blocks.back().upper[axis], "bodies." + body.name() + ".grid_motion");
                refuse_contact_it_cannot_take(body, axis);
            }
        const SolidBlock& b = blocks.back();
        double h = 1e300;
        for (int k = b.lower[0]; k < b.upper[0]; ++k) h = std::min(h, grid_.x_axis().width(k));
        for (int k = b.lower[1]; k < b.upper[1]; ++k) h = std::min(h, grid_.y_axis().width(k));
        cell_size_.push_back(h);
    }
    for (std::size_t a = 0; a < blocks.size(); ++a)
        for (std::size_t c = a + 1; c < blocks.size(); ++c) {
            const SolidBlock &p = blocks[a], &q = blocks[c];
            const bool apart = p.upper[0] + 2 <= q.lower[0] || q.upper[0] + 2 <= p.lower[0] ||
                               p.upper[1] + 2 <= q.lower[1] || q.upper[1] + 2 <= p.lower[1];
            if (!apart)
                throw std::invalid_argument("bodies." + bodies_[c].name() +
                                            ": body_fitted bodies must stay at least two cells from bodies." +
                                            bodies_[a].name());
        }
    solid_.set(std::move(blocks));
}

// The grid moves with the body along the axes it moves along (a free body's unlocked ones, a prescribed body's
// with a velocity, amplitude or acceleration there): the boundaries across them would move too.
// A body with layers can meet a wall across its motion: the layers between are removed until the modifier is the
// gap, which must stay open (contact at contact.distance); the rebound law acts with either treatment of the water's
// impulse (contact.water_impulse), and the exact coupling brings the water to the block's velocity.
void BodyFitted::refuse_contact_it_cannot_take(const Body& body, int axis) const {
    if (wall_across(settings_.boundaries, axis) < 0 || !body.free()) return;
    if (!(settings_.contact_distance > 0.0))
        throw std::invalid_argument(
            "contact.distance: the body_fitted body `" + body.name() +
            "` with grid_motion layers can reach a wall across its motion, and meets it at a gap that its last layer "
            "fills: set a gap > 0 (the block's first cell, or the study's 0.1 m)");
}

bool BodyFitted::moves_along(const Body& body, int axis) const {
    const MotionConfig& m = body.config().motion;
    return body.free() ? !m.locked[axis]
                       : m.velocity[axis] != 0.0 || m.amplitude[axis] != 0.0 || m.acceleration[axis] != 0.0;
}

void BodyFitted::refuse_walls_across_motion(const Body& body) const {
    for (int axis = 0; axis < 2; ++axis) {
        const int s = moves_along(body, axis) ? wall_across(settings_.boundaries, axis) : -1;
        if (s < 0) continue;
        throw std::invalid_argument("boundaries." + std::string(kSideNames[s]) +
                                    ".type: a wall across the motion of the body_fitted body `" + body.name() +
                                    "`, which carries the grid (and its boundaries) along " + (axis == 0 ? "x" : "y") +
                                    ": use inflow (water at rest) ahead and outflow behind" +
                                    (body.free() ? std::string(", or lock ") + (axis == 0 ? "x" : "y") : ""));
    }
}

void BodyFitted::attach(FlowSolver& flow) {
    flow_ = &flow;
    follow();
    if (carrying_ < 0 || !bodies_[carrying_].free()) return;
    compute_response();
}

// The flow's response to the free body's velocity on the grid as it is (band/body_fitted.hpp), and its added mass.
void BodyFitted::compute_response(bool warm) {
    response_centre_ = zone_centre_;
    const Body& body = bodies_[carrying_];
    response_ = flow_->hole_response(static_cast<std::size_t>(carrying_), warm ? &*response_ : nullptr,
                                     {moves_along(body, 0), moves_along(body, 1)});
    const SolidBlock& block = solid_.blocks()[carrying_];
    added_mass_.setZero();
    const double rd = settings_.density * settings_.depth;
    for (int k = 0; k < 2; ++k) {
        const std::array<double, 2> push = flow_->solid_gradient_sum(block, response_->pressure[k]);
        added_mass_(0, k) = rd * push[0];
        added_mass_(1, k) = rd * push[1];
    }
}

void BodyFitted::follow() {
    if (carrying_ < 0) return;
    const BodyState& s = bodies_[carrying_].state();
    if (layers_[0] || layers_[1]) {
        // The rigid zones where the body is, the modifiers stretched; the lines along an axis without layers stay.
        std::vector<double> x = grid_.x_axis().lines(), y = grid_.y_axis().lines();
        const bool keep = std::exchange(lines_restored_, false);
        GridMotion motion;
        if (!keep) zone_centre_ = {s.centre.x(), s.centre.y()};
        if (layers_[0]) {
            x = layers_[0]->stretched(x, s.centre.x());
            motion.axis[0] = {layers_[0]->first(), layers_[0]->last(), s.velocity.x()};
        }
        if (layers_[1]) {
            y = layers_[1]->stretched(y, s.centre.y());
            motion.axis[1] = {layers_[1]->first(), layers_[1]->last(), s.velocity.y()};
        }
        const bool moved = !keep && (x != grid_.x_axis().lines() || y != grid_.y_axis().lines());
        if (moved) flow_->stretch_grid_lines(x, y);
        flow_->set_grid_motion(motion);
        refresh_hierarchy();
        // Near a wall the stretching cell is the gap beside the block: the flow's response to the block's velocity
        // (and its added mass, which grows as the gap closes) changes with it every step.
        const auto trimmed = zone_trimmed();
        // Its solves start from the last step's response (a fifth of the bed bounce's run; a restart in this phase
        // starts them from zero and ends equal to the solver's tolerance, not bit for bit).
        if (moved && response_ && trimmed[0][0] + trimmed[0][1] + trimmed[1][0] + trimmed[1][1] > 0)
            compute_response(true);
        solid_.set_velocity(static_cast<std::size_t>(carrying_), {s.velocity.x(), s.velocity.y()});
        return;
    }
    // Where the block's cells are now: the grid moves by what separates them from the body.
    const SolidBlock& block = solid_.blocks()[carrying_];
    const Axis& X = grid_.x_axis();
    const Axis& Y = grid_.y_axis();
    const Vec2 on_grid(0.5 * (X.line(block.lower[0]) + X.line(block.upper[0])),
                       0.5 * (Y.line(block.lower[1]) + Y.line(block.upper[1])));
    const Vec2 shift = s.centre - on_grid;
    if (shift.x() != 0.0 || shift.y() != 0.0) flow_->translate_grid(shift.x(), shift.y());
    flow_->set_frame_velocity({s.velocity.x(), s.velocity.y()});
    solid_.set_velocity(static_cast<std::size_t>(carrying_), {s.velocity.x(), s.velocity.y()});
}

void BodyFitted::begin_step(const Velocity&) {
    if (!layers_[0] && !layers_[1]) return;
    const BodyState& s = bodies_[carrying_].state();
    std::vector<double> x = grid_.x_axis().lines(), y = grid_.y_axis().lines();
    bool changed = false;
    if (layers_[0])
        if (auto lines = layers_[0]->change(x, s.velocity.x())) x = std::move(*lines), changed = true;
    if (layers_[1])
        if (auto lines = layers_[1]->change(y, s.velocity.y())) y = std::move(*lines), changed = true;
    if (!changed) return;
    flow_->change_grid_lines(std::move(x), std::move(y));
    holes_found_again();
    change_energy_ = flow_->project_after_change();
    follow();
}

// The lines changed under the blocks: their cells are found again (the rigid zone was renumbered), the solver
// leaves the new ones out, and a free body's response to its velocity is computed on the new grid.
void BodyFitted::holes_found_again() {
    std::vector<SolidBlock> blocks;
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
        if (static_cast<int>(k) == carrying_) {
            // The carrying body's block is where its rigid zone is (the lines lag its final place by a fraction of
            // the step's travel).
            SolidBlock b = solid_.blocks()[k];
            for (int axis = 0; axis < 2; ++axis)
                if (layers_[axis])
                    b.lower[axis] = layers_[axis]->hole_lower(), b.upper[axis] = layers_[axis]->hole_upper();
            blocks.push_back(b);
            continue;
        }
        blocks.push_back(hole_of(bodies_[k], grid_));
        blocks.back().velocity = solid_.blocks()[k].velocity;
    }
    solid_.set(std::move(blocks));
    flow_->set_solid_cells(&solid_);
    hierarchy_dirty_ = true;  // set up again on the current lines: follow() puts it on the quantized ones
    if (response_) compute_response();
}

BodyFitted::NamedArrays BodyFitted::checkpoint_arrays() const {
    if (!layers_[0] && !layers_[1]) return {};
    std::vector<double> trims;
    for (int axis = 0; axis < 2; ++axis)
        for (int k = 0; k < 2; ++k) trims.push_back(layers_[axis] ? layers_[axis]->trimmed()[k] : 0.0);
    return {{"zone_centre", {zone_centre_[0], zone_centre_[1]}},
            {"response_centre", {response_centre_[0], response_centre_[1]}},
            {"zone_trim", trims}};
}

void BodyFitted::restored(const NamedArrays& arrays) {
    if (!layers_[0] && !layers_[1]) return;
    const auto zone = arrays.find("zone_centre"), response = arrays.find("response_centre");
    if (zone == arrays.end() || response == arrays.end() || zone->second.size() != 2 || response->second.size() != 2)
        throw std::runtime_error(
            "the checkpoint has no modifier-layer state (zone_centre, response_centre) for bodies." +
            bodies_[carrying_].name() + ": written by a run without grid_motion layers?");
    zone_centre_ = {zone->second[0], zone->second[1]};
    const auto trim = arrays.find("zone_trim");
    for (int axis = 0; axis < 2; ++axis)
        if (layers_[axis]) {
            if (trim != arrays.end() && trim->second.size() == 4)
                layers_[axis]->trim(static_cast<int>(trim->second[2 * axis]),
                                    static_cast<int>(trim->second[2 * axis + 1]));
            layers_[axis]->locate(axis == 0 ? grid_.x_axis().lines() : grid_.y_axis().lines(), zone_centre_[axis]);
        }
    const BodyState& s = bodies_[carrying_].state();
    solid_.set_velocity(static_cast<std::size_t>(carrying_), {s.velocity.x(), s.velocity.y()});
    // The blocks where the zones are; a free body's response on the grid it was computed on (the lines at the last
    // layer change), as the straight run holds it.
    const std::vector<double> x = grid_.x_axis().lines(), y = grid_.y_axis().lines();
    const std::array<double, 2> at_change = {response->second[0], response->second[1]};
    if (response_ && at_change != zone_centre_) {
        flow_->set_grid_lines(layers_[0] ? layers_[0]->stretched(x, at_change[0]) : x,
                              layers_[1] ? layers_[1]->stretched(y, at_change[1]) : y, true);
        const std::array<double, 2> now = zone_centre_;
        zone_centre_ = at_change;
        holes_found_again();
        zone_centre_ = now;
        flow_->set_grid_lines(x, y, true);  // the matrix rebuilt on the checkpoint's lines, the same solid cells
    } else {
        holes_found_again();
    }
    lines_restored_ = true;  // the place() after the restore keeps the checkpoint's lines
}

std::array<int, 2> BodyFitted::layer_changes() const {
    return {layers_[0] ? layers_[0]->changes() : 0, layers_[1] ? layers_[1]->changes() : 0};
}

void BodyFitted::refresh_hierarchy() {
    std::vector<double> x = grid_.x_axis().lines(), y = grid_.y_axis().lines();
    std::array<double, 2> centre{};
    for (int axis = 0; axis < 2; ++axis)
        if (layers_[axis]) centre[axis] = layers_[axis]->hierarchy_centre(axis == 0 ? x : y, zone_centre_[axis]);
    if (!hierarchy_dirty_ && centre == hierarchy_centre_) return;
    if (layers_[0]) x = layers_[0]->stretched(x, centre[0]);
    if (layers_[1]) y = layers_[1]->stretched(y, centre[1]);
    flow_->set_up_pressure_hierarchy(std::move(x), std::move(y));
    hierarchy_centre_ = centre;
    hierarchy_dirty_ = false;
}

void BodyFitted::place(double t) {
    for (Body& body : bodies_) body.move_to(t);  // a free body is where FreeBodies::predict put it
    follow();
}

Wrench BodyFitted::hydrodynamic_wrench(std::size_t b, const Velocity&, double) {
    if (static_cast<int>(b) != carrying_ || !response_)
        throw std::logic_error("BodyFitted::hydrodynamic_wrench: body " + bodies_[b].name() + " is not free");
    // Force (a), which closes the fluid's momentum balance; the rotation is locked.
    const std::array<double, 2> m = flow_->solid_momentum_rate(solid_.blocks()[b]);
    return {settings_.density * settings_.depth * Vec2(m[0], m[1]), 0.0};
}

std::optional<Eigen::Matrix3d> BodyFitted::added_mass(std::size_t b) const {
    if (static_cast<int>(b) != carrying_ || !response_) return std::nullopt;
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();  // the rotation is locked
    M.topLeftCorner<2, 2>() = added_mass_;
    return M;
}

void BodyFitted::body_moved(std::size_t b, double dt) {
    if (static_cast<int>(b) != carrying_ || !response_) return;
    // The step was projected with the sides at the predicted velocity (place -> follow); the update moved it.
    const std::array<double, 2> imposed = solid_.blocks()[b].velocity;
    const Vec2 v = bodies_[b].state().velocity;
    if (layers_[0] || layers_[1]) {
        // The lines stay where the step was projected (the body's predicted place, a distance dt (v - v*) / 2 from
        // its final one): moving them after the projection would change the cells' volumes under a divergence-free
        // flow. The next step's place() takes them to its own predicted place, the momentum moved conservatively.
        solid_.set_velocity(b, {v.x(), v.y()});
        GridMotion motion = flow_->grid_motion();
        for (int axis = 0; axis < 2; ++axis)
            if (layers_[axis]) motion.axis[axis].velocity = v[axis];
        flow_->set_grid_motion(motion);
    } else {
        follow();
    }
    flow_->add_body_response(*response_, {v.x() - imposed[0], v.y() - imposed[1]}, dt);
}

std::vector<BodyForces> BodyFitted::measure(const Velocity& vel, const Field2D& p, const WallTurbulence* turbulence) {
    std::vector<BodyForces> out(bodies_.size());
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        out[b].surface = hole_stress(grid_, solid_.blocks()[b], bodies_[b].state(), vel, p, settings_.density,
                                     settings_.viscosity, settings_.depth, turbulence);
        const std::array<double, 2> m = flow_->solid_momentum_rate(solid_.blocks()[b]);
        out[b].forcing = settings_.density * settings_.depth * Vec2(m[0], m[1]);
        out[b].forcing_torque = out[b].surface.total_torque();
    }
    return out;
}

// The fluid cells along each side: the wall-adjacent cells of a body-fitted mesh, sampled at their own centre,
// half a cell from the side (turbulence/k_epsilon.cpp: production and epsilon from the log law there).
std::vector<WallSample> BodyFitted::sample_walls(const Velocity& vel, const Field2D& k) const {
    std::vector<WallSample> out;
    for (const SolidBlock& h : solid_.blocks())
        for (const SideCell& c : side_cells(grid_, h, vel))
            out.push_back({c.i, c.j, c.distance, 2.0 * c.distance, c.distance, c.slip.norm(), k(c.i, c.j), true});
    return out;
}

}  // namespace chute
