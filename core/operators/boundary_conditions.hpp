#pragma once
// Boundary conditions on the four sides of the domain, imposed through boundary faces and ghost cells.
//
//   wall     u_n = 0, u_t = U_wall      ghost u_t mirrors the interior so the wall value is the mean
//   slip     u_n = 0, du_t/dn = 0
//   inflow   u_n, u_t prescribed (uniform vector or a parabola of given peak, cell-averaged so that
//            the flux through each boundary face is exact)
//   outflow  convective:  du_n/dt + U_c du_n/dn = 0 (U_c = mean outflow speed), mass-corrected so that
//                         sum of boundary fluxes is zero; pressure Neumann
//            zero_stress: du_n/dn = 0 on the predicted velocity, p = 0 on the boundary (Dirichlet), the
//                         projection corrects the boundary face
//   periodic handled by the halo exchange (periodic MPI topology)
// The pressure (projection) condition is Neumann on every side but a zero-stress outflow.
#include <array>

#include "field.hpp"
#include "flow_config.hpp"

namespace chute {

class BoundaryConditions {
public:
    BoundaryConditions(const Grid& grid, const std::array<BoundaryConfig, 4>& config);

    // Fill boundary-face normal velocities (wall, slip, inflow) and all ghost values; call after the halo
    // exchange. Idempotent: the time-dependent outflow faces are only changed by the two calls below.
    void apply(Velocity& vel) const;
    // Convective outflow: advance the outflow faces of `next` from the old field `old` over dt.
    // Zero-stress outflow: copy the adjacent interior face (du_n/dn = 0) into the boundary face.
    // Then, if the pressure problem is pure Neumann, shift the convective outflow so mass is conserved.
    void set_outflow(const Velocity& old, Velocity& next, double dt) const;
    // The grid's velocity (a translating body-fitted grid): a convective outflow is carried at the mean outward
    // speed relative to the grid.
    void set_frame_velocity(std::array<double, 2> w) { frame_ = w; }
    // Pressure ghosts: Neumann (copy) or Dirichlet p = 0 (odd mirror) at zero-stress outflows.
    void apply_pressure(Field2D& p) const;

    bool pressure_dirichlet(Side s) const { return dirichlet_[static_cast<int>(s)]; }
    bool pure_neumann() const;
    // Which faces the momentum equation advances on this patch (boundary faces are set here instead).
    int u_first() const { return u_first_; }
    int v_first() const { return v_first_; }
    // Zero-stress outflow faces are corrected by the projection although they are boundary faces.
    bool corrects_face(Side s) const { return dirichlet_[static_cast<int>(s)] && grid_.touches(s); }
    const BoundaryConfig& config(Side s) const { return config_[static_cast<int>(s)]; }
    // Net volume flux out of the domain through all boundary faces (global, per unit depth).
    double net_outflux(const Velocity& vel) const;

private:
    double inflow_normal(Side s, int k) const;  // normal velocity into the domain at boundary face k
    void apply_normal(Velocity& vel) const;
    void apply_ghosts_x(Velocity& vel) const;
    void apply_ghosts_y(Velocity& vel) const;

    const Grid& grid_;
    std::array<BoundaryConfig, 4> config_;
    std::array<bool, 4> dirichlet_{};
    int u_first_ = 0, v_first_ = 0;
    std::array<double, 2> frame_{};
};

}  // namespace chute
