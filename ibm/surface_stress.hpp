#pragma once
// Hydrodynamic force and torque on a body by integrating the stress over its outline, as Turmel & Locat
// (2008, eq. 10-13) do on their body-fitted mesh:
//
//   F = depth * sum_l ( -p_l n_l + tau_l ) ds_l,        M = depth * sum_l (X_l - x_c) x ( ... ) ds_l
//
// On the immersed boundary the fields are smeared within the kernel's reach of the surface, so they are
// sampled on the fluid side: at probe points X_l + d_k h n_l (d_1 < d_2 in cells, h the local spacing),
// bilinear interpolation across MPI patches. Then
//   pressure   p_l = p_1 - d_1 (p_2 - p_1) / (d_2 - d_1)             linear extrapolation to the wall
//   shear      tau_l = rho nu (dw_t/dn) t_l,  w = u - U_body(X)     relative velocity, zero at the wall;
//              dw/dn from the parabola through (0, 0), (d_1 h, w_1), (d_2 h, w_2)
// (at a rigid no-slip wall the viscous traction is rho nu dw/dn, and its normal part vanishes by continuity).
// With a k-epsilon model (k given) the Reynolds stress adds the turbulent part, as Turmel & Locat's eq. 14-15
// take it from OpenFOAM's R = 2/3 k I - nu_t (grad u + grad u^T) at the wall face:
//   turbulent  rho nu_w (dw/dn) t_l - 2/3 rho k_l n_l,   nu_w the wall eddy viscosity of the model's wall
//              law (turbulence/wall_function.hpp, through WallTurbulence) from k_l at the outer probe, y = d_2 h
//   pressure   the solver's p carries 2/3 k (viscous_stress.hpp), so p_l - 2/3 k_l is reported
// The sum of the three is the same with or without the split.
#include <array>
#include <vector>

#include "body.hpp"
#include "body_forces.hpp"
#include "carrier.hpp"
#include "euler_lagrange.hpp"

namespace chute {

class SurfaceStress {
public:
    SurfaceStress(const Grid& grid, const IbmConfig& config, const Body& body, double marker_spacing);
    // p is the kinematic pressure (p / rho), as FlowSolver holds it; turbulence: k and the wall law (or null).
    SurfaceForces compute(const Velocity& vel, const Field2D& p, double density, double viscosity, double depth,
                          const WallTurbulence* turbulence = nullptr);
    // From the last compute(): the surface points (world frame) and the pressure extrapolated to them (Pa).
    const std::vector<Vec2>& points() const { return world_; }
    const std::vector<double>& wall_pressure() const { return wall_pressure_; }

private:
    void place();

    const Grid& grid_;
    const Body& body_;
    std::array<double, 2> d_;
    std::vector<Marker> markers_;  // body frame, on the surface
    std::vector<Vec2> world_, normal_, probe1_, probe2_;
    std::vector<double> h_, wall_pressure_;
    std::vector<Stencil> p1_, p2_, u1_, u2_, v1_, v2_;
    bool placed_ = false;
};

}  // namespace chute
