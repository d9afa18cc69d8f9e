#pragma once
// One time step of the flow with its bodies, in the order of DESIGN.md's data flow:
//   predict u*  ->  move prescribed bodies to t^{n+1}, predict the free ones  ->  force u* (direct forcing)
//   ->  project  ->  free bodies: hydrodynamic wrench, rigid-body update, contact.
// dt <= 0: the stable step. The time spent on bodies is in StepStats::seconds_forcing.
#include "flow_solver.hpp"
#include "fluid_body_coupling.hpp"
#include "immersed_boundary.hpp"

namespace chute {

StepStats advance(FlowSolver& flow, ImmersedBoundary& bodies, FreeBodies& free_bodies, double dt = 0.0);

}  // namespace chute
