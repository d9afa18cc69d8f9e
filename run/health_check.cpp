#include "health_check.hpp"

#include <cmath>
#include <sstream>

#include "diagnostics.hpp"

namespace chute {

FlowHealth flow_health(const FlowSolver& flow) {
    return {kinetic_energy(flow.grid(), flow.velocity()), max_divergence(flow.grid(), flow.velocity())};
}

std::optional<std::string> HealthCheck::problem(const Model& model, const StepStats& step, const FlowHealth& health) {
    const double ke = health.kinetic_energy, div = health.max_divergence;
    if (first_dt_ == 0.0) first_dt_ = step.dt;
    const bool dt_collapsed = !fixed_dt_ && step.dt < 1e-6 * first_dt_;
    const std::optional<std::string> turbulence = model.turbulence() ? model.turbulence()->check() : std::nullopt;
    if (std::isfinite(ke) && std::isfinite(div) && div * step.dt <= divergence_limit_ && !dt_collapsed && !turbulence)
        return std::nullopt;
    std::ostringstream msg;
    msg << "run diverged at step " << model.flow().step() << ", t = " << model.flow().time() << ": ";
    if (turbulence)
        msg << *turbulence;
    else if (!std::isfinite(ke))
        msg << "kinetic energy is " << ke;
    else if (dt_collapsed)
        msg << "the time step fell to " << step.dt << " s, a millionth of the first step's " << first_dt_
            << " s (the velocity is blowing up)";
    else
        msg << "max |div u| dt = " << div * step.dt << " exceeds numerics.divergence_limit = " << divergence_limit_;
    msg << " (dt = " << step.dt << "; try a smaller numerics.cfl, a finer grid, or the van_leer scheme).";
    return msg.str();
}

}  // namespace chute
