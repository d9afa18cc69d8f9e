#include "cut_faces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <mpi.h>

#include "direct_forcing.hpp"  // min_spacing_along

namespace chute {

CutFaces::CutFaces(const Grid& grid, const std::vector<Body>& bodies)
    : grid_(grid),
      bodies_(bodies),
      aperture_u_(grid, 1.0),
      aperture_v_(grid, 1.0),
      open_(grid, 1.0),
      body_velocity_(grid),
      owner_u_(grid, -1.0),
      owner_v_(grid, -1.0),
      shut_middle_u_(grid, 0.5),
      shut_middle_v_(grid, 0.5) {}

double surface_distance(const Body& body, const Vec2& point, double tolerance) {
    const double d = body.outline().signed_distance(body.to_body(point));
    return d < tolerance ? std::min(d, -tolerance) : d;
}

// The crossing by bisection (to 1e-12 of the segment), exact for straight and curved surfaces alike; one crossing (a
// convex body).
double open_fraction(const Body& body, const Vec2& a, const Vec2& b, double tolerance) {
    double out = 0.0, in = 1.0;  // fractions along a-b known outside and inside
    for (int k = 0; k < 40; ++k) {
        const double mid = 0.5 * (out + in);
        (surface_distance(body, a + mid * (b - a), tolerance) < 0.0 ? in : out) = mid;
    }
    return 0.5 * (out + in);
}

bool CutFaces::update() {
    const bool moves = std::any_of(bodies_.begin(), bodies_.end(), [](const Body& b) { return b.moves(); });
    // Static bodies once, and again when the grid moved under them (a following window).
    if (!placement_.stale(moves)) return false;
    placement_.computed();
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    const int nx = grid_.nx(), ny = grid_.ny();
    // Corners i in [-1, nx + 1], j in [-1, ny + 1]: the signed distance to the nearest surface (inside any body
    // negative), and which body.
    const int cw = nx + 3, ch = ny + 3;
    std::vector<double> phi(static_cast<std::size_t>(cw) * ch, std::numeric_limits<double>::infinity());
    std::vector<int> owner(phi.size(), -1);
    auto at = [&](int i, int j) { return static_cast<std::size_t>(j + 1) * cw + (i + 1); };
    std::vector<double> spacing, tolerance;  // per body (min_spacing_along reads the whole axis: once per update)
    for (const Body& body : bodies_) {
        spacing.push_back(min_spacing_along(grid_, body));
        tolerance.push_back(on_surface_tolerance(spacing.back()));
    }
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const Body& body = bodies_[b];
        const Outline& outline = body.outline();
        int i0 = -1, i1 = nx + 1, j0 = -1, j1 = ny + 1;
        if (outline.closed()) {
            const Vec2 c = body.state().centre;
            const double reach = outline.reach() + 2.0 * spacing[b];  // every cut face's ends
            while (i0 < i1 && X.f(i0 + 1) < c.x() - reach) ++i0;
            while (i1 > i0 && X.f(i1 - 1) > c.x() + reach) --i1;
            while (j0 < j1 && Y.f(j0 + 1) < c.y() - reach) ++j0;
            while (j1 > j0 && Y.f(j1 - 1) > c.y() + reach) --j1;
        }
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const double d = surface_distance(body, Vec2(X.f(i), Y.f(j)), tolerance[b]);
                if (d < phi[at(i, j)]) phi[at(i, j)] = d, owner[at(i, j)] = static_cast<int>(b);
            }
    }
    aperture_u_.fill(1.0);
    aperture_v_.fill(1.0);
    body_velocity_.u.fill(0.0);
    body_velocity_.v.fill(0.0);
    owner_u_.fill(-1.0);
    owner_v_.fill(-1.0);
    shut_middle_u_.fill(0.5);
    shut_middle_v_.fill(0.5);
    // The ends' corners (i, j) and (i, j + 1) for a u face, (i, j) and (i + 1, j) for a v face.
    auto face = [&](Field2D& alpha, Field2D& U, Field2D& by, Field2D& middle, bool is_u, int i, int j) {
        const int i2 = is_u ? i : i + 1, j2 = is_u ? j + 1 : j;
        const double pa = phi[at(i, j)], pb = phi[at(i2, j2)];
        if (pa >= 0.0 && pb >= 0.0) return;  // open (alpha 1, from the fill)
        const int body = pa <= pb ? owner[at(i, j)] : owner[at(i2, j2)];
        if (pa < 0.0 && pb < 0.0)
            alpha(i, j) = 0.0;
        else {
            const Vec2 A(X.f(i), Y.f(j)), B(X.f(i2), Y.f(j2));
            const double open = pa >= 0.0 ? open_fraction(bodies_[body], A, B, tolerance[body])
                                          : open_fraction(bodies_[body], B, A, tolerance[body]);
            // A crossing within 1e-8 of an end is the on-surface tolerance's reach, not the surface's place (the
            // face beside a corner, on a side's line, its end on the corner: found 1e-9 of a cell along it, in
            // bits that the round-off of the body's place decides): the face is whole, open or shut, so that a
            // body keeping its place on a translating grid cuts the same faces bit for bit (ImmersedBoundary keeps
            // its responses then).
            if (open > 1.0 - kWholeFace) return;  // open (alpha 1, from the fill)
            alpha(i, j) = open < kWholeFace ? 0.0 : open;
            // The shut part runs from the inside end over 1 - alpha of the face.
            if (alpha(i, j) > 0.0) middle(i, j) = pa >= 0.0 ? 1.0 - 0.5 * (1.0 - open) : 0.5 * (1.0 - open);
        }
        by(i, j) = body;
        // The body's velocity at the shut part's middle: the mean of its rigid motion over that part.
        const Vec2 v = bodies_[body].velocity_at(shut_point(is_u, i, j, middle(i, j)));
        U(i, j) = is_u ? v.x() : v.y();
    };
    for (int j = -1; j <= ny; ++j)
        for (int i = -1; i <= nx + 1; ++i) face(aperture_u_, body_velocity_.u, owner_u_, shut_middle_u_, true, i, j);
    for (int j = -1; j <= ny + 1; ++j)
        for (int i = -1; i <= nx; ++i) face(aperture_v_, body_velocity_.v, owner_v_, shut_middle_v_, false, i, j);
    for (int j = -1; j <= ny; ++j)
        for (int i = -1; i <= nx; ++i)
            open_(i, j) = aperture_u_(i, j) > 0.0 || aperture_u_(i + 1, j) > 0.0 || aperture_v_(i, j) > 0.0 ||
                                  aperture_v_(i, j + 1) > 0.0
                              ? 1.0
                              : 0.0;
    return true;
}

