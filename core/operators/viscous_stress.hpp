#pragma once
// Viscous and turbulent (Boussinesq) stress with a variable eddy viscosity, on the MAC grid:
//
//   f_i = d/dx_j [ (nu + nu_t) (du_i/dx_j + du_j/dx_i) ]
//
// The normal stresses 2 (nu + nu_t) du/dx live at cell centres, the shear stresses (nu + nu_t)(du/dy + dv/dx)
// at cell corners; nu_t at corners is the mean of the four cells around, except on wall sides where the
// turbulence model puts the wall-function value (the viscosity that makes the mirrored-ghost gradient carry
// the log-law wall shear). With nu_t = 0 this is nu laplacian(u) + nu grad(div u), the same as diffusion.hpp
// on a divergence-free field. The isotropic part 2/3 k of the Reynolds stress is carried by the pressure.
#include "field.hpp"

namespace chute {

struct EddyViscosity {
    Field2D cell;      // nu_t at cell centres, ghosts filled
    Field2D corner;    // nu_t at corner (i, j) = (xf(i), yf(j)), i in [0, nx], j in [0, ny]
    double max = 0.0;  // largest nu_t on any rank (time-step limit)
    explicit EddyViscosity(const Grid& g) : cell(g), corner(g) {}
    EddyViscosity() = default;
};

// out += div[(nu + nu_t)(grad u + grad u^T)] on the advanced faces.
void add_viscous_stress(const Grid& grid, double nu, const EddyViscosity& eddy, const Velocity& vel, int u_first,
                        int v_first, Velocity& out);

// out += the cross terms d/dy[(nu + nu_t) dv/dx] (u faces) and d/dx[(nu + nu_t) du/dy] (v faces): the part
// of the stress left explicit when the rest is implicit (implicit_diffusion.hpp).
void add_cross_stress(const Grid& grid, double nu, const EddyViscosity& eddy, const Velocity& vel, int u_first,
                      int v_first, Velocity& out);

}  // namespace chute
