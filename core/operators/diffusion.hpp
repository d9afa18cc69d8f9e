#pragma once
// Viscous term nu * laplacian(u) in finite-volume form on the MAC grid (constant kinematic viscosity):
//   D_u(i,j) = nu { [ (u_{i+1}-u_i)/w_x(i) - (u_i-u_{i-1})/w_x(i-1) ] / dc_x(i)
//                 + [ (u_{j+1}-u_j)/dc_y(j+1) - (u_j-u_{j-1})/dc_y(j) ] / w_y(j) }
// and the same with x and y exchanged for v. Wall values enter through the mirrored ghost cells.
#include "field.hpp"

namespace chute {

// out += nu * laplacian(vel) on the advanced faces.
void add_diffusion(const Grid& grid, double nu, const Velocity& vel, int u_first, int v_first, Velocity& out);

}  // namespace chute
