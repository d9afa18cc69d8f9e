#pragma once
// The immersed bodies of a run and what the time step asks of them:
//
//   move_to(t^{n+1})                 prescribed motion (free bodies: rigidbody/fluid_body_coupling)
//   force(u*, dt)                    direct forcing of the predicted velocity (direct_forcing)
//   (projection)
//   forces(u^{n+1}, p^{n+1/2})       hydrodynamic force and torque on each body, two independent ways:
//     (a) from the forcing (Uhlmann 2005, eq. 23 and 28, rigid-body form of the internal fluid term):
//           F = rho depth ( -sum_l F_l dV_l + A dU_c/dt ),   M = rho depth ( -sum_l r_l x F_l dV_l + J domega/dt )
//         A the area and J the polar moment of area of the body: the fluid inside the outline moves with it;
//     (b) from the stress on the surface, split into pressure, viscous and turbulent parts (surface_stress).
// Both refer to the step's mid-point in time: the forcing acts over the step and the pressure is p^{n+1/2}.
#include <memory>
#include <vector>

#include "body.hpp"
#include "direct_forcing.hpp"
#include "flow_solver.hpp"
#include "surface_stress.hpp"

namespace chute {

struct BodyForces {
    Vec2 forcing = Vec2::Zero();   // (a), N
    double forcing_torque = 0.0;   // (a), N m
    SurfaceForces surface;         // (b), N and N m
    double max_slip = 0.0, rms_slip = 0.0;  // m/s after the forcing iterations
    // Free bodies only (rigidbody/fluid_body_coupling), N and N m; zero for fixed and prescribed bodies.
    Vec2 gravity = Vec2::Zero(), buoyancy = Vec2::Zero(), contact = Vec2::Zero();
    double contact_torque = 0.0;
};

class ImmersedBoundary {
public:
    ImmersedBoundary(const Grid& grid, const CaseConfig& config);

    bool empty() const { return bodies_.empty(); }
    const Grid& grid() const { return grid_; }
    const std::vector<Body>& bodies() const { return bodies_; }
    Body& body(std::size_t b) { return bodies_[b]; }  // free bodies are moved from outside (rigidbody/)
    void move_to(double t);
    void force(Velocity& star, double dt) { forcing_->apply(star, dt); }
    // k: the turbulence energy when a k-epsilon model runs (adds the turbulent part of the surface stress).
    std::vector<BodyForces> forces(const Velocity& vel, const Field2D& p, const Field2D* k = nullptr) const;
    const DirectForcing& forcing() const { return *forcing_; }
    const SurfaceStress& surface_stress(std::size_t b) const { return *stress_[b]; }

private:
    const Grid& grid_;
    const CaseConfig& config_;
    std::vector<Body> bodies_;
    std::unique_ptr<DirectForcing> forcing_;
    std::vector<std::unique_ptr<SurfaceStress>> stress_;
};

}  // namespace chute
