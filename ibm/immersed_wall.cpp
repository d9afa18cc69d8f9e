#include "immersed_wall.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace chute {

namespace {

// The global cell that contains x (clamped to the axis).
int cell_containing(const Axis& a, double x) {
    const auto& L = a.lines();
    const int k = static_cast<int>(std::lower_bound(L.begin(), L.end(), x) - L.begin()) - 1;
    return std::clamp(k, 0, a.cells() - 1);
}

}  // namespace

ImmersedWall::ImmersedWall(const Grid& grid, const std::vector<Body>& bodies, double image_cells, NearWall near_wall)
    : grid_(grid), bodies_(bodies), image_cells_(image_cells), near_wall_(near_wall), fluid_(grid, 1.0) {}

double ImmersedWall::sample_distance(const BandCell& c) const {
    return near_wall_ == NearWall::surface ? std::max(c.d, 0.5 * c.h) : image_cells_ * c.h;
}

double ImmersedWall::cell_size(int gi, int gj) const {
    return std::max(grid_.x_axis().width(gi), grid_.y_axis().width(gj));
}

void ImmersedWall::locate() {
    if (bodies_.empty()) return;
    // Body::moves() is true for prescribed and free motion alike.
    const bool any_moves = std::any_of(bodies_.begin(), bodies_.end(), [](const Body& b) { return b.moves(); });
    if (!placement_.stale(any_moves)) return;
    const bool grid_moved = placement_.lines_moved();  // a following window moved the grid (or the first call)
    placement_.computed();

    const int margin = static_cast<int>(std::ceil(image_cells_)) + 3;
    // Static bodies are scanned once (a plane bounds half the domain: all of it is scanned).
    if (!static_scanned_ || grid_moved) {
        fluid_.fill(1.0);
        band_.clear();
        for (std::size_t b = 0; b < bodies_.size(); ++b)
            if (!bodies_[b].moves()) scan_around(b, margin);
        static_fluid_ = fluid_;
        static_band_ = band_;
        static_scanned_ = true;
    }
    fluid_ = static_fluid_;
    band_ = static_band_;
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        if (bodies_[b].moves()) scan_around(b, margin);
    // A cell near one body may lie inside another (the block resting on the bed): the nearest surface and
    // the sign of the smallest distance decide.
    std::unordered_map<long long, std::size_t> seen;
    std::vector<BandCell> merged;
    for (const BandCell& c : band_) {
        const long long key = 1LL * c.gj * grid_.global_nx() + c.gi;
        auto [it, fresh] = seen.try_emplace(key, merged.size());
        if (fresh)
            merged.push_back(c);
        else if (c.d < merged[it->second].d)
            merged[it->second] = c;
    }
    if (near_wall_ == NearWall::surface)
        std::erase_if(merged, [](const BandCell& c) { return c.d < 0.0 || c.d >= c.h; });
    else
        std::erase_if(merged, [](const BandCell& c) { return c.d <= -2.0 * c.h; });
    band_ = std::move(merged);
    std::vector<Vec2> images;
    images.reserve(band_.size());
    for (const BandCell& c : band_) images.push_back(c.surface + sample_distance(c) * c.normal);
    su_ = bilinear_stencils(grid_, Staggering::u_face, images);
    sv_ = bilinear_stencils(grid_, Staggering::v_face, images);
    sk_ = bilinear_stencils(grid_, Staggering::cell, images);
}

// A closed body: the cells of its bounding box, widened by `margin` cells; an open line (plane): all cells.
void ImmersedWall::scan_around(std::size_t b, int margin) {
    const Body& body = bodies_[b];
    const Axis& ax = grid_.x_axis();
    const Axis& ay = grid_.y_axis();
    if (!body.outline().closed()) return scan(b, 0, ax.cells() - 1, 0, ay.cells() - 1);
    const double r = body.outline().reach();
    const Vec2 c = body.state().centre;
    scan(b, std::max(0, cell_containing(ax, c.x() - r) - margin),
         std::min(ax.cells() - 1, cell_containing(ax, c.x() + r) + margin),
         std::max(0, cell_containing(ay, c.y() - r) - margin),
         std::min(ay.cells() - 1, cell_containing(ay, c.y() + r) + margin));
}

void ImmersedWall::scan(std::size_t b, int gi0, int gi1, int gj0, int gj1) {
    const Body& body = bodies_[b];
    const Axis& ax = grid_.x_axis();
    const Axis& ay = grid_.y_axis();
    const LocalAxis& lx = grid_.lx();
    const LocalAxis& ly = grid_.ly();
    auto distance = [&](const Vec2& X) { return body.outline().signed_distance(body.to_body(X)); };
    for (int gj = gj0; gj <= gj1; ++gj)
        for (int gi = gi0; gi <= gi1; ++gi) {
            const Vec2 x(ax.centre(gi), ay.centre(gj));
            const double d = distance(x);
            const double h = cell_size(gi, gj);
            const int li = gi - lx.offset, lj = gj - ly.offset;
            if (d < 0.0 && li >= -kGhost && li < grid_.nx() + kGhost && lj >= -kGhost && lj < grid_.ny() + kGhost)
                fluid_(li, lj) = 0.0;
            if (d <= -2.0 * h || d >= std::max(image_cells_, 1.0) * h) continue;
            // Outward normal: the gradient of the signed distance (central differences).
            const double e = 1e-4 * h;
            Vec2 n(distance(x + Vec2(e, 0)) - distance(x - Vec2(e, 0)),
                   distance(x + Vec2(0, e)) - distance(x - Vec2(0, e)));
            if (n.norm() == 0.0) continue;
            n.normalize();
            band_.push_back({gi, gj, static_cast<int>(b), d, h, x - d * n, n});
        }
}

std::vector<WallSample> ImmersedWall::sample(const Velocity& vel, const Field2D& k) const {
    std::vector<WallSample> out;
    if (band_.empty()) return out;
    const std::vector<Vec2> u = interpolate_velocity(grid_, su_, sv_, vel);
    const std::vector<double> k_image = interpolate(grid_, sk_, k);
    const LocalAxis& lx = grid_.lx();
    const LocalAxis& ly = grid_.ly();
    for (std::size_t m = 0; m < band_.size(); ++m) {
        const BandCell& c = band_[m];
        const int i = c.gi - lx.offset, j = c.gj - ly.offset;
        if (i < 0 || i >= grid_.nx() || j < 0 || j >= grid_.ny()) continue;
        const Vec2 slip = u[m] - bodies_[c.body].velocity_at(c.surface);
        const double speed = std::abs(slip.dot(perp(c.normal)));
        out.push_back({i, j, c.d, c.h, sample_distance(c), speed, k_image[m], c.d >= 0.0 && c.d < c.h});
    }
    return out;
}

}  // namespace chute
