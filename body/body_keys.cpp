// The bodies' section of the case-file schema (body_config.hpp) and its reading: the keys as data, checked and
// typed by the generic reader (io/case_reader.hpp); then the checks inside one body.
#include <algorithm>
#include <cmath>

#include "body_config.hpp"
#include "case_reader.hpp"

namespace chute {

std::vector<CaseKey> body_keys() {
    using K = KeyType;
    return {
        {.path = "bodies",
         .type = K::section,
         .meaning = "Immersed bodies, each under a name of its choosing (letters, digits, _ and -); the "
                    "name labels its output file `body_<name>.csv`. No bodies: no forcing."},
        {.path = "bodies.<body>", .type = K::section, .meaning = "One body."},
        {.path = "bodies.<body>.shape",
         .type = K::choice,
         .required = true,
         .choices = {"circle", "rectangle", "polygon", "plane", "segment"},
         .meaning = "`circle`; `rectangle` (the block); `polygon` (any closed outline); `plane` (a static "
                    "straight boundary across the domain: a bed or a slope); `segment` (a static straight "
                    "piece of boundary between two points). Planes and segments have their solid on the "
                    "right of their direction: a plane at angle 0 has its solid below."},
        {.path = "bodies.<body>.centre",
         .type = K::vector2,
         .required = true,
         .when_key = "shape",
         .when_values = {"circle", "rectangle"},
         .units = "m",
         .meaning = "Initial centre of the circle or rectangle."},
        {.path = "bodies.<body>.diameter",
         .type = K::number,
         .required = true,
         .min = above(0),
         .when_key = "shape",
         .when_values = {"circle"},
         .units = "m",
         .meaning = "Diameter of the circle."},
        {.path = "bodies.<body>.size",
         .type = K::vector2,
         .required = true,
         .min = above(0),
         .when_key = "shape",
         .when_values = {"rectangle"},
         .units = "m",
         .meaning = "Width (along x before rotation) and height of the rectangle."},
        {.path = "bodies.<body>.vertices",
         .type = K::point_list,
         .required = true,
         .when_key = "shape",
         .when_values = {"polygon"},
         .units = "m",
         .meaning = "Corners of the polygon in place, in order around it (either way round); at least 3. Its "
                    "centre is its centroid."},
        {.path = "bodies.<body>.angle",
         .type = K::number,
         .default_value = "0.0",
         .when_key = "shape",
         .when_values = {"rectangle", "polygon", "plane"},
         .units = "deg",
         .meaning = "Rectangle, polygon: initial rotation about the centre, counterclockwise. Plane: "
                    "inclination of its direction from the x axis (0: a horizontal bed, solid below; 30: a "
                    "slope rising to the right, solid below it)."},
        {.path = "bodies.<body>.point",
         .type = K::vector2,
         .required = true,
         .when_key = "shape",
         .when_values = {"plane"},
         .units = "m",
         .meaning = "A point of the plane, inside the domain."},
        {.path = "bodies.<body>.from",
         .type = K::vector2,
         .required = true,
         .when_key = "shape",
         .when_values = {"segment"},
         .units = "m",
         .meaning = "First end of the segment."},
        {.path = "bodies.<body>.to",
         .type = K::vector2,
         .required = true,
         .when_key = "shape",
         .when_values = {"segment"},
         .units = "m",
         .meaning = "Second end of the segment; the solid lies on the right going from `from` to `to`."},
        {.path = "bodies.<body>.carrier",
         .type = K::choice,
         .default_value = "immersed",
         .choices = {"immersed", "body_fitted"},
         .meaning = "How the flow carries the body (docs/design.md): `immersed`, markers and forcing on the fixed "
                    "grid; `body_fitted`, a hole in the grid (an unrotated rectangle whose sides lie on grid lines; "
                    "fixed, or moving, prescribed or free with its rotation locked, the grid carried along). Every "
                    "body of a run is carried the same way."},
        {.path = "bodies.<body>.grid_motion",
         .type = K::choice,
         .default_value = "translate",
         .choices = {"translate", "layers"},
         .when_key = "carrier",
         .when_values = {"body_fitted"},
         .meaning = "How the grid follows a moving body_fitted body: `translate`, the whole grid moves with it (the "
                    "domain's boundaries too: no walls across its motion); `layers`, the lines around it (its window "
                    "and their growth up to the far-field width) move with it, the lines beyond stay, and the layer "
                    "of cells between them on each side stretches and is added or removed as the body goes (the "
                    "study's mesh modifiers, band/layers.hpp): the domain and its walls stay put, and the body can "
                    "travel any distance the domain holds. `layers` needs cells of the far-field width (spacing "
                    "clustered with `max`) between the window and the domain's ends."},
        {.path = "bodies.<body>.follow",
         .type = K::choice,
         .default_value = "none",
         .choices = {"none", "x", "y", "xy"},
         .when_key = "carrier",
         .when_values = {"immersed"},
         .meaning = "The grid follows this moving body along these axes (a window that follows the block, "
                    "run/following_frame.hpp), and the domain is a window a few body lengths around it instead of "
                    "its whole path. With `numerics.ibm.interface: sharp` the grid translates with the body, so "
                    "that the body keeps its place against the cells (a sharp surface moving oblique to a grid at "
                    "rest smears its boundary layer: docs/validation.md); with the diffuse interface it moves by "
                    "whole cells between steps so that the body stays within a cell of where it started on it, "
                    "and the followed axes must be uniform. The boundaries across the motion move with the "
                    "window: an `inflow` at velocity [0, 0] is the water at rest ahead (give it 7 or more body "
                    "sizes), an `outflow` lets the wake out behind at the speed relative to the window; no walls "
                    "across the motion. Velocities, positions and fields are those of the fixed frame. One body "
                    "at most."},
        {.path = "bodies.<body>.motion",
         .type = K::section,
         .meaning = "Prescribed motion of the centre and angle (closed shapes only; planes and segments are "
                    "fixed)."},
        {.path = "bodies.<body>.motion.type",
         .type = K::choice,
         .default_value = "fixed",
         .choices = {"fixed", "constant_velocity", "oscillation", "uniform_acceleration", "free"},
         .meaning = "`fixed`; `constant_velocity`: x = x0 + V t; `oscillation`: x = x0 + A sin(2 pi f t + "
                    "phase); `uniform_acceleration` from rest: x = x0 + a t^2/2. The angle follows the same "
                    "law with its own rate, amplitude or acceleration. `free`: moved by gravity, buoyancy, the "
                    "fluid and contact (needs `density`); `velocity` and `angular_velocity` are its start."},
        {.path = "bodies.<body>.motion.lock_x",
         .type = K::boolean,
         .default_value = "false",
         .when_key = "type",
         .when_values = {"free"},
         .meaning = "Keep the free body from moving along x."},
        {.path = "bodies.<body>.motion.lock_y",
         .type = K::boolean,
         .default_value = "false",
         .when_key = "type",
         .when_values = {"free"},
         .meaning = "Keep the free body from moving along y."},
        {.path = "bodies.<body>.motion.lock_rotation",
         .type = K::boolean,
         .default_value = "false",
         .when_key = "type",
         .when_values = {"free"},
         .meaning = "Keep the free body from turning (Turmel & Locat 2008 locked rotation)."},
        {.path = "bodies.<body>.motion.velocity",
         .type = K::vector2,
         .default_value = "[0.0, 0.0]",
         .when_key = "type",
         .when_values = {"constant_velocity", "free"},
         .units = "m/s",
         .meaning = "Velocity V of the centre (`free`: at the start)."},
        {.path = "bodies.<body>.motion.angular_velocity",
         .type = K::number,
         .default_value = "0.0",
         .when_key = "type",
         .when_values = {"constant_velocity", "free"},
         .units = "rad/s",
         .meaning = "Angular velocity, counterclockwise (`free`: at the start)."},
        {.path = "bodies.<body>.motion.amplitude",
         .type = K::vector2,
         .default_value = "[0.0, 0.0]",
         .when_key = "type",
         .when_values = {"oscillation"},
         .units = "m",
         .meaning = "Amplitude A of the centre's oscillation (a negative component reverses its phase)."},
        {.path = "bodies.<body>.motion.angular_amplitude",
         .type = K::number,
         .default_value = "0.0",
         .when_key = "type",
         .when_values = {"oscillation"},
         .units = "deg",
         .meaning = "Amplitude of the angle's oscillation."},
        {.path = "bodies.<body>.motion.frequency",
         .type = K::number,
         .required = true,
         .min = above(0),
         .when_key = "type",
         .when_values = {"oscillation"},
         .units = "Hz",
         .meaning = "Frequency f of the oscillation."},
        {.path = "bodies.<body>.motion.phase",
         .type = K::number,
         .default_value = "0.0",
         .when_key = "type",
         .when_values = {"oscillation"},
         .units = "deg",
         .meaning = "Phase of the oscillation at t = 0."},
        {.path = "bodies.<body>.motion.acceleration",
         .type = K::vector2,
         .default_value = "[0.0, 0.0]",
         .when_key = "type",
         .when_values = {"uniform_acceleration"},
         .units = "m/s^2",
         .meaning = "Acceleration a of the centre."},
        {.path = "bodies.<body>.motion.angular_acceleration",
         .type = K::number,
         .default_value = "0.0",
         .when_key = "type",
         .when_values = {"uniform_acceleration"},
         .units = "rad/s^2",
         .meaning = "Angular acceleration, counterclockwise."},
        {.path = "bodies.<body>.density",
         .type = K::number,
         .min = above(0),
         .units = "kg/m^3",
         .meaning = "Density of a free body (the study's rocks: 2400-2700). Required with motion type `free`."},
        {.path = "bodies.<body>.reference",
         .type = K::section,
         .meaning = "Scales of the force coefficients C = F / (0.5 rho U^2 L depth) in the body's time "
                    "series."},
        {.path = "bodies.<body>.reference.velocity",
         .type = K::number,
         .default_value = "1.0",
         .min = above(0),
         .units = "m/s",
         .meaning = "Reference speed U."},
        {.path = "bodies.<body>.reference.length",
         .type = K::number,
         .default_doc = "size across x",
         .min = above(0),
         .units = "m",
         .meaning = "Reference length L. Default: the body's height (its extent across the x direction): "
                    "a circle's diameter, a rectangle's height; a plane's or segment's length."},
    };
}

std::vector<Placeholder> body_placeholders() { return {{"<body>"}}; }

std::string placement_key(const BodyConfig& b) {
    return "bodies." + b.name +
           (b.shape == BodyShape::plane     ? ".point"
            : b.shape == BodyShape::segment ? ".from"
            : b.shape == BodyShape::polygon ? ".vertices"
                                            : ".centre");
}

std::vector<std::array<double, 2>> placement_points(const BodyConfig& b) {
    switch (b.shape) {
        case BodyShape::circle: {
            const double r = 0.5 * b.diameter;
            return {{b.centre[0] - r, b.centre[1] - r}, {b.centre[0] + r, b.centre[1] + r}};
        }
        case BodyShape::rectangle: {
            const double cs = std::cos(b.angle), sn = std::sin(b.angle);
            std::vector<std::array<double, 2>> corners;
            for (const double sx : {-0.5, 0.5})
                for (const double sy : {-0.5, 0.5}) {
                    const double x = sx * b.size[0], y = sy * b.size[1];
                    corners.push_back({b.centre[0] + cs * x - sn * y, b.centre[1] + sn * x + cs * y});
                }
            return corners;
        }
        case BodyShape::polygon:
            return b.vertices;  // the rotation about the centroid is checked by the solver
        case BodyShape::plane:
            return {b.point};
        case BodyShape::segment:
            return {b.from, b.to};
    }
    return {};
}

std::vector<BodyConfig> read_bodies(const CaseReader& r, double plane_reference_length) {
    constexpr double deg = 3.14159265358979323846 / 180.0;
    std::vector<BodyConfig> bodies;
    for (const std::string& p : r.instances("bodies.<body>")) {
        BodyConfig b;
        b.name = p.substr(p.rfind('.') + 1);
        b.shape = r.choice<BodyShape>(p + ".shape", {{"circle", BodyShape::circle},
                                                     {"rectangle", BodyShape::rectangle},
                                                     {"polygon", BodyShape::polygon},
                                                     {"plane", BodyShape::plane},
                                                     {"segment", BodyShape::segment}});
        b.carrier = r.choice<CarrierKind>(
            p + ".carrier", {{"immersed", CarrierKind::immersed}, {"body_fitted", CarrierKind::body_fitted}});
        if (b.carrier == CarrierKind::body_fitted)
            b.layers = r.choice<bool>(p + ".grid_motion", {{"translate", false}, {"layers", true}});
        else
            b.follow = r.choice<std::array<bool, 2>>(
                p + ".follow",
                {{"none", {false, false}}, {"x", {true, false}}, {"y", {false, true}}, {"xy", {true, true}}});
        const bool closed =
            b.shape == BodyShape::circle || b.shape == BodyShape::rectangle || b.shape == BodyShape::polygon;
        // The height: the extent across x, the default reference length.
        const auto y_extent = [](const std::vector<std::array<double, 2>>& points) {
            double ymin = 1e300, ymax = -1e300;
            for (const auto& q : points) ymin = std::min(ymin, q[1]), ymax = std::max(ymax, q[1]);
            return ymax - ymin;
        };
        double height = 0.0;
        if (b.shape == BodyShape::circle || b.shape == BodyShape::rectangle) b.centre = r.vector2(p + ".centre");
        if (b.shape == BodyShape::rectangle || b.shape == BodyShape::polygon || b.shape == BodyShape::plane)
            b.angle = r.number(p + ".angle") * deg;
        switch (b.shape) {
            case BodyShape::circle:
                b.diameter = r.number(p + ".diameter");
                height = b.diameter;
                break;
            case BodyShape::rectangle:
                b.size = r.vector2(p + ".size");
                height = y_extent(placement_points(b));
                break;
            case BodyShape::polygon: {
                b.vertices = r.point_list(p + ".vertices");
                if (b.vertices.size() < 3)
                    r.fail(p + ".vertices",
                           "a polygon needs at least 3 corners, got " + std::to_string(b.vertices.size()));
                double a2 = 0.0;
                for (std::size_t k = 0; k < b.vertices.size(); ++k) {
                    const auto& v = b.vertices[k];
                    const auto& w = b.vertices[(k + 1) % b.vertices.size()];
                    a2 += v[0] * w[1] - v[1] * w[0];
                }
                if (std::abs(a2) < 1e-14) r.fail(p + ".vertices", "the corners enclose no area");
                height = y_extent(b.vertices);
                break;
            }
            case BodyShape::plane:
                b.point = r.vector2(p + ".point");
                height = plane_reference_length;
                break;
            case BodyShape::segment:
                b.from = r.vector2(p + ".from");
                b.to = r.vector2(p + ".to");
                if (b.from == b.to) r.fail(p + ".to", "the two ends of the segment coincide");
                height = std::hypot(b.to[0] - b.from[0], b.to[1] - b.from[1]);
                break;
        }

        const std::string m = p + ".motion";
        b.motion.type = r.choice<MotionType>(m + ".type", {{"fixed", MotionType::fixed},
                                                           {"constant_velocity", MotionType::constant_velocity},
                                                           {"oscillation", MotionType::oscillation},
                                                           {"uniform_acceleration", MotionType::uniform_acceleration},
                                                           {"free", MotionType::free}});
        if (!closed && b.motion.type != MotionType::fixed)
            r.fail(m + ".type", "planes and segments are fixed; only circles, rectangles and polygons move");
        b.motion.velocity = r.vector2(m + ".velocity");
        b.motion.angular_velocity = r.number(m + ".angular_velocity");
        b.motion.amplitude = r.vector2(m + ".amplitude");
        b.motion.angular_amplitude = r.number(m + ".angular_amplitude") * deg;
        if (r.present(m + ".frequency")) b.motion.frequency = r.number(m + ".frequency");
        b.motion.phase = r.number(m + ".phase") * deg;
        b.motion.acceleration = r.vector2(m + ".acceleration");
        b.motion.angular_acceleration = r.number(m + ".angular_acceleration");
        if (b.motion.type == MotionType::free) {
            if (!r.present(p + ".density")) r.fail(p + ".density", "a free body needs its density");
            b.density = r.number(p + ".density");
            b.motion.locked = {r.boolean(m + ".lock_x"), r.boolean(m + ".lock_y"), r.boolean(m + ".lock_rotation")};
        } else if (r.present(p + ".density")) {
            r.fail(p + ".density", "only free bodies (motion type `free`) have a density");
        }
        if ((b.follow[0] || b.follow[1]) && b.motion.type == MotionType::fixed)
            r.fail(p + ".follow", "the body is fixed: the grid has nothing to follow");

        b.reference_velocity = r.number(p + ".reference.velocity");
        b.reference_length = r.present(p + ".reference.length") ? r.number(p + ".reference.length") : height;
        if (!(b.reference_length > 0.0))
            r.fail(p + ".reference.length", "the default (the body's extent across x) is 0: give a length");
        bodies.push_back(std::move(b));
    }
    return bodies;
}

}  // namespace chute
