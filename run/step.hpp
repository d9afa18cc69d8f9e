#pragma once
// One time step of the model, in the order of docs/design.md's data flow:
//
//   momentum prediction u*            (FlowSolver::predict: advection, diffusion with nu + nu_t)
//   bodies to t^{n+1}, imposed on u*  (free bodies predicted, prescribed ones placed; the carrier's forcing)
//   pressure projection               (FlowSolver::project: hypre)
//   rigid-body update and contact     (the carrier's hydrodynamic wrench on each free body; impacts)
//   [forcing, projection, update]     again in a free body's first step and at an impact (strong coupling)
//   turbulence update                 (k-epsilon from u^{n+1})
//   force measures                    (both, on every body: measure_forces)
//
// Stages are timed into the StageTimer (null: not timed) by name: "momentum", "poisson", "correction" (the flow
// solver's), "bodies" (the carrier and free-body dynamics), "turbulence", "forces".
#include <array>
#include <string_view>
#include <vector>

#include "model.hpp"
#include "stage_timer.hpp"

namespace chute {

// The stages of a step in the order they run, for a StageTimer that reports them in that order.
inline constexpr std::array<std::string_view, 6> kStepStages = {"momentum",   "bodies",     "poisson",
                                                                "correction", "turbulence", "forces"};

// Advances the model by one step of dt (> 0; Model::stable_dt() gives the stable one). (FlowSolver::advance is
// the flow alone.)
StepStats take_step(Model& model, double dt, StageTimer* timer = nullptr);

// The force record of every body after the step (body/body_forces.hpp): (a) and (b) from the carrier, gravity,
// buoyancy and contact from free-body dynamics.
std::vector<BodyForces> measure_forces(Model& model, StageTimer* timer = nullptr);

}  // namespace chute
