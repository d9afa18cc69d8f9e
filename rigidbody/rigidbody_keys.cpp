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
    };
}

std::array<double, 2> read_gravity(const CaseReader& r) { return r.vector2("gravity"); }

LumpedConfig read_lumped(const CaseReader& r) {
    LumpedConfig c;
    c.drag_coefficient = r.number("lumped.drag_coefficient");
    c.added_mass_coefficient = r.number("lumped.added_mass_coefficient");
    return c;
}

}  // namespace chute
