#pragma once
// Contact's part of a case (docs/case-file.md, `contact`): the rebound law of an impact and its constants.
// Plain data: read_contact() fills it (contact_keys.cpp, the schema's contact section).
#include <vector>

namespace chute {

// Rebound laws at an impact (contact/rebound.hpp):
//   lumped (RocFall's lumped mass, Turmel & Locat 2008): the centre's velocity, v_n' = -Rn v_n, v_t' = Rt v_t;
//   impulse: the same coefficients on the contact point's velocity, by an impulse that also turns the body;
//   soft: a spring-dashpot at the contact point over a finite contact time, sub-stepped inside the step.
enum class ReboundLaw { lumped, impulse, soft };

// Who reverses the water a body carries at an impact (lumped and impulse laws; rigidbody/free_bodies.hpp):
//   obstacle: the obstacle stops the body and the water it carries together (the effective mass m + m_a of
//         wet-collision models, Legendre et al. 2006), and the body leaves at the law's velocity. The sphere
//         experiments find the wet restitution near the dry one at high Stokes number (Joseph et al. 2001,
//         Gondret et al. 2002), and so does Chute's own resolved contact (docs/validation.md);
//   body: the law acts on the body alone, and the water moving with it then takes its momentum back from the
//         body at once (Turmel & Locat 2008's CFD: the "memory" of the water).
enum class WaterImpulse { obstacle, body };

struct ContactConfig {
    ReboundLaw law = ReboundLaw::lumped;
    double normal_restitution = 0.8;      // Rn
    double tangential_restitution = 0.8;  // Rt
    double rest_speed = 0.01;             // m/s: a slower rebound leaves the body resting on the obstacle
    double friction = 0.0;                // Coulomb coefficient while resting (sliding) on an obstacle
    double distance = 0.0;                // m: impacts happen at this gap (0: at the surface)
    double duration = 0.002;              // s: soft law, contact time of one impact
    WaterImpulse water_impulse = WaterImpulse::obstacle;
};

// The schema's contact section (io/case_reader.hpp) and its reading.
struct CaseKey;
class CaseReader;
std::vector<CaseKey> contact_keys();
ContactConfig read_contact(const CaseReader& reader);

}  // namespace chute
