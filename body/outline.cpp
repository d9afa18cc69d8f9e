#include "outline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace chute {

Outline Outline::circle(double diameter) {
    if (!(diameter > 0.0)) throw std::invalid_argument("circle: diameter must be positive");
    Outline o;
    o.kind_ = Kind::circle;
    o.radius_ = 0.5 * diameter;
    return o;
}

Outline Outline::polygon(std::vector<Vec2> v, Vec2* centroid) {
    if (v.size() < 3) throw std::invalid_argument("polygon: needs at least 3 vertices");
    // Shoelace area and centroid.
    double a2 = 0.0;
    Vec2 c = Vec2::Zero();
    for (std::size_t k = 0; k < v.size(); ++k) {
        const Vec2& p = v[k];
        const Vec2& q = v[(k + 1) % v.size()];
        const double w = cross(p, q);
        a2 += w;
        c += w * (p + q);
    }
    if (std::abs(a2) < 1e-300) throw std::invalid_argument("polygon: vertices enclose no area");
    c /= 3.0 * a2;
    if (a2 < 0.0) std::reverse(v.begin(), v.end());  // counterclockwise: outward normal on the right
    for (Vec2& p : v) p -= c;
    if (centroid) *centroid = c;
    Outline o;
    o.kind_ = Kind::polygon;
    o.vertices_ = std::move(v);
    return o;
}

Outline Outline::rectangle(double width, double height) {
    if (!(width > 0.0 && height > 0.0)) throw std::invalid_argument("rectangle: sides must be positive");
    const double a = 0.5 * width, b = 0.5 * height;
    return polygon({{-a, -b}, {a, -b}, {a, b}, {-a, b}});
}

Outline Outline::segment(const Vec2& a, const Vec2& b) {
    if ((b - a).norm() <= 0.0) throw std::invalid_argument("segment: the two ends coincide");
    Outline o;
    o.kind_ = Kind::segment;
    o.vertices_ = {a, b};
    return o;
}

double Outline::perimeter() const {
    if (kind_ == Kind::circle) return 2.0 * std::numbers::pi * radius_;
    if (kind_ == Kind::segment) return (vertices_[1] - vertices_[0]).norm();
    double s = 0.0;
    for (std::size_t k = 0; k < vertices_.size(); ++k)
        s += (vertices_[(k + 1) % vertices_.size()] - vertices_[k]).norm();
    return s;
}

double Outline::area() const {
    if (kind_ == Kind::circle) return std::numbers::pi * radius_ * radius_;
    if (kind_ == Kind::segment) return 0.0;
    double a2 = 0.0;
    for (std::size_t k = 0; k < vertices_.size(); ++k) a2 += cross(vertices_[k], vertices_[(k + 1) % vertices_.size()]);
    return 0.5 * a2;
}

double Outline::polar_moment() const {
    if (kind_ == Kind::circle) return 0.5 * std::numbers::pi * std::pow(radius_, 4);
    if (kind_ == Kind::segment) return 0.0;
    // Sum over the triangles (0, p, q): (Ix + Iy) = (1/12) sum w (p.p + p.q + q.q), w = p x q.
    double j = 0.0;
    for (std::size_t k = 0; k < vertices_.size(); ++k) {
        const Vec2& p = vertices_[k];
        const Vec2& q = vertices_[(k + 1) % vertices_.size()];
        j += cross(p, q) * (p.dot(p) + p.dot(q) + q.dot(q));
    }
    return j / 12.0;
}

