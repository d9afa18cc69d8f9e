#pragma once
// Rigid-body dynamics' part of a case (docs/case-file.md): the gravity that moves free bodies (`gravity`), and
// the constants of the lumped trajectory models written beside a run with free bodies (`lumped`). Plain data:
// read_gravity() and read_lumped() fill it (rigidbody_keys.cpp, the schema's gravity and lumped sections).
#include <array>
#include <vector>

namespace chute {

// The lumped trajectory models a run with free bodies writes beside its CFD result (rigidbody/lumped_model):
// Beranger et al. (1998) with these constants (Turmel & Locat 2008: C_D 2.0 for the block, C_a 0.5), and dry.
struct LumpedConfig {
    double drag_coefficient = 2.0;
    double added_mass_coefficient = 0.5;
};

// Strong coupling of free bodies in the steps where their velocity changes at once against the fluid's (the
// first step, an impact; rigidbody/free_bodies.hpp): after the first forcing, projection and body update the
// step passes again (force u^{n+1} towards the corrected motion, project, update) while the update moves by
// more than `tolerance` (of the net weight's acceleration, or of an impact's water impulse), at most
// `max_passes` passes in all. One pass sets only part of the fluid in motion (about half of the added mass at
// the start of a fall, docs/validation.md); the passes complete it.
struct CouplingConfig {
    int max_passes = 20;
    double tolerance = 0.01;
};

// The schema's gravity and lumped sections (io/case_reader.hpp) and their reading. Gravity is here, not in
// the flow's section, because only the free bodies and the lumped models feel it: the pressure is dynamic.
struct CaseKey;
class CaseReader;
std::vector<CaseKey> rigidbody_keys();
std::array<double, 2> read_gravity(const CaseReader& reader);  // m/s^2
LumpedConfig read_lumped(const CaseReader& reader);
CouplingConfig read_coupling(const CaseReader& reader);

}  // namespace chute
