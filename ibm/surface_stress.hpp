#pragma once
// Hydrodynamic force and torque on a body by integrating the stress over its outline, as Turmel & Locat
// (2008, eq. 10-13) do on their body-fitted mesh:
//
//   F = depth * sum_l ( -p_l n_l + tau_l ) ds_l,        M = depth * sum_l (X_l - x_c) x ( ... ) ds_l
//
// On the immersed boundary the fields are smeared within the forcing's reach of the surface (kernel support
// less the retraction: 2 - 0.43 = 1.57 cells out with the default roma3_smoothed, 1.2 with roma3 and 0.3), and a
// bilinear probe reads grid points up to one cell nearer the surface than itself; so they are sampled beyond
// the reach plus a cell (the first default probe, 2.5 cells, reads points from 1.5 cells: at the smear's edge), at
// probes X_l + d_k h n_l (numerics.ibm.stress_probes, default d = 2.5, 3.5, 4.5 cells, and 1.5, 2.5, 3.5 on the sharp
// interface, whose field has no smear to clear; h the local spacing), bilinear
// interpolation across MPI patches, and fitted by least squares in y = d h (fit_weights):
//   pressure   p(y) = p_l + (dp/dn) y + c y^2, with the wall-normal gradient the momentum equation sets at a
//              no-slip wall (Gresho & Sani 1987, IJNMF 7:1111, eq. 8):
//                dp/dn = -a_wall . n - nu d(gamma)/ds   (kinematic; a_wall the wall's acceleration, gamma the
//                                                        wall shear rate below, s along t)
//              With the slope fixed the fit carries only the curvature: a free slope extrapolated over 2.5
//              cells amplifies the outer profile's curvature (near the block's corners, DFG's front).
//   shear      tau_l = rho nu gamma_l t_l,  gamma_l = dw/dn of w(y) = gamma y + b y^2 (no slip at y = 0),
//              w = (u - U_body(X)) . t the relative velocity; truncation error O(w_nnn d^2 h^2).
// (at a rigid no-slip wall the viscous traction is rho nu dw/dn, and its normal part vanishes by continuity).
// The profiles measured, and why 2.5-4.5 cells: docs/validation.md ("Surface stress (b)").
// With a k-epsilon model (k given) the Reynolds stress adds the turbulent part, as Turmel & Locat's eq. 14-15
// take it from OpenFOAM's R = 2/3 k I - nu_t (grad u + grad u^T) at the wall face:
//   turbulent  rho nu_w (dw/dn) t_l - 2/3 rho k_l n_l,   nu_w the wall eddy viscosity of the model's wall
//              law (turbulence/wall_function.hpp, through WallTurbulence) from k_l at the outermost probe
//   pressure   the solver's p carries 2/3 k (viscous_stress.hpp), so p_l - 2/3 k_l is reported
// The sum of the three is the same with or without the split.
#include <vector>

#include "body.hpp"
#include "body_forces.hpp"
#include "carrier.hpp"
#include "euler_lagrange.hpp"
#include "grid_placement.hpp"

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
    std::vector<double> along_outline(const std::vector<double>& f) const;  // d f / ds at each point

    const Grid& grid_;
    const Body& body_;
    std::vector<double> d_;                                 // probe distances, cells
    std::vector<Marker> markers_;                           // body frame, on the surface
    std::vector<double> pressure_weights_, shear_weights_;  // fit_weights of the probes
    std::vector<Vec2> world_, normal_;
    std::vector<std::vector<Vec2>> probes_;  // [probe][point]
    std::vector<double> h_, wall_pressure_;
    std::vector<std::vector<Stencil>> sp_, su_, sv_;  // [probe][point]
    GridPlacement placement_{grid_};                  // of the probes
};

// Weights w_k of the least-squares fit f(d) = sum_m c_m d^(powers_m) through (d_k, f_k): the first coefficient
// is c_0 = sum_k w_k f_k. Powers {0, 2}: the wall value of a profile whose slope at the wall was taken out;
// {1, 2}: the wall slope of a profile through the origin.
std::vector<double> fit_weights(const std::vector<double>& d, const std::vector<int>& powers);

}  // namespace chute