namespace {

// The part of the disk of radius r about the origin where X <= x and Y <= y: its area and first moment. Over X the
// chord at X, |Y| <= s(X) = sqrt(r^2 - X^2), lies whole below y where s < y, is cut by y where |y| <= s (|X| <= a,
// a = sqrt(r^2 - y^2)), and lies above it where s < -y. S and T are the integrals of s and 2 X s from -r.
Outline::Part disk_quadrant(double r, double x, double y) {
    const auto clamped = [r](double X) { return std::clamp(X, -r, r); };
    const auto S = [&](double X) {
        X = clamped(X);
        return 0.5 * (X * std::sqrt(std::max(r * r - X * X, 0.0)) + r * r * std::asin(X / r)) +
               0.25 * std::numbers::pi * r * r;
    };
    const auto T = [&](double X) {
        X = clamped(X);
        return -2.0 / 3.0 * std::pow(std::max(r * r - X * X, 0.0), 1.5);
    };
    Outline::Part part;
    x = std::min(x, r);
    if (x <= -r || y <= -r) return part;
    if (y >= r) {
        part.area = 2.0 * S(x);
        part.moment.x() = T(x);
        return part;
    }
    const double a = std::sqrt(r * r - y * y);
    if (y > 0.0) {  // whole chords, symmetric about Y = 0
        const double left = std::min(x, -a);
        part.area += 2.0 * S(left);
        part.moment.x() += T(left);
        if (x > a) {
            part.area += 2.0 * (S(x) - S(a));
            part.moment.x() += T(x) - T(a);
        }
    }
    if (x > -a) {  // chords cut by y: Y from -s to y
        const double m = std::min(x, a);
        part.area += y * (m + a) + S(m) - S(-a);
        part.moment.x() += 0.5 * y * (m * m - a * a) + 0.5 * (T(m) - T(-a));
        part.moment.y() += 0.5 * ((y * y - r * r) * (m + a) + (m * m * m + a * a * a) / 3.0);
    }
    return part;
}

// The part of the polygon `p` on the side of the line X[axis] = at that `keep_below` names (Sutherland & Hodgman).
std::vector<Vec2> clipped(const std::vector<Vec2>& p, int axis, double at, bool keep_below) {
    std::vector<Vec2> out;
    out.reserve(p.size() + 2);
    const auto inside = [&](const Vec2& q) { return keep_below ? q[axis] <= at : q[axis] >= at; };
    for (std::size_t k = 0; k < p.size(); ++k) {
        const Vec2& a = p[k];
        const Vec2& b = p[(k + 1) % p.size()];
        if (inside(a)) out.push_back(a);
        if (inside(a) != inside(b)) {
            const double t = (at - a[axis]) / (b[axis] - a[axis]);
            Vec2 q = a + t * (b - a);
            q[axis] = at;
            out.push_back(q);
        }
    }
    return out;
}

}  // namespace

Outline::Part Outline::part_in_box(const Vec2& centre, double angle, const Vec2& lo, const Vec2& hi) const {
    Part part;
    if (kind_ == Kind::segment || !(hi.x() > lo.x() && hi.y() > lo.y())) return part;
    const Vec2 a = lo - centre, b = hi - centre;  // the box about the centre
    if (kind_ == Kind::circle) {
        const Part q[4] = {disk_quadrant(radius_, b.x(), b.y()), disk_quadrant(radius_, a.x(), b.y()),
                           disk_quadrant(radius_, b.x(), a.y()), disk_quadrant(radius_, a.x(), a.y())};
        part.area = std::max(q[0].area - q[1].area - q[2].area + q[3].area, 0.0);
        part.moment = q[0].moment - q[1].moment - q[2].moment + q[3].moment;
        return part;
    }
    // Counterclockwise (Outline::polygon) and still so once turned and clipped: the signed sums are the part's.
    const double c = std::cos(angle), s = std::sin(angle);  // once for all vertices (as rotated() turns them)
    std::vector<Vec2> p;
    p.reserve(vertices_.size());
    for (const Vec2& v : vertices_) p.push_back({c * v.x() - s * v.y(), s * v.x() + c * v.y()});
    for (int axis = 0; axis < 2 && !p.empty(); ++axis) {
        p = clipped(p, axis, a[axis], false);
        if (!p.empty()) p = clipped(p, axis, b[axis], true);
    }
    for (std::size_t k = 0; k < p.size(); ++k) {
        const Vec2& v = p[k];
        const Vec2& w = p[(k + 1) % p.size()];
        const double twice = cross(v, w);  // twice the triangle (0, v, w)
        part.area += 0.5 * twice;
        part.moment += (v + w) * (twice / 6.0);
    }
    return part;
}

Vec2 Outline::support_point(const Vec2& d) const {
    if (kind_ == Kind::circle) return radius_ * d.normalized();
    Vec2 best = vertices_.front();
    for (const Vec2& v : vertices_)
        if (v.dot(d) > best.dot(d)) best = v;
    return best;
}

double Outline::reach() const {
    if (kind_ == Kind::circle) return radius_;
    double r = 0.0;
    for (const Vec2& v : vertices_) r = std::max(r, v.norm());
    return r;
}

