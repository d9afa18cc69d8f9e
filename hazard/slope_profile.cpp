#include "slope_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "exact_text.hpp"
#include "text_file.hpp"

namespace chute {

SlopeProfile::SlopeProfile(const std::vector<Vec2>& points, const std::vector<int>& segment_materials,
                           double water_level)
    : water_level_(water_level) {
    if (points.size() < 2) throw std::invalid_argument("a profile needs at least 2 points");
    if (segment_materials.size() + 1 != points.size())
        throw std::invalid_argument("a profile needs one material per segment");
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec2& p = points[i];
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
            throw std::invalid_argument("point " + std::to_string(i) + " is not a finite number");
        if (i == 0) continue;
        const Vec2& q = points[i - 1];
        if (!(p.x() > q.x()))
            throw std::invalid_argument(
                "point " + std::to_string(i) + " (x = " + exact_text(p.x()) + ") " +
                (p.x() == q.x() ? "repeats the x of the point before it (a vertical face: give it a steep segment)"
                                : "folds the profile back on itself (x must increase; the point before has x = " +
                                      exact_text(q.x()) + ")"));
        SlopeSegment s;
        s.start = q, s.end = p;
        s.length = (p - q).norm();
        s.tangent = (p - q) / s.length;
        s.normal = Vec2(-s.tangent.y(), s.tangent.x());
        s.material = segment_materials[i - 1];
        if (s.material < 0) throw std::invalid_argument("segment " + std::to_string(i - 1) + " has no material");
        segments_.push_back(s);
        starts_.push_back(q.x());
    }
}

int SlopeProfile::segment_at(double x) const {
    const auto it = std::upper_bound(starts_.begin(), starts_.end(), x);
    return static_cast<int>(std::max<std::ptrdiff_t>(it - starts_.begin() - 1, 0));
}

double SlopeProfile::height_at(double x) const {
    const SlopeSegment& s = segments_[segment_at(x)];
    return s.start.y() + (x - s.start.x()) * s.tangent.y() / s.tangent.x();
}

double SlopeProfile::clearance(const Vec2& p) const {
    const SlopeSegment& s = segments_[segment_at(p.x())];
    return s.normal.dot(p - s.start);
}

ProfileTable read_profile_csv(const std::filesystem::path& file) {
    ProfileTable table;
    try {
        io::CSVReader<3, io::trim_chars<' ', '\t'>, io::no_quote_escape<','>, io::throw_on_overflow,
                      io::single_line_comment<'#'>>
            in(file.string());
        in.read_header(io::ignore_extra_column, "x", "z", "material");
        double x = 0.0, z = 0.0;
        std::string material;
        while (in.read_row(x, z, material)) {
            table.points.emplace_back(x, z);
            table.materials.push_back(material);
        }
    } catch (const io::error::base& e) {
        throw std::runtime_error(std::string("profile: ") + e.what());
    }
    if (table.points.size() < 2) throw std::runtime_error("profile file " + file.string() + ": fewer than 2 rows");
    return table;
}

}  // namespace chute
