#pragma once
// Free bodies moved by the flow: gravity, buoyancy, the hydrodynamic wrench the carrier measures
// (body/carrier.hpp), and contact with planes and the domain's walls (contact/).
//
// One step (docs/design.md's data flow), around the flow's predict / impose / project:
//   predict(t, dt)  before the carrier imposes the bodies: each free body moves over the step with the
//                   accelerations of the last step (impacts located inside it), so the fluid is forced
//                   towards where the body will be;
//   correct(t, dt)  after the projection: this step's hydrodynamic wrench F_h from the carrier, then the body's
//                   update from its state at t^n with a virtual mass C_V m_f added to both sides (Schwarz,
//                   Kempe & Froehlich 2015, JCP 281:591), which keeps light bodies stable:
//                     (m + C_V m_f) a = F_h + (m - m_f) g + C_V m_f a*,   a* the predicted acceleration,
//                   and the motion over the step with a held, impacts located inside it (contact/).
//                   A carrier that gives the body's added mass over the step exactly (Carrier::added_mass: the
//                   body-fitted one) takes it in place of C_V m_f, (m + M) a = F_h + (m - m_f) g + M a*, which
//                   is then the coupled solution itself: the carrier moves the flow to it (body_moved), and the
//                   step needs no further pass and no relaxation at any density ratio.
//   another_pass()  strong coupling: the step forces and projects again while the update still moves
//                   (numerics.coupling), and correct() runs again from the same start.
// An impact (impulse or lumped law) reverses the body's velocity at one instant, and the water moving with it
// (its added mass m_a) must reverse too. The rebound law sets the body's velocity; the passes let the fluid
// follow within the step, and what the wrench then holds beyond the regular force (the one the held
// accelerations stand for) is the water's impulse at the impact, J_w ~ -m_a dv. Who supplies it is the
// case's choice (contact.water_impulse):
//   obstacle (the default; the effective mass m + m_a of wet-collision models, Legendre et al. 2006, Phys.
//         Fluids 18:097102): the obstacle stops the body and its water together, and the body leaves at V_law;
//   body (Turmel & Locat 2008): the water takes its momentum back from the body at once, so the body leaves
//         at the velocity V with m (V - V_law) = J_w(V), solved over the passes with the virtual mass as
//         relaxation: (m + C_V m_f) V_k = m V_law + J_w(V_{k-1}) + C_V m_f V_{k-1}.
// Either way the step's impulses are recorded as impulses (BodyLoads, N s), the same for any dt, and the
// event carries the rebound with the water's impulse (ContactEvent::velocity_wet).
// The pressure is dynamic, so buoyancy -m_f g is added explicitly (m_f = rho_f V).
#include <algorithm>
#include <filesystem>
#include <vector>

#include "carrier.hpp"
#include "checkpoint.hpp"
#include "contact_config.hpp"
#include "impacts.hpp"
#include "rigidbody_config.hpp"

namespace chute {

// The change that further coupling passes would still make, estimated from the last pass's change and the one
// before it (previous < 0: there is none yet) as for a linearly converging sequence: change r / (1 - r), with
// r = change / previous at most 0.99, and never less than the last change itself (FreeBodies::another_pass).
double remaining_change(double change, double previous);
// How many more passes the same sequence needs before remaining_change falls to `tolerance`, at the ratio of the
// last two changes held (0 when it is there already or there is no earlier change to take a ratio from).
double passes_to_tolerance(double change, double previous, double tolerance);

// What free-body dynamics needs of a case (run/case_settings.hpp gathers it).
struct FreeBodySettings {
    ContactConfig contact;
    Vec2 gravity{0.0, -9.81};
    double fluid_density = 1000.0, depth = 1.0;
    double virtual_mass = 1.0;  // C_V (numerics.ibm.virtual_mass)
    CouplingConfig coupling;
    std::vector<Obstacle> obstacles;
};

class FreeBodies {
public:
    // `bodies` are the run's (the free ones among them are moved here); `carrier` carries them.
    FreeBodies(const FreeBodySettings& settings, std::vector<Body>& bodies, Carrier& carrier);

