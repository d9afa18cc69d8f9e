#pragma once
// The stress on a body-fitted hole's sides, integrated face by face (the study's eq. 10-15; what OpenFOAM's
// forces function object sums over a body-fitted patch). Each side segment is one cell face; the fluid cell
// beside it is the wall-adjacent cell, its centre d1 (half a cell) from the side:
//   pressure   p_wall = p_1 + (a_body . n) d1    (kinematic p; the momentum equation at a no-slip wall gives
//              dp/dn = -a_wall . n, Gresho & Sani 1987 eq. 8, its viscous part left out), force -rho p_wall n ds
//   viscous    the tangential faces at the segment's two ends, shear (u_t - U_t) / d1 each (the flux the
//              momentum equation's diffusion takes through the side: the mirrored ghost puts u_t = U_t on it),
//              averaged: force rho nu shear t ds. The normal viscous stress is zero on a no-slip wall (du_n/dn
//              = -du_t/dt = 0 there).
//   turbulent  with a wall law (k-epsilon): the wall eddy viscosity nu_w(k_1, d1) on the same shear, and the
//              normal Reynolds stress -2/3 rho k_1 n; the pressure part then takes the solver's p less 2/3 k_1
//              (the model's p holds 2/3 k), as the immersed surfaces' (ibm/surface_stress.cpp).
// Torques about the body's centre, from the segment's middle.
#include "body.hpp"
#include "body_forces.hpp"
#include "carrier.hpp"
#include "field.hpp"
#include "solid_cells.hpp"

namespace chute {

// Summed over every rank (collective).
SurfaceForces hole_stress(const Grid& grid, const SolidBlock& hole, const BodyState& body, const Velocity& vel,
                          const Field2D& p, double density, double viscosity, double depth,
                          const WallTurbulence* turbulence = nullptr);

}  // namespace chute