std::vector<Marker> Outline::markers(double spacing) const {
    if (!(spacing > 0.0)) throw std::invalid_argument("markers: spacing must be positive");
    std::vector<Marker> m;
    if (kind_ == Kind::circle) {
        const int n = std::max(8, static_cast<int>(std::ceil(perimeter() / spacing)));
        const double ds = perimeter() / n;
        for (int k = 0; k < n; ++k) {
            const double t = 2.0 * std::numbers::pi * k / n;
            const Vec2 normal(std::cos(t), std::sin(t));
            m.push_back({radius_ * normal, normal, ds});
        }
        return m;
    }
    // Edges: markers at the midpoints of equal sub-segments, so none sits on a corner and each edge's
    // length is shared exactly; the outward normal of a counterclockwise edge p -> q is on its right.
    const std::size_t edges = kind_ == Kind::segment ? 1 : vertices_.size();
    for (std::size_t k = 0; k < edges; ++k) {
        const Vec2& p = vertices_[k];
        const Vec2& q = vertices_[(k + 1) % vertices_.size()];
        const double len = (q - p).norm();
        const int n = std::max(1, static_cast<int>(std::ceil(len / spacing)));
        const Vec2 t = (q - p) / len;
        const Vec2 normal(t.y(), -t.x());
        // A segment's solid is on its right, so its outward (fluid-side) normal is on its left.
        const Vec2 out = kind_ == Kind::segment ? Vec2(-normal) : normal;
        for (int s = 0; s < n; ++s) m.push_back({p + (s + 0.5) / n * (q - p), out, len / n});
    }
    return m;
}

bool Outline::contains(const Vec2& p) const { return signed_distance(p) < 0.0; }

double Outline::signed_distance(const Vec2& p) const {
    if (kind_ == Kind::circle) return p.norm() - radius_;
    if (kind_ == Kind::segment) {
        // Distance to the infinite line, negative on the solid (right) side.
        const Vec2 t = (vertices_[1] - vertices_[0]).normalized();
        return cross(t, p - vertices_[0]);
    }
    double d = std::numeric_limits<double>::infinity();
    bool inside = false;
    for (std::size_t k = 0, l = vertices_.size() - 1; k < vertices_.size(); l = k++) {
        const Vec2& a = vertices_[l];
        const Vec2& b = vertices_[k];
        const Vec2 e = b - a;
        const double s = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
        d = std::min(d, (p - a - s * e).norm());
        if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) / (b.y() - a.y()) * e.x())
            inside = !inside;
    }
    return inside ? -d : d;
}

SurfacePoint Outline::nearest(const Vec2& p) const {
    if (kind_ == Kind::circle) {
        const double r = p.norm();
        const Vec2 n = r > 0.0 ? Vec2(p / r) : Vec2(1.0, 0.0);
        return {radius_ * n, n, r - radius_};
    }
    if (kind_ == Kind::segment) {
        const Vec2 t = (vertices_[1] - vertices_[0]).normalized();
        const Vec2 out(-t.y(), t.x());  // the fluid (left) side
        const double d = cross(t, p - vertices_[0]);
        return {p - d * out, out, d};
    }
    // The nearest point over the edges; on an edge's interior the normal is the edge's, at a vertex the direction
    // to p (the distance field's gradient), or the mean of the two edges' normals when p is on the vertex.
    SurfacePoint best{Vec2::Zero(), Vec2::Zero(), std::numeric_limits<double>::infinity()};
    std::size_t best_edge = 0;
    double best_s = 0.0;
    for (std::size_t k = 0, l = vertices_.size() - 1; k < vertices_.size(); l = k++) {
        const Vec2& a = vertices_[l];
        const Vec2 e = vertices_[k] - a;
        const double s = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
        const double d = (p - a - s * e).norm();
        if (d < best.distance) best = {a + s * e, Vec2::Zero(), d}, best_edge = l, best_s = s;
    }
    auto edge_normal = [&](std::size_t l) {
        const Vec2 e = (vertices_[(l + 1) % vertices_.size()] - vertices_[l]).normalized();
        return Vec2(e.y(), -e.x());  // counterclockwise: outward on the right
    };
    const double d = signed_distance(p);
    const Vec2 n_edge = edge_normal(best_edge);
    if (best_s > 0.0 && best_s < 1.0)
        best.normal = n_edge;
    else if (best.distance > 1e-12 * reach())
        best.normal = (d > 0.0 ? 1.0 : -1.0) * (p - best.position) / best.distance;
    else {
        const std::size_t other =
            best_s == 0.0 ? (best_edge + vertices_.size() - 1) % vertices_.size() : (best_edge + 1) % vertices_.size();
        best.normal = (n_edge + edge_normal(other)).normalized();
    }
    best.distance = d;
    return best;
}

}  // namespace chute