Vec2 CutFaces::shut_point(bool is_u, int i, int j, double middle) const {
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    return is_u ? Vec2(X.f(i), Y.f(j) + middle * Y.w(j)) : Vec2(X.f(i) + middle * X.w(i), Y.f(j));
}

Velocity CutFaces::shut_velocity(std::size_t b, const Vec2& U, double omega, const Vec2& centre) const {
    Velocity out(grid_);
    const auto body = static_cast<double>(b);
    auto at = [&](const Vec2& p) -> Vec2 {
        return {U.x() + omega * (centre.y() - p.y()), U.y() + omega * (p.x() - centre.x())};
    };
    for (int j = -kGhost; j < grid_.ny() + kGhost; ++j)
        for (int i = -kGhost; i < grid_.nx() + kGhost; ++i) {
            if (owner_u_(i, j) == body) out.u(i, j) = at(shut_point(true, i, j, shut_middle_u_(i, j))).x();
            if (owner_v_(i, j) == body) out.v(i, j) = at(shut_point(false, i, j, shut_middle_v_(i, j))).y();
        }
    return out;
}

void CutFaces::add_shut_velocity(const Velocity& unit, double scale) {
    for (int j = -kGhost; j < grid_.ny() + kGhost; ++j)
        for (int i = -kGhost; i < grid_.nx() + kGhost; ++i) {
            body_velocity_.u(i, j) += scale * unit.u(i, j);
            body_velocity_.v(i, j) += scale * unit.v(i, j);
        }
}

std::vector<Wrench> CutFaces::pressure_wrenches(const Field2D& q, double density, double depth) const {
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    std::vector<double> sums(3 * bodies_.size(), 0.0);  // force x, y and moment per body
    // Face (i, j) of a cell with pressure qc, its outward normal n (+-1 along its axis).
    auto add = [&](double qc, bool is_u, int i, int j, double n) {
        const Field2D& by = is_u ? owner_u_ : owner_v_;
        if (by(i, j) < 0.0) return;
        const double shut = 1.0 - (is_u ? aperture_u_ : aperture_v_)(i, j);
        if (shut <= 0.0) return;
        const auto b = static_cast<std::size_t>(by(i, j));
        const Vec2 at = shut_point(is_u, i, j, (is_u ? shut_middle_u_ : shut_middle_v_)(i, j));
        const double amount = qc * shut * (is_u ? Y.w(j) : X.w(i)) * n;
        const Vec2 f = is_u ? Vec2(amount, 0.0) : Vec2(0.0, amount);
        sums[3 * b] += f.x();
        sums[3 * b + 1] += f.y();
        sums[3 * b + 2] += cross(at - bodies_[b].state().centre, f);
    };
    for (int j = 0; j < grid_.ny(); ++j)
        for (int i = 0; i < grid_.nx(); ++i) {
            if (open_(i, j) == 0.0) continue;
            const double qc = q(i, j);
            add(qc, true, i, j, -1.0);
            add(qc, true, i + 1, j, 1.0);
            add(qc, false, i, j, -1.0);
            add(qc, false, i, j + 1, 1.0);
        }
    if (grid_.size() > 1)
        MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
    std::vector<Wrench> out(bodies_.size());
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        out[b].force = density * depth * Vec2(sums[3 * b], sums[3 * b + 1]);
        out[b].torque = density * depth * sums[3 * b + 2];
    }
    return out;
}

}  // namespace chute
