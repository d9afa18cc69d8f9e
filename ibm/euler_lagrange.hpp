#pragma once
// Transfers between Lagrangian points and the staggered Eulerian grid, across MPI patches.
//
// A stencil links one point X to the owned grid points x of one staggering (u faces, v faces or cell
// centres) with weights w(x, X) that sum to one over all ranks:
//   delta:    w = phi((x - X)/hx) phi((y - Y)/hy), normalised (Uhlmann 2005 eq. 13-14 on a uniform grid,
//             where the sum is already one; on a stretched grid h is the local spacing at X)
//   bilinear: the four surrounding points (probes for the surface stress).
// Points outside the domain (ghost faces, boundary faces whose value a boundary condition sets) are left
// out before normalising. Every rank builds every point's stencil from the global grid lines and keeps the
// part it owns, so
//   interpolate:  U(X)  = sum_x w(x, X) u(x)                  (each rank sums its part; MPI_Allreduce)
//   spread:       u(x) += sum_X w(x, X) A(X) / V(x)            (A an amount of momentum per density,
//                                                                  V(x) the control volume of x)
// are adjoint, and spreading conserves momentum exactly: sum_x V(x) du(x) = sum_X A(X).
#include <vector>

#include "delta_kernel.hpp"
#include "field.hpp"
#include "outline.hpp"

namespace chute {

enum class Staggering { u_face, v_face, cell };

struct StencilPoint {
    int i, j;           // local indices of an owned point
    double weight;      // w(x, X)
    double inv_volume;  // 1 / V(x)
};
using Stencil = std::vector<StencilPoint>;

std::vector<Stencil> delta_stencils(const Grid& grid, DeltaKernel kernel, Staggering s,
                                    const std::vector<Vec2>& points);
std::vector<Stencil> bilinear_stencils(const Grid& grid, Staggering s, const std::vector<Vec2>& points);

// Interpolated values at every point, on every rank (collective).
std::vector<double> interpolate(const Grid& grid, const std::vector<Stencil>& stencils, const Field2D& f);
// Velocity at every point from u-face and v-face stencils: one collective reduction for both components.
std::vector<Vec2> interpolate_velocity(const Grid& grid, const std::vector<Stencil>& su, const std::vector<Stencil>& sv,
                                       const Velocity& vel);
// Adds each point's amount, spread by its stencil, to f (owned points only; not collective).
void spread(const std::vector<Stencil>& stencils, const std::vector<double>& amounts, Field2D& f);

// Local grid spacing (hx, hy) of the cell containing X (clamped to the domain).
Vec2 local_spacing(const Grid& grid, const Vec2& X);

}  // namespace chute
