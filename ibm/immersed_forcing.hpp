#pragma once
// How the immersed boundary imposes its bodies on the predicted velocity (ibm/immersed_boundary.hpp), one of two
// ways chosen by numerics.ibm.interface:
//   sharp    the surface enters the discrete equations where it lies: faces inside a body take its velocity and
//            the fluid faces beside the surface a value reconstructed along the normal (sharp_forcing.hpp);
//   diffuse  Lagrangian markers whose forcing is spread over a regularised delta kernel (direct_forcing.hpp).
// Either reports the momentum it gave the fluid, which force measure (a) needs.
#include <vector>

#include "field.hpp"
#include "outline.hpp"

namespace chute {

struct BodyForcing {
    Vec2 momentum_rate = Vec2::Zero();  // momentum given to the fluid per unit time / (rho depth)  (m^3/s^2)
    double torque_rate = 0.0;           // its moment about the body centre  (m^4/s^2)
    double max_slip = 0.0;              // max |u - U_body| where the surface is imposed, after forcing (m/s)
    double rms_slip = 0.0;
};

class ImmersedForcing {
public:
    virtual ~ImmersedForcing() = default;
    // A new step (the volume forcing of the diffuse method follows the bodies' accelerations from zero again).
    virtual void begin_step() = 0;
    // Force u* (owned faces) towards the bodies' velocities at their present place.
    virtual void apply(Velocity& star, double dt) = 0;
    // Per body, what the last apply() gave the fluid.
    virtual const std::vector<BodyForcing>& forcing() const = 0;
    // The slip the projection left where the surface was imposed (m/s), into forcing()'s max_slip and rms_slip;
    // a method that reports the slip of its own iteration instead does nothing. Collective.
    virtual void measure_slip(const Velocity&) {}
    // The smallest grid spacing along body b's outline, and the spacing of its surface points (m).
    virtual double cell_size(std::size_t b) const = 0;
    virtual double marker_spacing(std::size_t b) const = 0;
};

}  // namespace chute
