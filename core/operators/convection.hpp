#pragma once
// Convective term of the momentum equation in conservative finite-volume form on the MAC grid.
//
// For the u control volume around face (i, j), of width dc_x(i) and height w_y(j):
//   C_u = [ (U u)_e - (U u)_w ] / dc_x(i) + [ (V u)_n - (V u)_s ] / w_y(j)
// The transporting velocities U, V are the volume fluxes through the control-volume faces (averages of
// the neighbouring face velocities weighted by the part of the face in each cell, so that the discrete
// continuity of the u control volume follows from that of the cells). The transported value is
//   central:  linear interpolation to the face (second order, non-dissipative; for validation),
//   van_leer, koren: upwind value plus a limited anti-diffusive correction (TVD, bounded; for high Re),
//            phi_f = phi_U + 1/2 psi(r) (phi_D - phi_U),  r = (phi_U - phi_UU) / (phi_D - phi_U).
// The v equation is the same with x and y exchanged.
#include <array>

#include "field.hpp"
#include "flow_config.hpp"
#include "grid_motion.hpp"

namespace chute {

// out(i, j) = -C(i, j) on the faces [u_first, nx) x [0, ny) for u and [0, nx) x [v_first, ny) for v.
// On a grid whose lines move (`lines`, core/grid/grid_motion.hpp: the body-fitted grid carried by its block;
// arbitrary Lagrangian-Eulerian form, Donea et al. 2004) the transporting velocities are relative to the faces,
// U - w_f, while the transported velocity stays the inertial one. The rate stays per unit volume of the control
// volume at the start of the step; where the lines stretch it (a modifier layer), the flow solver carries the
// momentum to the new volumes (core/operators/line_motion.hpp).
// `wall_faces` (null: none): nonzero on the faces a sharp immersed surface sets from strictly inside its body (ghost
// faces holding the mirror 2 U_b - u(image) of ibm/sharp_forcing.hpp, and the body's velocity deeper in; not a face
// on the surface, which holds the wall's own velocity as a body-fitted wall's face does), ghosts included. A flux
// between such a face and its neighbour takes the central value whatever the scheme: with the mirror that is the
// wall's own velocity, so the momentum a moving wall carries across the face is the wall's (U_b . n U_b, as on a
// body-fitted wall whose grid moves with it: none relative to it). The upwind value would be the mirror ahead of a
// moving front (or the fluid's behind a back face): a spurious flux U_b . n (u_1 - U_b) that does not vanish as the
// grid is refined; it held about half of the 5 % by which the study's block moving through still water had less
// drag than held in a stream (docs/validation.md, "Sharp interface", fourth step). On a held wall the
// transporting velocity there is about 0, so the choice changes nothing (2e-5 of the held block's drag).
// `transport` (null: `vel`): the velocities that transport the momentum across the control volumes' sides (each side's
// the mean of the two faces beside it), `vel` staying the transported one. With a sharp surface's cut faces
// (FlowSolver::PressureBoundary::cut_transport) they are the faces' volume fluxes per unit area, alpha u + (1 - alpha)
// U_b: a side the surface shuts carries the body's flux, not the mirrored velocity of the ghost faces beside it, and
// each control volume's continuity is that of its two cells, which the projection met (the cut cells' staggered
// momentum of Cheny & Botella 2010, JCP 229:1043, LS-STAG). The flow solver then hands the transported `vel` with
// the body's velocity on the shut faces and no `wall_faces` (the scheme's own value everywhere).
// `far` (null: `vel`): the values the limiter reads two faces upwind or downwind (its ratio r), there the ghost faces'
// mirrors.
void convection(const Grid& grid, ConvectionScheme scheme, const Velocity& vel, int u_first, int v_first, Velocity& out,
                const LineVelocities* lines = nullptr, const Velocity* wall_faces = nullptr,
                const Velocity* transport = nullptr, const Velocity* far = nullptr);

}  // namespace chute
