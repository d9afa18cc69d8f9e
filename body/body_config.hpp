#pragma once
// A body as the case file gives it (docs/case-file.md, `bodies.<name>`): shape and place, prescribed motion or
// free, density, and the scales of its force coefficients. Plain data: read_bodies() fills it (body_keys.cpp,
// the schema's bodies section), Body (body.hpp) places and moves it.
#include <array>
#include <string>
#include <vector>

namespace chute {

enum class BodyShape { circle, rectangle, polygon, plane, segment };
enum class MotionType { fixed, constant_velocity, oscillation, uniform_acceleration, free };
// How a body is carried through the flow (body/carrier.hpp): carrier 1 or carrier 2 of docs/design.md.
enum class CarrierKind { immersed, body_fitted };

// Prescribed motion of a body's reference point (its centre of area) and angle, from its initial place:
//   fixed; constant_velocity: x0 + V t; oscillation: x0 + A sin(2 pi f t + phase);
//   uniform_acceleration (from rest): x0 + a t^2 / 2.  Angles likewise.
//   free: moved by the forces on it (rigidbody/), starting with `velocity` and `angular_velocity`.
struct MotionConfig {
    MotionType type = MotionType::fixed;
    std::array<double, 2> velocity{0.0, 0.0}, amplitude{0.0, 0.0}, acceleration{0.0, 0.0};
    double angular_velocity = 0.0, angular_amplitude = 0.0, angular_acceleration = 0.0;  // rad, s
    double frequency = 0.0, phase = 0.0;                                                 // Hz, rad
    std::array<bool, 3> locked{false, false, false};                                     // free: x, y, rotation held
};

struct BodyConfig {
    std::string name;
    BodyShape shape = BodyShape::circle;
    std::array<double, 2> centre{0.0, 0.0};              // circle, rectangle
    double diameter = 0.0;                               // circle
    std::array<double, 2> size{0.0, 0.0};                // rectangle: width, height (before rotation)
    double angle = 0.0;                                  // rad: rectangle/polygon rotation, plane inclination
    std::vector<std::array<double, 2>> vertices;         // polygon
    std::array<double, 2> point{0.0, 0.0};               // plane: a point on it
    std::array<double, 2> from{0.0, 0.0}, to{0.0, 0.0};  // segment
    MotionConfig motion;
    double density = 0.0;                                     // kg/m^3, free bodies
    double reference_velocity = 1.0, reference_length = 1.0;  // force coefficients
    CarrierKind carrier = CarrierKind::immersed;
    bool layers = false;  // body_fitted: the grid follows with modifier layers (band/layers.hpp), not translating
    std::array<bool, 2> follow{false,
                               false};  // immersed: the grid follows the body along x, y (run/following_frame.hpp)
};

// Where a body is at the start, for the check that it lies in the domain (run/case_file.cpp): the key that
// places it (`centre`, `vertices`, `point` or `from`), which the error names, and the points that must lie
// inside: a circle's bounding box, a rectangle's corners, a polygon's corners as given, a plane's point, a
// segment's ends.
std::string placement_key(const BodyConfig& body);
std::vector<std::array<double, 2>> placement_points(const BodyConfig& body);

// The schema's bodies section (io/case_reader.hpp): bodies.<body>.* with the placeholder `<body>` (any name),
// and its reading, in name order, with the checks inside one body (a polygon's corners, a segment's ends,
// only closed shapes move, density exactly for free bodies). Angles are read in degrees and kept in radians.
// A reference length not given defaults to the body's height (its extent across x), a plane's to
// `plane_reference_length` (the domain's diagonal: the assembly knows the domain).
struct CaseKey;
struct Placeholder;
class CaseReader;
std::vector<CaseKey> body_keys();
std::vector<Placeholder> body_placeholders();
std::vector<BodyConfig> read_bodies(const CaseReader& reader, double plane_reference_length);

}  // namespace chute
