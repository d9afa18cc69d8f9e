#include "health_check.hpp"

#include <cmath>
#include <sstream>

#include "diagnostics.hpp"
#include "implicit_diffusion.hpp"

namespace chute {

FlowHealth flow_health(const FlowSolver& flow) {
    return {kinetic_energy(flow.grid(), flow.velocity(), flow.fluid_cells()), flow.max_divergence()};
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
    if (poisson_at_bound(step)) msg << "; " << poisson_bound_text(step);
    msg << " (dt = " << step.dt << "; try a smaller numerics.cfl, a finer grid, or the van_leer scheme).";
    return msg.str();
}

std::optional<std::string> HealthCheck::warning(const Model& model, const StepStats& step) {
    std::ostringstream msg;
    msg << "step " << model.flow().step() << ", t = " << model.flow().time() << ": ";
    if (!warned_poisson_ && poisson_at_bound(step)) {
        warned_poisson_ = true;
        msg << poisson_bound_text(step)
            << "; the run goes on while max |div u| dt stays below numerics.divergence_limit (noted once)";
        return msg.str();
    }
    if (!warned_diffusion_ && step.diffusion_iterations >= ImplicitDiffusion::kMaxIterations) {
        warned_diffusion_ = true;
        msg << "the implicit diffusion solve stopped at its bound of " << ImplicitDiffusion::kMaxIterations
            << " iterations; the step is still a damped update, but the eddy viscosity is likely far out of "
               "scale (check turbulence.* and fluid.viscosity; noted once)";
        return msg.str();
    }
    if (!warned_coupling_ && step.coupling_unconverged) {
        warned_coupling_ = true;
        msg << "the coupling passes stopped short of numerics.coupling.tolerance (at numerics.coupling.max_passes, "
               "or where the passes left could not meet it at the rate seen); part of the body's start or impact "
               "comes out as a force over the next steps (noted once)";
        return msg.str();
    }
    return std::nullopt;
}

std::string HealthCheck::poisson_bound_text(const StepStats& step) const {
    std::ostringstream msg;
    msg << "the pressure solve stopped at numerics.poisson.max_iterations = " << poisson_max_iterations_
        << " with relative residual " << step.poisson_residual
        << " (numerics.poisson.tolerance = " << poisson_tolerance_ << ")";
    return msg.str();
}

}  // namespace chute
