#include "case_settings.hpp"

#include "wall_function.hpp"

namespace chute {

ImmersedBoundarySettings immersed_boundary_settings(const CaseConfig& c) {
    ImmersedBoundarySettings s{c.ibm, c.density, c.viscosity, c.depth, c.turbulence.image_distance, {}};
    if (c.turbulence.model != TurbulenceModelType::laminar)
        s.wall_profile = [nu = c.viscosity](double speed, double L, double y) {
            return law_of_the_wall_speed(speed, L, y, nu);
        };
    return s;
}

BodyFittedSettings body_fitted_settings(const CaseConfig& c) {
    return {c.density,
            c.viscosity,
            c.depth,
            {c.boundary[0].type, c.boundary[1].type, c.boundary[2].type, c.boundary[3].type},
            c.contact.distance};
}

FreeBodySettings free_body_settings(const CaseConfig& c) {
    return {c.contact,  Vec2(c.gravity[0], c.gravity[1]),    c.density, c.depth, c.ibm.virtual_mass,
            c.coupling, obstacles_of(c, c.bodies, c.contact)};
}

KEpsilonSettings k_epsilon_settings(const CaseConfig& c) {
    return {c.turbulence, c.viscosity, c.diffusion_number, c.boundary, c.initial_velocity};
}

}  // namespace chute
