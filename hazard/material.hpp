#pragma once
// What a slope segment is made of, as rockfall codes describe it (RocFall, Rocscience; Turmel & Locat 2008
// used Rn = Rt = 0.8): the dry normal and tangential coefficients of restitution, drawn anew at every impact; the
// friction angle of sliding, drawn when a slide starts; and the roughness, the standard deviation of a normal
// perturbation of the segment's angle at each impact.
#include <string>

#include "distribution.hpp"

namespace chute {

struct Material {
    std::string name;
    Distribution normal_restitution = Distribution::fixed(0.8);      // Rn
    Distribution tangential_restitution = Distribution::fixed(0.8);  // Rt
    Distribution friction_angle = Distribution::fixed(30.0);         // degrees
    double roughness = 0.0;                                          // degrees (standard deviation)
};

}  // namespace chute
