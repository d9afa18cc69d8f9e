#pragma once
// Pressure projection (Chorin 1968; Kim & Moin 1985 for the staggered-grid form):
//   laplacian(p^{n+1}) = div(u*) / dt,      u^{n+1} = u* - dt grad(p^{n+1})
// Discrete divergence and gradient are adjoint on the MAC grid, so the projected field is divergence-free
// to the Poisson solver's tolerance in every cell:
//   div(i,j)     = (u_{i+1,j} - u_{i,j}) / w_x(i) + (v_{i,j+1} - v_{i,j}) / w_y(j)
//   grad_x(i,j)  = (p_{i,j} - p_{i-1,j}) / dc_x(i)          (on u faces)
#include "boundary_conditions.hpp"
#include "field.hpp"

namespace chute {

// The discrete divergence of cell (i, j): the one definition used by the projection and the diagnostics.
inline double cell_divergence(const Grid& grid, const Velocity& vel, int i, int j) {
    return (vel.u(i + 1, j) - vel.u(i, j)) / grid.lx().w(i) + (vel.v(i, j + 1) - vel.v(i, j)) / grid.ly().w(j);
}

// out(i, j) = scale * div(vel) on the owned cells.
void divergence(const Grid& grid, const Velocity& vel, double scale, Field2D& out);
// vel -= dt grad(p) on the advanced faces and on boundary faces with a pressure (Dirichlet) condition; with the
// faces' apertures (FlowSolver::PressureBoundary), only on the faces open to the flow (alpha > 0).
// p must have valid ghosts.
void subtract_pressure_gradient(const Grid& grid, const BoundaryConditions& bc, const Field2D& p, double dt,
                                Velocity& vel, const Field2D* aperture_u = nullptr,
                                const Field2D* aperture_v = nullptr);

}  // namespace chute
