#pragma once
// Carrier 1 (body/carrier.hpp): the bodies imposed on a fixed Cartesian grid by direct forcing on Lagrangian
// markers. What the step asks of it:
//
//   begin_step(u^n)                  the fluid momentum P^n inside each free body (enclosed_momentum)
//   place(t^{n+1})                   prescribed motion (free bodies are placed by rigidbody/free_bodies)
//   impose(u*, dt)                   direct forcing of the predicted velocity (direct_forcing); again on
//                                    u^{n+1} for each further pass of a strongly coupled step, the momentum
//                                    given to the fluid summed over the passes
//   (projection)
//   hydrodynamic_wrench(b, u^{n+1})  on a free body at its predicted place (Uhlmann 2005 eq. 23, the internal
//                                    fluid's momentum from the grid, Kempe & Froehlich 2012):
//                                      F = rho depth ( -sum_l F_l dV_l + (P^{n+1} - P^n) / dt )
//   measure(u^{n+1}, p^{n+1/2})      the hydrodynamic force and torque on each body, two independent ways:
//     (a) from the forcing: for a free body, and for every body on ghost faces, the wrench above (ghost faces:
//         P the momentum the body's region holds, SharpForcing::held_momentum, and the projection's pressure
//         increment through the cut cells' shut parts); on the diffuse interface and forcing faces, for a fixed or
//         prescribed body, the rigid-body form of the internal fluid term (Uhlmann 2005, eq. 23 and 28),
//           F = rho depth ( -sum_l F_l dV_l + A dU_c/dt ),   M = rho depth ( -sum_l r_l x F_l dV_l + J domega/dt )
//         A the area and J the polar moment of area of the body: the fluid inside the outline moves with it;
//     (b) from the stress on the surface, split into pressure, viscous and turbulent parts (surface_stress).
// Both refer to the step's mid-point in time: the forcing acts over the step and the pressure is p^{n+1/2}.
// The walls a turbulence model sees are the cells beside the outlines (immersed_wall).
#include <memory>
#include <optional>
#include <vector>

#include "carrier.hpp"
#include "cut_faces.hpp"
#include "enclosed_momentum.hpp"
#include "ibm_config.hpp"
#include "immersed_forcing.hpp"
#include "immersed_wall.hpp"
#include "sharp_forcing.hpp"
#include "surface_stress.hpp"

namespace chute {

// What the immersed boundary needs of a case (run/case_settings.hpp gathers it).
struct ImmersedBoundarySettings {
    IbmConfig ibm;
    double density = 1000.0, viscosity = 1e-6, depth = 1.0;  // the fluid's, and the run's span
    double image_distance = 2.0;  // cells: where wall functions sample the flow (turbulence.image_distance)
    // With a wall-function turbulence model, its law of the wall (the sharp interface's profile beside a surface);
    // empty: laminar.
    WallProfile wall_profile;
};

class ImmersedBoundary final : public Carrier {
public:
    // `bodies` are the run's; they outlive the carrier.
    ImmersedBoundary(const Grid& grid, const ImmersedBoundarySettings& settings, std::vector<Body>& bodies);

    const std::vector<Body>& bodies() const override { return bodies_; }
    double cell_size(std::size_t b) const override { return forcing_->cell_size(b); }

    void begin_step(const Velocity& start) override;
    void place(double t) override;
    void impose(Velocity& predicted, double dt) override;
    Wrench hydrodynamic_wrench(std::size_t b, const Velocity& vel, double dt) override;
    // Ghost faces: a free body is coupled exactly (body/carrier.hpp). Its added mass over the step is the wrench of
    // the cut pressure problem's response to the body's surfaces in a unit motion along each free degree of freedom
    // (x, y, rotation about its centre; FlowSolver::cut_response, CutFaces::pressure_wrenches), M_jk = -W_j(phi_k),
    // computed with the step's matrix in hydrodynamic_wrench() (one Poisson solve per free degree of freedom);
    // body_moved() adds the response to the change the update made to the motion the step imposed, so the next step
    // starts from a flow that moves with the body. Without it the body met the flow's answer to its last change a
    // step late, and a block whose added mass grows as it nears the bed diverged 3 cm above it (docs/validation.md,
    // "Sharp interface", seventh step). Forcing faces and the diffuse interface: none (passes and the virtual mass).
    std::optional<Eigen::Matrix3d> added_mass(std::size_t b) const override;
    void body_moved(std::size_t b, double dt) override;
    std::vector<BodyForces> measure(const Velocity& vel, const Field2D& p, const WallTurbulence* turbulence) override;

