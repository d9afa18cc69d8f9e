#pragma once
// The momentum carried through a motion of grid lines within a step (a body-fitted block's modifier layers,
// band/layers.hpp), in the conservative arbitrary Lagrangian-Eulerian form (Donea et al. 2004):
//
//   V^{n+1} u^{n+1} = V^n u^n - dt sum_f u_f (U_f - w_f) A_f + ...
//
// The step's convective fluxes (core/operators/convection.hpp) take the faces' velocities w_f as the
// Adams-Bashforth combination of the step's and the last step's, which sweep dt AB2(w_f) A_f: `counted`. The
// lines actually move by D_f, known only once the body has moved. Here each control volume keeps the momentum it
// had (its value scaled by its old over its new extent) and exchanges with its neighbour the momentum of the
// volume (D_f - counted_f) A_f its face swept beyond what the fluxes counted, at the face value of the flow at the
// start of the move. The fluid's momentum is kept to round-off, and a uniform flow stays uniform whatever the
// lines do (the geometric conservation law, Thomas & Lombard 1979): the volumes follow the lines exactly.
#include <vector>

#include "field.hpp"

namespace chute {

// Lines of `axis` move from `before` to the grid's lines (the grid holds the new ones; the other axis's lines did
// not move). `target` holds the momentum per unit volume of the old control volumes (u* or u^{n+1}, halos
// exchanged); `face` is the flow whose face values the swept volumes carry (u^n before the projection, u^{n+1}
// after it; halos exchanged); `counted[k]` is how far line k was already swept by the step's fluxes (m). Every
// field in `rescaled` (the Adams-Bashforth history: a rate per unit volume) is scaled by old over new extent.
// Owned faces only; the caller exchanges halos and fills boundaries after.
void move_momentum_with_lines(const Grid& grid, int axis, const std::vector<double>& before,
                              const std::vector<double>& counted, const Velocity& face, Velocity& target,
                              const std::vector<Velocity*>& rescaled);

}  // namespace chute
