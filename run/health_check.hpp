#pragma once
// After each step: has the run left the stable regime? (CaNS's chkdiv: stop cleanly instead of writing NaN.)
//   the kinetic energy or the divergence is no longer finite;
//   max |div u| dt exceeds numerics.divergence_limit;
//   the time step fell below a millionth of the first (the CFL limit follows a velocity that blows up);
//   the turbulence model reports a problem (non-finite k or eps, runaway nu_t).
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
        : divergence_limit_(config.divergence_limit), fixed_dt_(config.fixed_dt.has_value()) {}
    // Empty, or why the run must stop (collective: every rank gets the same answer).
    std::optional<std::string> problem(const Model& model, const StepStats& step, const FlowHealth& health);

private:
    double divergence_limit_;
    bool fixed_dt_;
    double first_dt_ = 0.0;
};

}  // namespace chute
