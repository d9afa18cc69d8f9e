#include "body_fitted.hpp"

#include <algorithm>
#include <stdexcept>

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
        if (body.free())
            throw std::invalid_argument(key +
                                        ".type: a free body_fitted body is not carried yet (prescribed motion "
                                        "only in this version)");
        if (m.angular_velocity != 0.0 || m.angular_amplitude != 0.0 || m.angular_acceleration != 0.0)
            throw std::invalid_argument(key + ": a body_fitted body translates only (its sides stay on grid lines)");
        if (body.moves()) {
            if (carrying_ >= 0)
                throw std::invalid_argument(key + ".type: one body_fitted body moves, and the grid with it; bodies." +
                                            bodies_[carrying_].name() + " already does");
            carrying_ = static_cast<int>(k);
        }
        blocks.push_back(hole_of(body, grid_));
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

void BodyFitted::attach(FlowSolver& flow) {
    flow_ = &flow;
    follow();
}

void BodyFitted::follow() {
    if (carrying_ < 0) return;
    const Vec2 v = bodies_[carrying_].state().velocity;
    flow_->set_frame_velocity({v.x(), v.y()});
    solid_.set_velocity(static_cast<std::size_t>(carrying_), {v.x(), v.y()});
}

void BodyFitted::place(double t) {
    for (std::size_t k = 0; k < bodies_.size(); ++k) {
        Body& body = bodies_[k];
        const Vec2 before = body.state().centre;
        body.move_to(t);
        if (static_cast<int>(k) != carrying_) continue;
        const Vec2 shift = body.state().centre - before;
        flow_->translate_grid(shift.x(), shift.y());
    }
    follow();
}

Wrench BodyFitted::hydrodynamic_wrench(std::size_t b, const Velocity&, double) {
    // Only free bodies are moved by a wrench, and the constructor refuses them.
    throw std::logic_error("BodyFitted::hydrodynamic_wrench: body " + bodies_[b].name() +
                           " is not free (free body_fitted bodies come with the moving grid)");
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
    const Axis& X = grid_.x_axis();
    const Axis& Y = grid_.y_axis();
    const int ox = grid_.lx().offset, oy = grid_.ly().offset;
    auto owned = [&](int i, int j) { return i >= 0 && i < grid_.nx() && j >= 0 && j < grid_.ny(); };
    for (const SolidBlock& h : solid_.blocks()) {
        for (const bool top : {false, true}) {
            const int gj = top ? h.upper[1] : h.lower[1] - 1;
            const double y = 0.5 * Y.width(gj);
            for (int gi = h.lower[0]; gi < h.upper[0]; ++gi) {
                const int i = gi - ox, j = gj - oy;
                if (!owned(i, j)) continue;
                const double slip = std::abs(0.5 * (vel.u(i, j) + vel.u(i + 1, j)) - h.velocity[0]);
                out.push_back({i, j, y, 2.0 * y, y, slip, k(i, j), true});
            }
        }
        for (const bool right : {false, true}) {
            const int gi = right ? h.upper[0] : h.lower[0] - 1;
            const double y = 0.5 * X.width(gi);
            for (int gj = h.lower[1]; gj < h.upper[1]; ++gj) {
                const int i = gi - ox, j = gj - oy;
                if (!owned(i, j)) continue;
                const double slip = std::abs(0.5 * (vel.v(i, j) + vel.v(i, j + 1)) - h.velocity[1]);
                out.push_back({i, j, y, 2.0 * y, y, slip, k(i, j), true});
            }
        }
    }
    return out;
}

}  // namespace chute
