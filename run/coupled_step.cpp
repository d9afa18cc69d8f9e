#include "coupled_step.hpp"

#include <algorithm>
#include <chrono>

namespace chute {

StepStats advance(FlowSolver& flow, ImmersedBoundary& bodies, FreeBodies& free_bodies, double dt,
                  KEpsilon* turbulence) {
    using clock = std::chrono::steady_clock;
    const double t = flow.time();
    if (dt <= 0.0) dt = std::min(flow.next_dt(), free_bodies.max_dt(flow.config().cfl));
    dt = flow.predict(dt);
    auto start = clock::now();
    if (!bodies.empty()) {
        bodies.move_to(t + dt);
        free_bodies.predict(t, dt, flow.velocity());
        bodies.force(flow.predicted(), dt);
    }
    double seconds_bodies = std::chrono::duration<double>(clock::now() - start).count();
    StepStats stats = flow.project();
    start = clock::now();
    if (!free_bodies.empty()) free_bodies.correct(t, dt, flow.velocity());
    seconds_bodies += std::chrono::duration<double>(clock::now() - start).count();
    stats.seconds_forcing = seconds_bodies;
    if (turbulence) {
        start = clock::now();
        turbulence->update(dt);
        stats.seconds_turbulence = std::chrono::duration<double>(clock::now() - start).count();
    }
    return stats;
}

}  // namespace chute
