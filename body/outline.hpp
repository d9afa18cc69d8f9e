#pragma once
// The outline of a body in its own frame: a circle, a closed polygon (the block is a rectangle), or an
// open line (a static plane or segment, the sea bed or a slope, with the solid on one side).
//
// Closed outlines are centred on their centroid, so that rotation about the body's reference point is
// rotation about the centre of area. Lagrangian markers are placed about one grid cell apart; each carries
// the length of outline it stands for (its weight in every surface integral) and the outward normal, which
// points into the fluid.
#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace chute {

using Vec2 = Eigen::Vector2d;

// 2D cross product a x b (z component); also omega x r = omega * perp(r).
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
inline Vec2 perp(const Vec2& r) { return {-r.y(), r.x()}; }
inline Vec2 rotated(const Vec2& r, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * r.x() - s * r.y(), s * r.x() + c * r.y()};
}

// The point of an outline nearest to a point p, with the outward normal there and p's signed distance.
struct SurfacePoint {
    Vec2 position;    // on the outline
    Vec2 normal;      // outward unit normal (into the fluid); at a corner, from the corner towards p outside
    double distance;  // signed distance of p, negative inside the solid
};

struct Marker {
    Vec2 position;  // body frame
    Vec2 normal;    // outward unit normal (into the fluid), body frame
    double length;  // outline length this marker stands for (m)
};

class Outline {
public:
    static Outline circle(double diameter);
    // Vertices in any order of traversal; the polygon is shifted so that its centroid is the origin.
    // `centroid` (if not null) receives the centroid of the vertices as given.
    static Outline polygon(std::vector<Vec2> vertices, Vec2* centroid = nullptr);
    static Outline rectangle(double width, double height);
    // An open line from a to b (body frame = world frame: static); the solid lies on its right.
    static Outline segment(const Vec2& a, const Vec2& b);

    bool closed() const { return kind_ != Kind::segment; }

    double perimeter() const;
    double area() const;          // 0 for an open line
    double polar_moment() const;  // integral of |r|^2 over the area about the centroid (m^4)
    double reach() const;         // largest distance of the outline from the body-frame origin
    // The point of the outline farthest along the direction d (body frame): a corner of a polygon, the
    // point of a circle where d is the outward normal. Contact detection finds a body's lowest point with it.
    Vec2 support_point(const Vec2& d) const;
    // Markers spaced at most `spacing` apart, evenly along each edge (circle: along the arc).
    std::vector<Marker> markers(double spacing) const;
    // The part of the solid inside the axis-aligned box [lo, hi] of the world, the outline placed with its origin at
    // `centre` and turned by `angle` (closed outlines; nothing for an open line): its area and its first moment about
    // `centre`, the integral of (x - centre) over it. Exact for a polygon (clipped by the box, Sutherland & Hodgman
    // 1974, then the shoelace sums) and a circle (the disk's quadrants, by inclusion and exclusion). Over boxes that
    // tile the plane the parts add up to area() and a zero moment to round-off wherever the body lies, so that a
    // control volume's part inside a moving body is a state of the body's place with no error that changes with it
    // (SharpForcing::held_momentum).
    struct Part {
        double area = 0.0;
        Vec2 moment = Vec2::Zero();
    };
    Part part_in_box(const Vec2& centre, double angle, const Vec2& lo, const Vec2& hi) const;
    // Is the body-frame point inside the solid (closed outlines), or on its solid side (open lines)?
    bool contains(const Vec2& p) const;
    // Signed distance to the outline, negative inside the solid.
    double signed_distance(const Vec2& p) const;
    // The nearest point of the outline to p (an open line: of the infinite line through it, as signed_distance).
    // Outside a polygon's corner the normal points from the corner to p, so X_s + |d| n = p everywhere outside.
    SurfacePoint nearest(const Vec2& p) const;

private:
    enum class Kind { circle, polygon, segment };
    Kind kind_ = Kind::circle;
    double radius_ = 0.0;
    std::vector<Vec2> vertices_;
};

}  // namespace chute