    void locate_walls() override { walls_.locate(); }
    const Field2D& fluid_cells() const override { return walls_.fluid(); }
    std::vector<WallSample> sample_walls(const Velocity& vel, const Field2D& k) const override {
        return walls_.sample(vel, k);
    }
    bool walls_between_cells() const override { return walls_.near_wall() == NearWall::surface; }
    // Ghost faces: the open flux the cut ghost faces carry from step to step (SharpForcing::open_flux).
    NamedArrays checkpoint_arrays() const override;
    void restored(const NamedArrays& arrays) override;

    void attach(FlowSolver& flow) override;
    void attach_turbulence(const WallTurbulence& turbulence) override { wall_turbulence_.emplace(turbulence); }

    const ImmersedForcing& forcing() const { return *forcing_; }
    // Ghost faces: the responses of the exact coupling solved so far (the others kept from an earlier step), for tests
    // and diagnostics.
    std::size_t responses_solved() const { return responses_solved_; }
    const SurfaceStress& surface_stress(std::size_t b) const { return *stress_[b]; }

private:
    const Grid& grid_;
    ImmersedBoundarySettings settings_;
    std::vector<Body>& bodies_;
    std::unique_ptr<ImmersedForcing> forcing_;
    SharpForcing* sharp_ = nullptr;  // forcing_ when the interface is sharp
    FlowSolver* flow_ = nullptr;
    std::optional<WallTurbulence> wall_turbulence_;  // attach_turbulence(); laminar: none
    Velocity diffused_;  // cut momentum with implicit diffusion: u* as the implicit solve left it
    std::vector<std::unique_ptr<SurfaceStress>> stress_;
    ImmersedWall walls_;
    std::unique_ptr<CutFaces> cut_;  // with ghost faces: the faces the surfaces cut, for the pressure problem
    bool pressure_boundary_set_ = false;
    void set_pressure_boundary();  // the flow's pressure problem from cut_
    // The wrench of the step on body b from the forcing, the momentum inside and (ghost faces) the pressure increment:
    // measure (a) of a free body, and of every body on ghost faces.
    Wrench interface_wrench(std::size_t b, const Velocity& vel, double dt) const;
    std::vector<EnclosedMomentum> start_momentum_;  // P^n of each free body (ghost faces: of every body)
    std::vector<Vec2> start_centre_;                // the centres P^n's moments are about
    std::vector<BodyForcing> step_forcing_;         // the forcing of the step, summed over its passes
    std::vector<Wrench> wrench_;                    // the last hydrodynamic wrench of each free body
    // Ghost faces, per free body: its free degrees of freedom (0 x, 1 y, 2 rotation), their unit motions' shut-face
    // velocities and the flow's response to them in this step, its added mass, and the motion the step imposed
    // (body_moved()).
    struct Coupling {
        std::vector<int> motions;
        std::vector<Velocity> unit;
        const FlowSolver::BodyResponse* response = nullptr;  // kept_response_'s, valid until the next step's
        Eigen::Matrix3d added_mass = Eigen::Matrix3d::Zero();
        Eigen::Vector3d imposed = Eigen::Vector3d::Zero();
    };
    std::vector<std::optional<Coupling>> coupling_;
    // The flow's response to body b's unit motions: solved, or the last one solved for it when everything it is
    // computed from is the same bit for bit. Collective.
    const FlowSolver::BodyResponse& response(std::size_t b, const std::vector<Velocity>& unit);
    // What the cut pressure problem's matrix is made of: the cut faces' apertures, the cells with flow and the grid's
    // spacings, this rank's part.
    std::vector<double> pressure_inputs() const;
    // `holds` true on every rank. Collective.
    bool on_every_rank(bool holds) const;
    std::vector<double> pressure_inputs_;  // of the matrix set last
    std::size_t pressure_matrix_ = 0;      // counts the matrices set (set_pressure_boundary)
    struct KeptResponse {
        std::size_t matrix;          // the pressure_matrix_ it was solved with
        std::vector<Velocity> unit;  // the unit motions' shut-face velocities it answers
        FlowSolver::BodyResponse response;
    };
    std::vector<std::optional<KeptResponse>> kept_response_;
    std::size_t responses_solved_ = 0;
};

}  // namespace chute
