#include "plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "flow_solver.hpp"
#include "outline.hpp"

namespace chute {

namespace {

constexpr double kWaterViscosity = 1.0e-6;  // m^2/s at 20 C
constexpr double kShortestStep = 1.0e-9;    // s
constexpr double kMostSteps = 1.0e8;

std::string number(double v) {
    std::ostringstream s;
    s.precision(4);
    s << v;
    return s.str();
}

bool closed(BodyShape s) { return s == BodyShape::circle || s == BodyShape::rectangle || s == BodyShape::polygon; }

// The narrowest width of a closed body: a circle's diameter, a rectangle's shorter side; for a polygon the
// least extent across its edges' normals (exact for convex outlines, where the narrowest width is always
// measured across an edge).
double narrowest_width(const BodyConfig& b) {
    if (b.shape == BodyShape::circle) return b.diameter;
    if (b.shape == BodyShape::rectangle) return std::min(b.size[0], b.size[1]);
    std::vector<Vec2> v;
    for (const auto& p : b.vertices) v.emplace_back(p[0], p[1]);
    double width = std::numeric_limits<double>::infinity();
    for (std::size_t e = 0; e < v.size(); ++e) {
        const Vec2 edge = v[(e + 1) % v.size()] - v[e];
        if (edge.norm() == 0.0) continue;
        const Vec2 n = perp(edge.normalized());
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const Vec2& p : v) lo = std::min(lo, p.dot(n)), hi = std::max(hi, p.dot(n));
        width = std::min(width, hi - lo);
    }
    return width;
}

Vec2 centre_of(const BodyConfig& b) {
    if (b.shape == BodyShape::circle || b.shape == BodyShape::rectangle) return {b.centre[0], b.centre[1]};
    Vec2 c(0.0, 0.0);
    for (const auto& p : b.vertices) c += Vec2(p[0], p[1]) / static_cast<double>(b.vertices.size());
    return c;
}

// Width of the cell of `axis` holding x (the nearest end cell when x lies outside).
double cell_width_at(const Axis& axis, double x) {
    const auto& lines = axis.lines();
    const auto above = std::upper_bound(lines.begin(), lines.end(), x);
    const int k = std::clamp(static_cast<int>(above - lines.begin()) - 1, 0, axis.cells() - 1);
    return axis.width(k);
}

double finest_cell(const Axis& axis) {
    double h = std::numeric_limits<double>::infinity();
    for (int k = 0; k < axis.cells(); ++k) h = std::min(h, axis.width(k));
    return h;
}

// The fastest speed the case names: inflow, moving walls, the initial current, the bodies' reference and
// prescribed velocities. A still start with free bodies gets its speed from their reference velocity.
double speed_scale(const CaseConfig& c) {
    const auto norm = [](const std::array<double, 2>& v) { return std::hypot(v[0], v[1]); };
    double u = norm(c.initial_velocity);
    if (c.initial == InitialCondition::taylor_green) u = std::max(u, c.taylor_green_amplitude);
    for (const BoundaryConfig& b : c.boundary) u = std::max({u, norm(b.velocity), std::abs(b.peak)});
    for (const BodyConfig& b : c.bodies) {
        if (b.motion.type == MotionType::fixed) continue;
        u = std::max({u, b.reference_velocity, norm(b.motion.velocity)});
        if (b.motion.type == MotionType::oscillation)
            u = std::max(u, 2.0 * std::numbers::pi * b.motion.frequency * norm(b.motion.amplitude));
    }
    return u;
}

bool explicit_diffusion(const CaseConfig& c) {
    return c.diffusion == DiffusionScheme::explicit_ab2 ||
           (c.diffusion == DiffusionScheme::automatic && c.turbulence.model == TurbulenceModelType::laminar);
}

void check_fluid(const CaseConfig& c, std::vector<std::string>& out) {
    if (c.viscosity > 1.0)
        out.push_back("fluid.viscosity: " + number(c.viscosity) + " m^2/s is " + number(c.viscosity / kWaterViscosity) +
                      " times water's; it is the kinematic viscosity in m^2/s (water 1e-06, air 1.5e-05, glycerol "
                      "1e-03): check its units");
    if (c.density < 0.05 || c.density > 2.0e4)
        out.push_back("fluid.density: " + number(c.density) +
                      " kg/m^3 is outside what a fluid has (air 1.2, water 1000, mercury 13 500): check its units");
}

void check_bodies(const CaseConfig& c, const Axis& x, const Axis& y, std::vector<std::string>& out) {
    for (const BodyConfig& b : c.bodies) {
        const std::string key = "bodies." + b.name;
        if (b.motion.type == MotionType::free) {
            if (b.density > 2.5e4)
                out.push_back(key + ".density: " + number(b.density) +
                              " kg/m^3 is denser than any solid (rock 2000-3000, steel 7850): check its units");
            else if (b.density < c.density)
                out.push_back(key + ".density: " + number(b.density) + " kg/m^3 is below fluid.density " +
                              number(c.density) + ": the body is lighter than the fluid and will rise");
        }
        if (!closed(b.shape)) continue;
        const Vec2 at = centre_of(b);
        const double cell = std::max(cell_width_at(x, at.x()), cell_width_at(y, at.y()));
        const double width = narrowest_width(b);
        if (width < 2.0 * cell)
            out.push_back(key + ": the body is " + number(width) + " m across, " + number(width / cell) + " cells of " +
                          number(cell) +
                          " m where it starts; the immersed boundary needs at least 2 (the study's block has "
                          "20): refine domain.x and domain.y there");
    }
}

void check_time_step(const CaseConfig& c, const Axis& x, const Axis& y, std::vector<std::string>& out) {
    const double hx = finest_cell(x), hy = finest_cell(y), speed = speed_scale(c);
    double dt = std::min(c.max_dt, c.end_time);
    std::string limit = "numerics.max_dt";
    if (c.fixed_dt) {
        dt = *c.fixed_dt;
        limit = "numerics.dt";
    } else {
        if (speed > 0.0 && c.cfl * std::min(hx, hy) / speed < dt) {
            dt = c.cfl / (speed / hx + speed / hy);
            limit = "numerics.cfl " + number(c.cfl) + " at " + number(speed) + " m/s on cells of " +
                    number(std::min(hx, hy)) + " m";
        }
        const double diffusive = c.diffusion_number / (c.viscosity * (1.0 / (hx * hx) + 1.0 / (hy * hy)));
        if (explicit_diffusion(c) && diffusive < dt) {
            dt = diffusive;
            limit = "the explicit diffusion limit of fluid.viscosity " + number(c.viscosity) + " m^2/s on cells of " +
                    number(std::min(hx, hy)) + " m (numerics.diffusion_number " + number(c.diffusion_number) + ")";
        }
    }
    const double steps = c.end_time / dt;
    if (dt < kShortestStep || steps > kMostSteps)
        out.push_back("time.end: the time step would be about " + number(dt) + " s (" + limit + "), " + number(steps) +
                      " steps to time.end " + number(c.end_time) + " s; check the units of the keys behind it");
}

void check_gravity(const CaseConfig& c, std::vector<std::string>& out) {
    const bool free_bodies = std::any_of(c.bodies.begin(), c.bodies.end(),
                                         [](const BodyConfig& b) { return b.motion.type == MotionType::free; });
    if (!free_bodies) return;
    const double g = std::hypot(c.gravity[0], c.gravity[1]);
    if (c.gravity[1] > 0.0)
        out.push_back("gravity: [" + number(c.gravity[0]) + ", " + number(c.gravity[1]) +
                      "] m/s^2 points up (+y); the bed is usually below, gravity [0, -9.81]");
    if (g > 100.0) out.push_back("gravity: " + number(g) + " m/s^2 is more than 10 g (Earth 9.81): check its units");
}

// Whether a body's prescribed or free motion has a component along axis k (its rotation aside).
bool moves_along(const MotionConfig& m, int k) {
    switch (m.type) {
        case MotionType::fixed:
            return false;
        case MotionType::free:
            return !m.locked[k];
        case MotionType::constant_velocity:
            return m.velocity[k] != 0.0;
        case MotionType::oscillation:
            return m.amplitude[k] != 0.0;
        case MotionType::uniform_acceleration:
            return m.acceleration[k] != 0.0;
    }
    return true;
}

// The sharp interface beside a turbulence model's wall functions needs ghost faces, and a body that moves across a
// grid at rest smears its boundary layer as its sides cross the cells (docs/limitations.md, "The sharp interface"):
// a window that translates with it along every axis it moves along carries it with the grid. A rectangle whose sides
// lie within cells reads another force than on the lines (a square held in a stream: -9 % to +4 %, against +0.6 %
// aligned; docs/validation.md, "Sharp interface", tenth step).
void check_interface(const CaseConfig& c, const Axis& x, const Axis& y, std::vector<std::string>& out) {
    if (c.ibm.interface != Interface::sharp) return;
    const bool immersed = std::any_of(c.bodies.begin(), c.bodies.end(),
                                      [](const BodyConfig& b) { return b.carrier == CarrierKind::immersed; });
    if (!immersed) return;
    if (c.turbulence.model != TurbulenceModelType::laminar && c.ibm.sharp_faces != IbmConfig::SharpFaces::ghost)
        out.push_back(
            "numerics.ibm.interface: sharp with turbulence.model k_epsilon and numerics.ibm.sharp_faces forcing is not "
            "validated: a square sheds too weakly (the Lyn square's C_D 0.9-1.3 against 2.04 body-fitted); with "
            "sharp_faces: ghost it reads 2.07 (docs/validation.md, \"Sharp interface\")");
    for (const BodyConfig& b : c.bodies) {
        if (b.carrier != CarrierKind::immersed) continue;
        bool crossing = false;
        for (int k = 0; k < 2; ++k) crossing = crossing || (moves_along(b.motion, k) && !b.follow[k]);
        if (crossing)
            out.push_back("bodies." + b.name +
                          ".follow: the sharp interface on a body that moves across a grid at rest is not validated: "
                          "its boundary layer smears as its sides cross the cells (the study's block moved along a "
                          "diagonal reads 34 % less drag than held, face-on a few percent, with a ripple); a window "
                          "that translates with it along every axis it moves along (follow: xy, inflow at rest "
                          "ahead, outflow behind) reads the held drag (docs/limitations.md)");
        const double quarter_turns = b.angle / (0.5 * std::numbers::pi);
        if (b.shape != BodyShape::rectangle || std::abs(quarter_turns - std::round(quarter_turns)) > 1e-9) continue;
        const bool turned = std::lround(quarter_turns) % 2 != 0;
        const double half_x = 0.5 * (turned ? b.size[1] : b.size[0]), half_y = 0.5 * (turned ? b.size[0] : b.size[1]);
        const double off_x =
            std::max(nearest_line(x, b.centre[0] - half_x).cells, nearest_line(x, b.centre[0] + half_x).cells);
        const double off_y =
            std::max(nearest_line(y, b.centre[1] - half_y).cells, nearest_line(y, b.centre[1] + half_y).cells);
        if (off_x > 1e-6 || off_y > 1e-6) {
            std::ostringstream m;
            m.precision(2);
            m << "bodies." << b.name << ".centre: its sides lie within cells (" << off_x
              << " of a cell off the x lines, " << off_y
              << " off the y lines); on the sharp interface a body's force depends on its place within its "
              << "cells (a square held in a stream: -9 % to +4 % off the lines, +0.6 % on them; docs/limitations.md): "
              << "put its sides on grid lines";
            out.push_back(m.str());
        }
    }
}

}  // namespace

std::vector<std::string> plausibility_warnings(const CaseConfig& config) {
    std::vector<std::string> out;
    const Axis x = build_axis(config.x, false), y = build_axis(config.y, false);
    check_fluid(config, out);
    check_bodies(config, x, y, out);
    check_time_step(config, x, y, out);
    check_gravity(config, out);
    check_interface(config, x, y, out);
    return out;
}

}  // namespace chute
