#include "direct_forcing.hpp"

#include <mpi.h>
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
    : grid_(grid), config_(config), bodies_(bodies), result_(bodies.size()), followed_(bodies.size()) {
    ranges_.push_back(0);
    for (const Body& body : bodies_) {
        const double h = min_spacing_along(grid_, body);
        cell_size_.push_back(h);
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
            // A marker stands for its length of outline times the cells' extent along its normal (the kernel's
            // thickness across the surface): dy on a face along x, dx on one along y, h on square cells at any
            // angle. The geometric mean sqrt(dx dy) over-weighted the faces of flat cells by sqrt(dx / dy), and the
            // forcing iteration diverged past an aspect ratio of about 20 (docs/validation.md, "Case fuzz").
            const Vec2 h = local_spacing(grid_, world_[l]);
            const Vec2 n = bodies_[b].direction_to_world(body_frame_[l].normal);
            volume_[l] = body_frame_[l].length * std::hypot(n.x() * h.x(), n.y() * h.y());
        }
    su_ = delta_stencils(grid_, config_.kernel, Staggering::u_face, world_);
    sv_ = delta_stencils(grid_, config_.kernel, Staggering::v_face, world_);
    find_interior_faces();
    placement_.computed();
}

void DirectForcing::find_interior_faces() {
    const auto& X = grid_.lx();
    const auto& Y = grid_.ly();
    const int nx = grid_.nx(), ny = grid_.ny();
    interior_.assign(bodies_.size(), {});
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const Body& body = bodies_[b];
        if (!body.outline().closed()) continue;
        const double h = cell_size_[b];
        // Owned faces in the body's bounding box only.
        const double reach = body.outline().reach();
        const Vec2 c = body.state().centre;
        auto range = [](const LocalAxis& a, int n, double lo, double hi) {
            int first = 0, last = n - 1;
            while (first < n && a.f(first + 1) < lo) ++first;
            while (last >= 0 && a.f(last) > hi) --last;
            return std::pair{first, last};
        };
        const auto [i0, i1] = range(X, nx, c.x() - reach, c.x() + reach);
        const auto [j0, j1] = range(Y, ny, c.y() - reach, c.y() + reach);
        // a(d), d the depth below the surface in cells: a ramp of volume_ramp cells (a whole number, so that its
        // lattice sum does not depend on where the body sits against the grid) from the depth the kernel reaches
        // from the markers (support + retraction), so that it does not force the fluid the markers force. A ramp
        // centred there raised the accelerated square's added mass by 10 % (docs/validation.md).
        const double start = kernel_support(config_.kernel) + config_.retraction, ramp = config_.volume_ramp;
        auto share = [&](const Vec2& p) {
            const double d = -body.outline().signed_distance(body.to_body(p)) / h;
            if (ramp == 0.0) return d > start ? 1.0 : 0.0;
            return std::clamp((d - start) / ramp, 0.0, 1.0);
        };
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const Vec2 pu(X.f(i), Y.c(j)), pv(X.c(i), Y.f(j));
                if (const double a = share(pu); a > 0.0) interior_[b].push_back({i, j, true, X.dc(i) * Y.w(j), pu, a});
                if (const double a = share(pv); a > 0.0) interior_[b].push_back({i, j, false, X.w(i) * Y.dc(j), pv, a});
            }
    }
}

void DirectForcing::force_interior(Velocity& star, double dt) {
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        double sums[3] = {0.0, 0.0, 0.0};  // momentum rate x, y and torque rate of this rank's faces
        const Vec2 c = bodies_[b].state().centre;
        // The body's acceleration not yet followed in this step (a further pass of a strongly coupled step
        // starts from a field that already moved with the last pass's).
        const BodyState& st = bodies_[b].state();
        const Vec2 accel = st.acceleration - followed_[b].acceleration;
        const double angular_accel = st.angular_acceleration - followed_[b].angular_acceleration;
        followed_[b].acceleration = st.acceleration;
        followed_[b].angular_acceleration = st.angular_acceleration;
        for (const InteriorFace& f : interior_[b]) {
            const Vec2 U = bodies_[b].velocity_at(f.position);
            double& value = f.is_u ? star.u(f.i, f.j) : star.v(f.i, f.j);
            const double target = f.is_u ? U.x() : U.y();
            // A partly forced face follows the body's acceleration in full and keeps (1 - share) of its own
            // dynamics (pressure gradient, advection): the enclosed fluid stays rigid against an accelerating
            // body while the forced volume grows and shrinks smoothly as the body crosses cells.
            const Vec2 dU = dt * (accel + angular_accel * perp(f.position - c));
            const double follow = f.is_u ? dU.x() : dU.y();
            const double change =
                f.share == 1.0 ? target - value : f.share * (target - value) + (1.0 - f.share) * follow;
            const double rate = change * f.volume / dt;
            value = f.share == 1.0 ? target : value + change;  // exact where fully forced
            const Vec2 m = f.is_u ? Vec2(rate, 0.0) : Vec2(0.0, rate);
            sums[0] += m.x();
            sums[1] += m.y();
            sums[2] += cross(f.position - c, m);
        }
        if (grid_.size() > 1) MPI_Allreduce(MPI_IN_PLACE, sums, 3, MPI_DOUBLE, MPI_SUM, grid_.comm());
        result_[b].momentum_rate += Vec2(sums[0], sums[1]);
        result_[b].torque_rate += sums[2];
    }
}

void DirectForcing::begin_step() {
    for (BodyState& f : followed_) f = BodyState{};
}

void DirectForcing::apply(Velocity& star, double dt) {
    const bool any_moves = std::any_of(bodies_.begin(), bodies_.end(), [](const Body& b) { return b.moves(); });
    if (placement_.stale(any_moves)) place_markers();
    const std::size_t n = world_.size();
    std::vector<Vec2> target(n), force_sum(n, Vec2::Zero());
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        for (std::size_t l = ranges_[b]; l < ranges_[b + 1]; ++l) target[l] = bodies_[b].velocity_at(world_[l]);

    for (BodyForcing& r : result_) r = BodyForcing{};
    force_interior(star, dt);

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
        BodyForcing& r = result_[b];
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
    }
}

}  // namespace chute
