// Contact's section of the case-file schema (contact_config.hpp) and its reading.
#include "case_reader.hpp"
#include "contact_config.hpp"

namespace chute {

std::vector<CaseKey> contact_keys() {
    using K = KeyType;
    return {
        {.path = "contact",
         .type = K::section,
         .meaning = "Impacts of free bodies on planes and on wall or slip sides of the domain."},
        {.path = "contact.law",
         .type = K::choice,
         .default_value = "lumped",
         .choices = {"lumped", "impulse", "soft"},
         .meaning = "`lumped` (RocFall's lumped mass): v_n' = -Rn v_n, v_t' = Rt v_t on the centre's velocity, "
                    "spin kept. `impulse`: the same coefficients on the contact point's velocity, through an "
                    "impulse that also changes the spin. `soft`: a linear spring-dashpot at the contact point "
                    "lasting `duration`, damped to give Rn, with Coulomb `friction` along the surface."},
        {.path = "contact.normal_restitution",
         .type = K::number,
         .default_value = "0.8",
         .min = at_least(0.0),
         .max = at_most(1.0),
         .meaning = "Rn (Turmel & Locat 2008: 0.8)."},
        {.path = "contact.tangential_restitution",
         .type = K::number,
         .default_value = "0.8",
         .min = at_least(0.0),
         .max = at_most(1.0),
         .meaning = "Rt (Turmel & Locat 2008: 0.8)."},
        {.path = "contact.rest_speed",
         .type = K::number,
         .default_value = "0.01",
         .min = above(0.0),
         .units = "m/s",
         .meaning = "A rebound slower than this (normal speed of the contact point) leaves the body resting on "
                    "the obstacle, sliding with `friction`."},
        {.path = "contact.distance",
         .type = K::number,
         .default_value = "0.0",
         .min = at_least(0.0),
         .units = "m",
         .meaning = "Gap at which an impact happens. 0: at the surface. In water a flat face that meets a wall "
                    "squarely is slowed by the fluid it squeezes out (docs/validation.md, The contact gap): a "
                    "body_fitted body with layers resolves that cushion (its gap is the cell that stretches; "
                    "converged at 5 mm), the immersed boundary not below about one cell, where a contact distance "
                    "of one or two cells stands for the unresolved approach. Turmel & Locat's body-fitted mesh "
                    "needed about 0.1 m, which leaves the cushion out."},
        {.path = "contact.duration",
         .type = K::number,
         .default_value = "0.002",
         .min = above(0.0),
         .units = "s",
         .meaning = "Soft law: the duration of one impact (it sets the spring's stiffness; Rn sets its "
                    "damping). It is sub-stepped in 100 steps whatever the flow's step."},
        {.path = "contact.water_impulse",
         .type = K::choice,
         .default_value = "obstacle",
         .choices = {"obstacle", "body"},
         .meaning = "Lumped and impulse laws in a fluid: who reverses the water the body carries (its added "
                    "mass) at an impact. `obstacle` (wet-collision models, Legendre et al. 2006): the obstacle "
                    "stops the body and its water together, and the body leaves at the law's velocity, as the "
                    "sphere experiments at high Stokes number find (Joseph et al. 2001, Gondret et al. 2002) and "
                    "a contact resolved over many steps (`soft`) gives. `body` (Turmel & Locat 2008's CFD): "
                    "the law sets the body's velocity, then that water takes its momentum back from the body at "
                    "once, so the body leaves far slower. Either way the water's impulse is solved within the "
                    "impact step (numerics.coupling; a body_fitted body is coupled exactly, (m + M) V = m V_law + "
                    "M v_free with `body`) and recorded in N s; contacts.csv gives the rebound with it "
                    "(docs/validation.md, Impacts in water)."},
        {.path = "contact.friction",
         .type = K::number,
         .default_value = "0.0",
         .min = at_least(0.0),
         .meaning = "Coulomb friction coefficient of a body resting (sliding) on an obstacle."},
    };
}

ContactConfig read_contact(const CaseReader& r) {
    ContactConfig c;
    c.law = r.choice<ReboundLaw>(
        "contact.law", {{"lumped", ReboundLaw::lumped}, {"impulse", ReboundLaw::impulse}, {"soft", ReboundLaw::soft}});
    c.normal_restitution = r.number("contact.normal_restitution");
    c.tangential_restitution = r.number("contact.tangential_restitution");
    c.rest_speed = r.number("contact.rest_speed");
    c.friction = r.number("contact.friction");
    c.distance = r.number("contact.distance");
    c.duration = r.number("contact.duration");
    c.water_impulse = r.choice<WaterImpulse>("contact.water_impulse",
                                             {{"obstacle", WaterImpulse::obstacle}, {"body", WaterImpulse::body}});
    return c;
}

}  // namespace chute
