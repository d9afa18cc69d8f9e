#pragma once
// A static obstacle a body can hit: a plane with the solid on one side (the sea bed, a slope, a domain wall).
#include <string>
#include <vector>

#include "body.hpp"
#include "case_config.hpp"

namespace chute {

struct Obstacle {
    std::string name;
    Vec2 point = Vec2::Zero();    // a point of the plane
    Vec2 normal = Vec2::UnitY();  // unit normal pointing out of the solid, into the fluid
};

// How far the body's nearest point lies from the obstacle (negative: overlap), and that point (world frame).
struct Gap {
    double distance = 0.0;
    Vec2 point = Vec2::Zero();
};

Gap gap(const Outline& outline, const BodyState& s, const Obstacle& obstacle);

// The static planes of a case a body can hit: its `plane` bodies and the domain sides of type wall or slip,
// each moved out by contact.distance.
std::vector<Obstacle> obstacles_of(const CaseConfig& config);

}  // namespace chute
