#include "calibration_range.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace chute {

std::vector<std::string> calibration_range_warnings(const HazardCase& c) {
    std::vector<std::string> out;
    const SlopeRebound& law = c.settings.wet_rebound.slope;
    if (!law.measured()) return out;
    const SlopeProfile profile = c.profile();
    constexpr double kSlack = 0.5 * std::numbers::pi / 180.0;  // a calibration at 29.9992 degrees covers 30
    int count = 0;
    double steepest = 0.0, x_first = 0.0, x_last = 0.0;
    for (const SlopeSegment& s : profile.segments()) {
        const double angle = ground_inclination(s.normal);
        // Wet: any part of it under the water (its lower end).
        if (!profile.wet(std::min(s.start.y(), s.end.y())) || angle <= law.angle + kSlack) continue;
        if (count == 0) x_first = s.start.x();
        x_last = s.end.x();
        steepest = std::max(steepest, angle);
        ++count;
    }
    if (count > 0) {
        const double deg = 180.0 / std::numbers::pi;
        std::ostringstream m;
        m.precision(3);
        m << "profile: " << count << " segment(s) under the water between x = " << x_first << " and " << x_last
          << " m are steeper than the " << law.angle * deg << " degrees the calibration's slope law was measured on "
          << "(up to " << steepest * deg << " degrees); their bounces take its " << law.angle * deg
          << " degree values, an extrapolation (on 45 degrees the law gave the study's block a bounce 72 % lower than "
             "the CFD's: docs/limitations.md). model.slope_law=false gives the bed's law instead.";
        out.push_back(m.str());
    }
    return out;
}

}  // namespace chute
