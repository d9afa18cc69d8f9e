#pragma once
// Free bodies moved by the flow: gravity, buoyancy, the hydrodynamic force and torque from the forcing, and
// contact with planes and the domain's walls.
//
// One step (DESIGN.md's data flow), around the flow's predict / force / project:
//   predict(t, dt)  before the forcing: each free body moves over the step with the accelerations of the last
//                   step (impacts located inside it), so the fluid is forced towards where the body will be;
//   correct(t, dt)  after the projection: this step's hydrodynamic wrench from the forcing and the change of
//                   the fluid momentum P inside the body (Uhlmann 2005 eq. 23; P on the grid, Kempe & Froehlich
//                   2012),   F_h = -rho_f depth sum_l F_l dV_l + rho_f depth (P^{n+1} - P^n) / dt,
//                   then the body's update from its state at t^n with a virtual mass C_V m_f added to both
//                   sides (Schwarz, Kempe & Froehlich 2015, JCP 281:591), which keeps light bodies stable:
//                     (m + C_V m_f) a = F_h + (m - m_f) g + C_V m_f a*,   a* the predicted acceleration,
//                   and the motion over the step with a held, impacts located inside it (contact/).
// The pressure is dynamic, so buoyancy -m_f g is added explicitly (m_f = rho_f V).
#include <filesystem>
#include <vector>

#include "case_config.hpp"
#include "checkpoint.hpp"
#include "enclosed_momentum.hpp"
#include "immersed_boundary.hpp"
#include "impacts.hpp"

namespace chute {

// Static planes a body can hit: the case's `plane` bodies and the domain sides of type wall or slip, each
// moved out by contact.distance.
std::vector<Obstacle> obstacles_of(const CaseConfig& config);

// What moved a free body over the last step (N and N m), for the time series.
struct FreeBodyForces {
    Wrench hydrodynamic, gravity, buoyancy, contact;  // contact: the impulses of the step divided by dt
};

class FreeBodies {
public:
    FreeBodies(const CaseConfig& config, ImmersedBoundary& ibm);

    bool empty() const { return free_.empty(); }
    // The largest step over which no free body moves more than `cfl` cells (with its present velocity and
    // acceleration): the flow's CFL limit does not see a body that starts from rest in still fluid.
    double max_dt(double cfl) const;
    // `vel` is u^n (before the step): its momentum inside each body is P^n of the first step.
    void predict(double t, double dt, const Velocity& vel);
    void correct(double t, double dt, const Velocity& vel);

    // Per body of the ImmersedBoundary (zero for bodies that are not free).
    const std::vector<FreeBodyForces>& forces() const { return forces_; }
    // Puts each free body's forces into the immersed boundary's report: (a) becomes the hydrodynamic force
    // of the coupling (with the fluid momentum inside the body from the grid), plus gravity, buoyancy, contact.
    void report(std::vector<BodyForces>& forces) const;
    const std::vector<ContactEvent>& events() const { return events_; }  // this step's impacts
    const std::vector<Obstacle>& obstacles() const { return obstacles_; }

    // Everything a restart needs, one array per free body ("free_body_<name>"), and its reading back:
    // state, held accelerations, contact state and the enclosed fluid momentum P^n.
    std::vector<CheckpointArray> checkpoint_arrays() const;
    void restore(const std::filesystem::path& checkpoint);

private:
    struct Free {
        std::size_t index = 0;  // in the ImmersedBoundary
        RigidInertia inertia;
        double fluid_mass = 0.0, fluid_inertia = 0.0;  // rho_f V and rho_f J depth: the displaced fluid
        BodyState start;                   // at t^n
        Vec2 acceleration = Vec2::Zero();  // of the last update: the next prediction
        double angular_acceleration = 0.0;
        ContactState contact, contact_at_start;
        EnclosedMomentum momentum;  // P^n
    };
    const CaseConfig& config_;
    ImmersedBoundary& ibm_;
    std::vector<Obstacle> obstacles_;
    std::vector<Free> free_;
    std::vector<FreeBodyForces> forces_;
    std::vector<ContactEvent> events_;
    bool momentum_known_ = false;
};

}  // namespace chute
