#include "hole.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace chute {

namespace {

// The index of the grid line at x, or an error naming the side and the nearest lines.
int line_at(const Axis& axis, double x, const std::string& body, const char* side, const char* key) {
    const NearestLine n = nearest_line(axis, x);
    if (n.cells <= 1e-6) return n.index;
    const auto& L = axis.lines();
    std::ostringstream m;
    m << "bodies." << body << ": its " << side << " side at " << x << " m is not on a grid line (nearest lines "
      << L[n.below] << " and " << L[n.above] << " m); a body_fitted body needs its sides on lines of `" << key << "`";
    throw std::invalid_argument(m.str());
}

}  // namespace

SolidBlock hole_of(const Body& body, const Grid& grid) {
    const BodyConfig& c = body.config();
    const std::string& name = body.name();
    if (c.shape != BodyShape::rectangle)
        throw std::invalid_argument("bodies." + name + ".carrier: `body_fitted` carries rectangles only (shape `" +
                                    (c.shape == BodyShape::circle ? std::string("circle") : std::string("other")) +
                                    "`)");
    if (c.angle != 0.0 || body.state().angle != 0.0)
        throw std::invalid_argument("bodies." + name +
                                    ".angle: a body_fitted rectangle is not rotated (its sides lie on grid lines)");
    const Vec2 centre = body.state().centre;
    const double hw = 0.5 * c.size[0], hh = 0.5 * c.size[1];
    const Axis& X = grid.x_axis();
    const Axis& Y = grid.y_axis();
    SolidBlock b;
    b.lower = {line_at(X, centre.x() - hw, name, "left", "domain.x"),
               line_at(Y, centre.y() - hh, name, "bottom", "domain.y")};
    b.upper = {line_at(X, centre.x() + hw, name, "right", "domain.x"),
               line_at(Y, centre.y() + hh, name, "top", "domain.y")};
    b.velocity = {body.state().velocity.x(), body.state().velocity.y()};
    return b;
}

std::vector<SideCell> side_cells(const Grid& grid, const SolidBlock& hole, const Velocity& vel) {
    const Axis& X = grid.x_axis();
    const Axis& Y = grid.y_axis();
    const int ox = grid.lx().offset, oy = grid.ly().offset;
    auto owned = [&](int i, int j) { return i >= 0 && i < grid.nx() && j >= 0 && j < grid.ny(); };
    std::vector<SideCell> out;
    for (const bool top : {false, true}) {  // segments along x, the fluid row below / above; u is tangential
        const int gj = top ? hole.upper[1] : hole.lower[1] - 1;
        const double wall = Y.line(top ? hole.upper[1] : hole.lower[1]);
        for (int gi = hole.lower[0]; gi < hole.upper[0]; ++gi) {
            const int i = gi - ox, j = gj - oy;
            if (!owned(i, j)) continue;
            const double u = 0.5 * (vel.u(i, j) + vel.u(i + 1, j)) - hole.velocity[0];
            out.push_back({i, j, Vec2(0.0, top ? 1.0 : -1.0), Vec2(X.centre(gi), wall), 0.5 * Y.width(gj), X.width(gi),
                           Vec2(u, 0.0)});
        }
    }
    for (const bool right : {false, true}) {  // segments along y, the fluid column left / right; v is tangential
        const int gi = right ? hole.upper[0] : hole.lower[0] - 1;
        const double wall = X.line(right ? hole.upper[0] : hole.lower[0]);
        for (int gj = hole.lower[1]; gj < hole.upper[1]; ++gj) {
            const int i = gi - ox, j = gj - oy;
            if (!owned(i, j)) continue;
            const double v = 0.5 * (vel.v(i, j) + vel.v(i, j + 1)) - hole.velocity[1];
            out.push_back({i, j, Vec2(right ? 1.0 : -1.0, 0.0), Vec2(wall, Y.centre(gj)), 0.5 * X.width(gi),
                           Y.width(gj), Vec2(0.0, v)});
        }
    }
    return out;
}

}  // namespace chute
