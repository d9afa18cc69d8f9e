#include "direct_forcing.hpp"

#include <algorithm>
#include <cmath>

namespace chute {

double min_spacing_along(const Grid& grid, const Body& body) {
    // Sample the outline densely (a fraction of the smallest cell) and take the smallest local spacing.
    const auto& X = grid.x_axis().lines();
    const auto& Y = grid.y_axis().lines();
    double hmin = 1e300;
    for (std::size_t k = 0; k + 1 < X.size(); ++k) hmin = std::min(hmin, X[k + 1] - X[k]);
    for (std::size_t k = 0; k + 1 < Y.size(); ++k) hmin = std::min(hmin, Y[k + 1] - Y[k]);
    double h = 1e300;
    for (const Marker& m : body.outline().markers(0.25 * hmin)) {
        const Vec2 s = local_spacing(grid, body.to_world(m.position));
        h = std::min(h, std::min(s.x(), s.y()));
    }
    return h;
}

DirectForcing::DirectForcing(const Grid& grid, const IbmConfig& config, const std::vector<Body>& bodies)
    : grid_(grid), config_(config), bodies_(bodies), result_(bodies.size()) {
    ranges_.push_back(0);
    for (const Body& body : bodies_) {
        const double h = min_spacing_along(grid_, body);
        spacing_.push_back(config_.marker_spacing * h);
        for (Marker m : body.outline().markers(config_.marker_spacing * h)) {
            // Retraction (Breugem 2012, sec. 2.3): markers a fraction of a cell inside the surface
            // compensate for the thickness the kernel gives the interface.
            if (body.outline().closed()) m.position -= config_.retraction * h * m.normal;
            body_frame_.push_back(m);
        }
        ranges_.push_back(body_frame_.size());
    }
    world_.resize(body_frame_.size());
    volume_.resize(body_frame_.size());
}

void DirectForcing::place_markers() {
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        for (std::size_t l = ranges_[b]; l < ranges_[b + 1]; ++l) {
            world_[l] = bodies_[b].to_world(body_frame_[l].position);
            const Vec2 h = local_spacing(grid_, world_[l]);
            volume_[l] = body_frame_[l].length * std::sqrt(h.x() * h.y());
        }
    su_ = delta_stencils(grid_, config_.kernel, Staggering::u_face, world_);
    sv_ = delta_stencils(grid_, config_.kernel, Staggering::v_face, world_);
    placed_ = true;
}

void DirectForcing::apply(Velocity& star, double dt) {
    const bool any_moves = std::any_of(bodies_.begin(), bodies_.end(), [](const Body& b) { return b.moves(); });
    if (!placed_ || any_moves) place_markers();
    const std::size_t n = world_.size();
    std::vector<Vec2> target(n), force_sum(n, Vec2::Zero());
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        for (std::size_t l = ranges_[b]; l < ranges_[b + 1]; ++l) target[l] = bodies_[b].velocity_at(world_[l]);

    std::vector<double> du(n), dv(n);
    for (int it = 0; it < config_.forcing_iterations; ++it) {
        const std::vector<Vec2> U = interpolate_velocity(grid_, su_, sv_, star);
        for (std::size_t l = 0; l < n; ++l) {
            const Vec2 F = (target[l] - U[l]) / dt;
            force_sum[l] += F;
            du[l] = dt * F.x() * volume_[l];
            dv[l] = dt * F.y() * volume_[l];
        }
        spread(su_, du, star.u);
        spread(sv_, dv, star.v);
    }

    const std::vector<Vec2> U = interpolate_velocity(grid_, su_, sv_, star);
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        BodyForcing r;
        double sq = 0.0;
        for (std::size_t l = ranges_[b]; l < ranges_[b + 1]; ++l) {
            const Vec2 f = force_sum[l] * volume_[l];
            r.momentum_rate += f;
            r.torque_rate += cross(world_[l] - bodies_[b].state().centre, f);
            const double slip = (U[l] - target[l]).norm();
            r.max_slip = std::max(r.max_slip, slip);
            sq += slip * slip;
        }
        const std::size_t count = ranges_[b + 1] - ranges_[b];
        r.rms_slip = count ? std::sqrt(sq / count) : 0.0;
        result_[b] = r;
    }
}

}  // namespace chute
