// Rigid-body dynamics' sections of the case-file schema (rigidbody_config.hpp) and their reading.
#include "case_reader.hpp"
#include "rigidbody_config.hpp"

namespace chute {

std::vector<CaseKey> rigidbody_keys() {
    using K = KeyType;
    return {
        {.path = "gravity",
         .type = K::vector2,
         .default_value = "[0.0, -9.81]",
         .units = "m/s^2",
         .meaning = "Gravity on free bodies. The pressure is dynamic (hydrostatic part removed), so the fluid "
                    "feels no gravity and each free body gets its buoyancy -rho_f V g explicitly."},

        {.path = "lumped",
         .type = K::section,
         .meaning = "The lumped trajectory models written beside a run with free bodies (`lumped_<body>.csv`)."},
        {.path = "lumped.drag_coefficient",
         .type = K::number,
         .default_value = "2.0",
         .min = at_least(0.0),
         .meaning = "C_D of the Beranger et al. (1998) model (Turmel & Locat 2008: 2.0 for the block)."},
        {.path = "lumped.added_mass_coefficient",
         .type = K::number,
         .default_value = "0.5",
         .min = at_least(0.0),
         .meaning = "C_a of the Beranger model (Turmel & Locat 2008: 0.5)."},

        {.path = "numerics.coupling",
         .type = K::section,
         .meaning = "Strong coupling of free bodies and flow in the steps where a body's velocity changes at once "
                    "against the fluid's (its first step, an impact): further forcing and projection passes, so "
                    "that the fluid the body sets in motion (its added mass) moves within the step."},
        {.path = "numerics.coupling.max_passes",
         .type = K::integer,
         .default_value = "200",
         .min = at_least(1),
         .max = at_most(1000),
         .meaning = "Most forcing and projection passes in one step; 1 is the explicit (weak) coupling. An impact "
                    "takes some 90-190 to meet the tolerance. From the 10th pass on, a step whose passes left "
                    "cannot meet it at the rate seen stops at once; a step stopped short of it is noted once."},
        {.path = "numerics.coupling.tolerance",
         .type = K::number,
         .default_value = "0.01",
         .min = above(0),
         .meaning = "Such a step passes again while the passes still to come would move a free body's "
                    "acceleration by more than this fraction of its net weight's acceleration |m - m_f| g / m, "
                    "or an impact's water impulse by more than this fraction of itself; estimated from the "
                    "last two passes' changes d as d r / (1 - r), r their ratio (the passes converge slowly)."},
    };
}

std::array<double, 2> read_gravity(const CaseReader& r) { return r.vector2("gravity"); }

LumpedConfig read_lumped(const CaseReader& r) {
    LumpedConfig c;
    c.drag_coefficient = r.number("lumped.drag_coefficient");
    c.added_mass_coefficient = r.number("lumped.added_mass_coefficient");
    return c;
}

CouplingConfig read_coupling(const CaseReader& r) {
    CouplingConfig c;
    c.max_passes = static_cast<int>(r.integer("numerics.coupling.max_passes"));
    c.tolerance = r.number("numerics.coupling.tolerance");
    return c;
}

}  // namespace chute
