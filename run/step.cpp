#include "step.hpp"

#include <algorithm>

namespace chute {

StepStats take_step(Model& model, double dt, StageTimer* timer) {
    FlowSolver& flow = model.flow();
    Carrier& carrier = model.carrier();
    FreeBodies& free_bodies = model.free_bodies();
    const double t = flow.time();
    flow.set_timer(timer);

    {
        StageTimer::Scope timed(timer, "bodies");
        model.window_before_step();
        carrier.begin_step(flow.velocity());
    }
    dt = flow.predict(dt);
    {
        StageTimer::Scope timed(timer, "bodies");
        free_bodies.predict(t, dt);
        carrier.place(t + dt);
        // A translating window's lines with the body, before its surface is imposed there.
        model.window_to_placed_body();
        carrier.impose(flow.predicted(), dt);
    }
    StepStats stats = flow.project();
    {
        StageTimer::Scope timed(timer, "bodies");
        free_bodies.correct(t, dt, flow.velocity());
    }
    // Strong coupling where a free body's velocity changes at once (its first step, an impact): while its update
    // still moves, force u^{n+1} towards the corrected motion and project again. One pass sets only part of the
    // fluid the body drives in motion (its added mass); the passes complete it (rigidbody/free_bodies.hpp).
    // numerics.ibm.projection_passes asks for passes in every step: each leaves less slip after the projection.
    const int passes = model.config().ibm.projection_passes;
    while (free_bodies.another_pass(stats.coupling_passes) || stats.coupling_passes < passes) {
        {
            StageTimer::Scope timed(timer, "bodies");
            carrier.impose(flow.reopen(), dt);
        }
        stats.poisson_iterations = std::max(stats.poisson_iterations, flow.reproject().poisson_iterations);
        ++stats.coupling_passes;
        StageTimer::Scope timed(timer, "bodies");
        free_bodies.correct(t, dt, flow.velocity());
    }
    stats.coupling_unconverged = free_bodies.coupling_unconverged(stats.coupling_passes);
    if (free_bodies.impact_step()) flow.forget_impulsive_pressure();
    if (KEpsilon* turbulence = model.turbulence()) {
        StageTimer::Scope timed(timer, "turbulence");
        turbulence->update(dt);
    }
    // A translating grid's velocity for the next step, so that its limit (Model::stable_dt) sees the relative
    // velocities the step will have; a restart sets it the same way (restore_run).
    model.window_after_step();
    return stats;
}

std::vector<BodyForces> measure_forces(Model& model, StageTimer* timer) {
    StageTimer::Scope timed(timer, "forces");
    const std::optional<WallTurbulence> turbulence = model.wall_turbulence();
    FlowSolver& flow = model.flow();
    // After an impact step the pressure is the step's starting one (forget_impulsive_pressure), so (b) holds
    // no impulse / dt.
    std::vector<BodyForces> forces =
        model.carrier().measure(flow.velocity(), flow.pressure(), turbulence ? &*turbulence : nullptr);
    const double dt = flow.previous_dt();
    for (std::size_t b = 0; b < forces.size(); ++b) {
        BodyForces& f = forces[b];
        f.loads = model.free_bodies().loads(b);
        // An impact's water impulse is recorded as the impulse it is (loads), not inside the step's force.
        // (Only in a step with an impact: the record of t = 0 has no step, dt = 0.)
        if (f.loads.water_impulse.isZero() && f.loads.water_angular_impulse == 0.0) continue;
        // A carrier that couples the body exactly (body-fitted) measures (a) after body_moved() brought the water to
        // the body's final velocity: the impulse is not in it (2026-11-24: subtracting it put 4.6e5 N into the bed
        // bounce's record at the impact).
        if (!model.carrier().measure_holds_impulse(b)) continue;
        f.forcing -= f.loads.water_impulse / dt;
        f.forcing_torque -= f.loads.water_angular_impulse / dt;
    }
    return forces;
}

}  // namespace chute