    bool empty() const { return free_.empty(); }
    // The largest step over which no free body moves more than `cfl` cells (with its present velocity and
    // acceleration): the flow's CFL limit does not see a body that starts from rest in still fluid.
    double max_dt(double cfl) const;
    void predict(double t, double dt);
    // `vel` is u^{n+1}, from which the carrier measures the hydrodynamic wrench.
    void correct(double t, double dt, const Velocity& vel);
    // Strong coupling in the steps where a free body's velocity changes at once against the fluid's: its first
    // step (released in fluid at rest, with only an estimate of its acceleration) and a step with an impact.
    // There a single forcing and projection sets only part of the fluid the body drives in motion (about half
    // of its added mass, docs/validation.md), so the step forces and projects again, and correct() runs again
    // from the same start, while the passes still to come would move the update by more than
    // numerics.coupling.tolerance: the acceleration by that fraction of the net weight's, (m - m_f) |g| / m, or an
    // impact's water impulse (and with contact.water_impulse `body` the velocity the body leaves with) by that
    // fraction of itself.
    // Elsewhere the flow of the last step already moves with the body, and a pass would only chase the
    // step-to-step noise of the force (the step after an impact too: passing there left the surface's slip
    // five times larger, docs/validation.md).
    // The passes converge slowly, and more slowly as they go (the ratio of successive changes climbs from 0.75 to
    // 0.98 over an impact's first 60 passes, docs/validation.md): a small change of the last pass is not a small
    // error. So a step passes again while the change still to come (remaining_change) exceeds
    // numerics.coupling.tolerance.
    // Whether a step that has made `passes` passes makes another: not when the passes left to max_passes cannot
    // reach the tolerance at the rate seen (a flow far out of scale, say, whose first step would otherwise spend
    // all of them).
    bool another_pass(int passes) const {
        return impulsive_ && coupling_remaining() > settings_.coupling.tolerance && !out_of_passes(passes);
    }
    // Whether this step's passes stopped short of the tolerance (at max_passes, or because they could not meet it
    // within them).
    bool coupling_unconverged(int passes) const {
        return impulsive_ && coupling_remaining() > settings_.coupling.tolerance && out_of_passes(passes);
    }
    // Whether a free body hit an obstacle with an impulse law in this step (its water's impulse is in the
    // step's pressure: FlowSolver::forget_impulsive_pressure).
    bool impact_step() const {
        return std::any_of(free_.begin(), free_.end(), [](const Free& f) { return f.impact; });
    }
    // Gravity, buoyancy and contact on body b over the last step (zero for bodies that are not free).
    const BodyLoads& loads(std::size_t b) const { return loads_[b]; }
    const std::vector<ContactEvent>& events() const { return events_; }  // this step's impacts
    const std::vector<Obstacle>& obstacles() const { return settings_.obstacles; }
    const ContactConfig& contact() const { return settings_.contact; }

    // Everything a restart needs, one array per free body ("free_body_<name>"), and its reading back:
    // state, held accelerations and contact state.
    std::vector<CheckpointArray> checkpoint_arrays() const;
    void restore(const std::filesystem::path& checkpoint);

private:
    double coupling_remaining() const { return remaining_change(coupling_change_, previous_change_); }
    // The ratio of two changes is a fair guide only once the first, fast passes are over (a start converges in
    // 6-7 passes with ratios that jump about), so the rate is judged from the 10th pass on.
    bool out_of_passes(int passes) const {
        const int max = settings_.coupling.max_passes;
        if (passes >= max) return true;
        return passes >= 10 &&
               passes + passes_to_tolerance(coupling_change_, previous_change_, settings_.coupling.tolerance) > max;
    }
    struct Free {
        std::size_t index = 0;  // in the run's bodies
        RigidInertia inertia;
        double fluid_mass = 0.0, fluid_inertia = 0.0;  // rho_f V and rho_f J depth: the displaced fluid
        double weight_acceleration = 0.0;              // |m - m_f| |g| / m: the scale of coupling_change_
        BodyState start;                               // at t^n
        Vec2 acceleration = Vec2::Zero();              // of the last update: the next prediction
        double angular_acceleration = 0.0;
        ContactState contact, contact_at_start;
        bool impact = false;                    // the step's motion holds an impact (impulse or lumped law)
        Vec2 held_acceleration = Vec2::Zero();  // the accelerations the step was predicted with
        double held_angular_acceleration = 0.0;
        Vec2 rebound_velocity = Vec2::Zero();  // contact.water_impulse body: the last pass's V_k (and spin)
        double rebound_angular_velocity = 0.0;
        bool started = false;  // has taken a step (a restored body has)
    };
    FreeBodySettings settings_;
    std::vector<Body>& bodies_;
    Carrier& carrier_;
    std::vector<Free> free_;
    std::vector<BodyLoads> loads_;
    std::vector<ContactEvent> events_;
    double coupling_change_ = 0.0;   // how far the last correct() moved the update, in its scales (-1: none yet)
    double previous_change_ = -1.0;  // the same for the correct() before it in this step (-1: none yet)
    bool impulsive_ = false;         // a free body starts or hits an obstacle in this step
};

}  // namespace chute
