#pragma once
// Convection and diffusion of cell-centred scalars (k and epsilon) by the MAC velocity, explicit:
//
//   T(phi)_P = -(1/V) sum_f A_f u_f (phi_f - phi_P) + (1/V) sum_f A_f Gamma_f (phi_N - phi_P) / dc_f
//
// The convective part is the advective form -div(u phi) + phi div(u): a uniform phi stays uniform whatever
// faces are closed. phi_f is the van Leer TVD face value (limiter.hpp), so with forward Euler and
// cfl <= 1/2 the update is bounded (no new extrema: k and epsilon stay positive). Gamma_f = nu + nu_t,f /
// sigma with nu_t,f the mean of the two cells. Faces between a fluid cell and a solid cell (inside an
// immersed body: `fluid` = 0) carry no flux, convective or diffusive: the immersed surface is a zero-flux
// wall for the scalar, and the wall functions set the near-wall cells (immersed_wall.hpp).
// Each face is visited once for all the scalars (they share the velocity, the mask and nu_t).
#include <array>
#include <vector>

#include "field.hpp"
#include "grid_motion.hpp"

namespace chute {

struct TransportedScalar {
    const Field2D* phi;  // needs valid ghosts
    double sigma;        // turbulent Prandtl-Schmidt number
    Field2D* out;        // T(phi) on owned cells (0 in solid cells)
};

// nu_t and fluid need valid ghosts. `lines`: the velocities of moving grid lines (a grid carried by a body-fitted
// block, core/grid/grid_motion.hpp): the scalars are carried by the velocity relative to each face, as the momentum
// is (core/operators/convection.hpp); the advective form (phi_P times the net outflow) is the geometric
// conservation law's term where cells stretch.
void scalar_transport(const Grid& grid, const Velocity& vel, const Field2D& nu_t, double nu, const Field2D& fluid,
                      const std::vector<TransportedScalar>& scalars, const LineVelocities* lines = nullptr);

}  // namespace chute
