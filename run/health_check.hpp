#pragma once
// After each step: has the run left the stable regime? (CaNS's chkdiv: stop cleanly instead of writing NaN.)
//   the kinetic energy or the divergence is no longer finite;
//   max |div u| dt exceeds numerics.divergence_limit;
//   the time step fell below a millionth of the first (the CFL limit follows a velocity that blows up);
//   the turbulence model reports a problem (non-finite k or eps, runaway nu_t).
// When the pressure solve stopped at numerics.poisson.max_iterations in that step, the message says so.
// The message names the cause and the keys to change.
#include <optional>
#include <string>

#include "model.hpp"

namespace chute {

// The flow's health after a step: what the time series records and the divergence check reads (collective).
struct FlowHealth {
    double kinetic_energy = 0.0, max_divergence = 0.0;
};
FlowHealth flow_health(const FlowSolver& flow);

class HealthCheck {
public:
    explicit HealthCheck(const CaseConfig& config)
        : divergence_limit_(config.divergence_limit),
          fixed_dt_(config.fixed_dt.has_value()),
          poisson_max_iterations_(config.poisson_max_iterations),
          poisson_tolerance_(config.poisson_tolerance) {}
    // Empty, or why the run must stop (collective: every rank gets the same answer).
    std::optional<std::string> problem(const Model& model, const StepStats& step, const FlowHealth& health);
    // Empty, or (once per run and solve) a note that the pressure or the implicit diffusion solve stopped at
    // its iteration bound: the run goes on, since the divergence check judges whether an unconverged
    // pressure matters, and an unconverged diffusion solve is still a stable (damped) update.
    std::optional<std::string> warning(const Model& model, const StepStats& step);

private:
    bool poisson_at_bound(const StepStats& step) const { return step.poisson_iterations >= poisson_max_iterations_; }
    std::string poisson_bound_text(const StepStats& step) const;

    double divergence_limit_;
    bool fixed_dt_;
    int poisson_max_iterations_;
    double poisson_tolerance_;
    double first_dt_ = 0.0;
    bool warned_poisson_ = false, warned_diffusion_ = false, warned_coupling_ = false;
};

}  // namespace chute
