#pragma once
// The slope a hazard analysis runs blocks down: a polyline (x, z) with x strictly increasing (the ground is
// below it), a material per segment, and a water level (segments and flight below it are wet, above it dry,
// so that a block can fall from a cliff into a fjord). A vertical face is given as a steep segment.
//
// Given in the case (`profile.points` with one `profile.material`) or as a CSV file (`profile.file`, columns
// x, z, material: the material of the segment that starts at that point; the last row's is not used).
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace chute {

using Vec2 = Eigen::Vector2d;

// The ground's inclination from the horizontal (rad) for its unit normal out of the ground.
inline double ground_inclination(const Vec2& normal) { return std::acos(std::clamp(normal.y(), -1.0, 1.0)); }

struct SlopeSegment {
    Vec2 start, end;
    Vec2 tangent;  // unit, towards increasing x
    Vec2 normal;   // unit, out of the ground (z > 0 side)
    double length = 0.0;
    int material = 0;
};

class SlopeProfile {
public:
    // Throws std::invalid_argument naming the point (its index, from 0) that is not finite, repeats an x or
    // folds back (x not increasing), or a material index out of range.
    SlopeProfile(const std::vector<Vec2>& points, const std::vector<int>& segment_materials, double water_level);

    const std::vector<SlopeSegment>& segments() const { return segments_; }
    double x_min() const { return segments_.front().start.x(); }
    double x_max() const { return segments_.back().end.x(); }
    double water_level() const { return water_level_; }
    bool wet(double z) const { return z < water_level_; }

    // The segment under x (the one that starts at x at a vertex); x is clamped to the profile.
    int segment_at(double x) const;
    double height_at(double x) const;  // z of the ground under x
    // Signed distance of a point above the ground, normal to the segment under it (0 exactly on the ground).
    double clearance(const Vec2& p) const;

private:
    std::vector<SlopeSegment> segments_;
    std::vector<double> starts_;  // x of each segment's start, for the search
    double water_level_;
};

// Points and per-segment material names of a profile CSV (columns x, z, material; any others ignored). Throws
// std::runtime_error naming the file and line of a malformed row.
struct ProfileTable {
    std::vector<Vec2> points;
    std::vector<std::string> materials;  // one per point; the last is not used
};
ProfileTable read_profile_csv(const std::filesystem::path& file);

}  // namespace chute
