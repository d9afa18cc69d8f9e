#include "cut_faces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "direct_forcing.hpp"  // min_spacing_along

namespace chute {

CutFaces::CutFaces(const Grid& grid, const std::vector<Body>& bodies)
    : grid_(grid),
      bodies_(bodies),
      aperture_u_(grid, 1.0),
      aperture_v_(grid, 1.0),
      open_(grid, 1.0),
      body_velocity_(grid) {}

double surface_distance(const Body& body, const Vec2& point, double tolerance) {
    const double d = body.outline().signed_distance(body.to_body(point));
    return d < tolerance ? std::min(d, -tolerance) : d;
}

namespace {

// The fraction of the segment a-b outside `body`, `a` outside and `b` inside: the crossing by bisection (to 1e-12 of
// the segment), exact for straight and curved surfaces alike; one crossing (a convex body).
double open_fraction(const Body& body, const Vec2& a, const Vec2& b, double tolerance) {
    double out = 0.0, in = 1.0;  // fractions along a-b known outside and inside
    for (int k = 0; k < 40; ++k) {
        const double mid = 0.5 * (out + in);
        (surface_distance(body, a + mid * (b - a), tolerance) < 0.0 ? in : out) = mid;
    }
    return 0.5 * (out + in);
}

}  // namespace

bool CutFaces::update() {
    const bool moves = std::any_of(bodies_.begin(), bodies_.end(), [](const Body& b) { return b.moves(); });
    if (done_ && !moves) return false;
    done_ = true;
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    const int nx = grid_.nx(), ny = grid_.ny();
    // Corners i in [-1, nx + 1], j in [-1, ny + 1]: the signed distance to the nearest surface (inside any body
    // negative), and which body.
    const int cw = nx + 3, ch = ny + 3;
    std::vector<double> phi(static_cast<std::size_t>(cw) * ch, std::numeric_limits<double>::infinity());
    std::vector<int> owner(phi.size(), -1);
    auto at = [&](int i, int j) { return static_cast<std::size_t>(j + 1) * cw + (i + 1); };
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const Body& body = bodies_[b];
        const Outline& outline = body.outline();
        const double tolerance = on_surface_tolerance(min_spacing_along(grid_, body));
        int i0 = -1, i1 = nx + 1, j0 = -1, j1 = ny + 1;
        if (outline.closed()) {
            const Vec2 c = body.state().centre;
            const double reach = outline.reach() + 2.0 * min_spacing_along(grid_, body);  // every cut face's ends
            while (i0 < i1 && X.f(i0 + 1) < c.x() - reach) ++i0;
            while (i1 > i0 && X.f(i1 - 1) > c.x() + reach) --i1;
            while (j0 < j1 && Y.f(j0 + 1) < c.y() - reach) ++j0;
            while (j1 > j0 && Y.f(j1 - 1) > c.y() + reach) --j1;
        }
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const double d = surface_distance(body, Vec2(X.f(i), Y.f(j)), tolerance);
                if (d < phi[at(i, j)]) phi[at(i, j)] = d, owner[at(i, j)] = static_cast<int>(b);
            }
    }
    aperture_u_.fill(1.0);
    aperture_v_.fill(1.0);
    body_velocity_.u.fill(0.0);
    body_velocity_.v.fill(0.0);
    // The ends' corners (i, j) and (i, j + 1) for a u face, (i, j) and (i + 1, j) for a v face.
    auto face = [&](Field2D& alpha, Field2D& U, bool is_u, int i, int j) {
        const int i2 = is_u ? i : i + 1, j2 = is_u ? j + 1 : j;
        const double pa = phi[at(i, j)], pb = phi[at(i2, j2)];
        if (pa >= 0.0 && pb >= 0.0) return;  // open (alpha 1, from the fill)
        const int body = pa <= pb ? owner[at(i, j)] : owner[at(i2, j2)];
        if (pa < 0.0 && pb < 0.0)
            alpha(i, j) = 0.0;
        else {
            const Vec2 A(X.f(i), Y.f(j)), B(X.f(i2), Y.f(j2));
            const double tolerance = on_surface_tolerance(min_spacing_along(grid_, bodies_[body]));
            alpha(i, j) = pa >= 0.0 ? open_fraction(bodies_[body], A, B, tolerance)
                                    : open_fraction(bodies_[body], B, A, tolerance);
        }
        const Vec2 p = is_u ? Vec2(X.f(i), Y.c(j)) : Vec2(X.c(i), Y.f(j));
        const Vec2 v = bodies_[body].velocity_at(p);
        U(i, j) = is_u ? v.x() : v.y();
    };
    for (int j = -1; j <= ny; ++j)
        for (int i = -1; i <= nx + 1; ++i) face(aperture_u_, body_velocity_.u, true, i, j);
    for (int j = -1; j <= ny + 1; ++j)
        for (int i = -1; i <= nx; ++i) face(aperture_v_, body_velocity_.v, false, i, j);
    for (int j = -1; j <= ny; ++j)
        for (int i = -1; i <= nx; ++i)
            open_(i, j) = aperture_u_(i, j) > 0.0 || aperture_u_(i + 1, j) > 0.0 || aperture_v_(i, j) > 0.0 ||
                                  aperture_v_(i, j + 1) > 0.0
                              ? 1.0
                              : 0.0;
    return true;
}

}  // namespace chute
