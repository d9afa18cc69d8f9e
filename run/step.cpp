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
        carrier.begin_step(flow.velocity());
    }
    dt = flow.predict(dt);
    {
        StageTimer::Scope timed(timer, "bodies");
        free_bodies.predict(t, dt);
        carrier.place(t + dt);
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
    while (free_bodies.another_pass(stats.coupling_passes)) {
        {
            StageTimer::Scope timed(timer, "bodies");
            carrier.impose(flow.reopen(), dt);
        }
        stats.poisson_iterations = std::max(stats.poisson_iterations, flow.reproject().poisson_iterations);
        ++stats.coupling_passes;
        StageTimer::Scope timed(timer, "bodies");
        free_bodies.correct(t, dt, flow.velocity());
    }
    if (KEpsilon* turbulence = model.turbulence()) {
        StageTimer::Scope timed(timer, "turbulence");
        turbulence->update(dt);
    }
    return stats;
}

std::vector<BodyForces> measure_forces(Model& model, StageTimer* timer) {
    StageTimer::Scope timed(timer, "forces");
    const std::optional<WallTurbulence> turbulence = model.wall_turbulence();
    const WallTurbulence* wall = turbulence ? &*turbulence : nullptr;
    FlowSolver& flow = model.flow();
    std::vector<BodyForces> forces = model.carrier().measure(flow.velocity(), flow.pressure(), wall);
    const double dt = flow.previous_dt();
    std::vector<BodyForces> before_impact;  // (b) from the step's starting pressure, for bodies that hit
    for (std::size_t b = 0; b < forces.size(); ++b) {
        BodyForces& f = forces[b];
        f.loads = model.free_bodies().loads(b);
        if (f.loads.water_impulse.isZero() && f.loads.water_angular_impulse == 0.0) continue;
        // An impact's water impulse is recorded as the impulse it is, not inside the step's force: (a) without
        // it, and (b) from p^{n-1/2}, since p^{n+1/2} of an impact step is the impulsive pressure / dt.
        f.forcing -= f.loads.water_impulse / dt;
        f.forcing_torque -= f.loads.water_angular_impulse / dt;
        if (before_impact.empty())
            before_impact = model.carrier().measure(flow.velocity(), flow.previous_pressure(), wall);
        f.surface = before_impact[b].surface;
    }
    return forces;
}

}  // namespace chute
