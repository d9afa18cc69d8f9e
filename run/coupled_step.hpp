#pragma once
// One time step of the flow with its bodies, in the order of DESIGN.md's data flow:
//   predict u*  ->  move prescribed bodies to t^{n+1}, predict the free ones  ->  force u* (direct forcing)
//   ->  project  ->  free bodies: hydrodynamic wrench, rigid-body update, contact  ->  turbulence update.
// dt <= 0: the stable step. The time spent on bodies is in StepStats::seconds_forcing, on the turbulence
// model in StepStats::seconds_turbulence.
#include "flow_solver.hpp"
#include "fluid_body_coupling.hpp"
#include "immersed_boundary.hpp"
#include "k_epsilon.hpp"

namespace chute {

StepStats advance(FlowSolver& flow, ImmersedBoundary& bodies, FreeBodies& free_bodies, double dt = 0.0,
                  KEpsilon* turbulence = nullptr);

}  // namespace chute
