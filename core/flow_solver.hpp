#pragma once
// The incompressible Navier-Stokes solver: state, and one time step of the projection method.
//
//   d u / dt + div(u u) = -grad p + nu laplacian(u) + f,      div u = 0
//
// One step (Adams-Bashforth 2 for convection and diffusion, incremental pressure-correction projection,
// van Kan 1986; the form Uhlmann 2005 uses so that immersed-boundary forcing sees the pressure gradient):
//   predict:
//     H^n  = -C(u^n) + nu L(u^n) + f
//     u*   = u^n + dt [ (1 + r/2) H^n - (r/2) H^{n-1} - grad p^{n-1/2} ],   r = dt^n / dt^{n-1}
//     boundary faces of u* (inflow, wall, outflow)
//   with implicit diffusion H^n keeps only the cross terms of the stress and u* then takes the backward-Euler
//   step of the rest (core/implicit_diffusion.hpp)
//   (an immersed-boundary forcing may edit u* here: ibm/direct_forcing)
//   project:
//     laplacian(phi) = div(u*) / dt          (hypre PCG + PFMG, starting from r (p^{n-1/2} - p^{n-3/2}))
//     u^{n+1} = u* - dt grad phi,   p^{n+1/2} = p^{n-1/2} + phi
// With explicit diffusion this is the same discrete system as solving for p directly (phi = p^{n+1/2} -
// p^{n-1/2}); the pressure is second order at t^{n+1/2} (tests/unit/test_taylor_green.cpp).
// The first step (and the first after a change of scheme) is forward Euler.
#include <array>
#include <memory>
#include <vector>

#include "boundary_conditions.hpp"
#include "field.hpp"
#include "flow_config.hpp"
#include "grid_motion.hpp"
#include "halo_exchange.hpp"
#include "implicit_diffusion.hpp"
#include "poisson_solver.hpp"
#include "solid_cells.hpp"
#include "stage_timer.hpp"
#include "viscous_stress.hpp"

namespace chute {

struct StepStats {
    double dt = 0.0;
    int poisson_iterations = 0;
    int diffusion_iterations = 0;  // implicit diffusion: PCG iterations of the larger component
    double poisson_residual = 0.0;
    int coupling_passes = 0;            // forcing and projection passes of the step (run/step.cpp: strong coupling)
    bool coupling_unconverged = false;  // the passes stopped short of numerics.coupling.tolerance
};

class FlowSolver {
public:
    FlowSolver(const FlowConfig& config, MPI_Comm comm);

    // Impose the initial condition of the case (uniform current or Taylor-Green vortex) at time 0.
    void set_initial_condition();
    // Advance by one step of size dt (or the stable step if dt <= 0): predict() then project().
    StepStats advance(double dt = 0.0);
    // The two halves of a step, for a caller that forces the predicted velocity in between.
    // predict() returns the dt it uses; predicted() is u* (owned faces valid, halos not) until project().
    double predict(double dt = 0.0);
    Velocity& predicted() { return star_; }
    StepStats project();
    // A further pass within the step just taken, for a body coupled strongly to the flow (run/step.cpp):
    // reopen() hands back u^{n+1} as the velocity to force again, reproject() projects it again
    // (laplacian(phi) = div(u)/dt from phi = 0, u -= dt grad phi, p^{n+1/2} += phi). Time, step count and
    // the AB2 history stay those of the step; the returned stats are this pass's solve.
    Velocity& reopen();
    StepStats reproject();
    // After a step in which a body's velocity jumped (an impact): p^{n+1/2} holds the impulsive pressure / dt
    // that reversed the water with it, an impulse of that instant only. Kept, the next step's prediction
    // (u* = ... - dt grad p) would give the water that impulse again, so the next step starts from p^{n-1/2}.
    void forget_impulsive_pressure();
    // The step advance() would take: min of the CFL and diffusion limits (none with implicit diffusion),
    // max_dt, or the fixed dt.
    double next_dt() const;
    // A turbulence model writes its eddy viscosity here (turbulence/); from then on the momentum equation
    // uses div[(nu + nu_t)(grad u + grad u^T)] and the diffusion limit of the step counts nu + max nu_t
    // (explicit diffusion only).
    EddyViscosity& eddy_viscosity() {
        eddy_on_ = true;
        return eddy_;
    }
    bool turbulent() const { return eddy_on_; }
    const EddyViscosity& eddy_viscosity() const { return eddy_; }

    const Grid& grid() const { return *grid_; }
    const FlowConfig& config() const { return config_; }
    const Velocity& velocity() const { return vel_; }
    const Field2D& pressure() const { return p_; }
    double time() const { return time_; }
    long step() const { return step_; }

    // State access for initial conditions, tests and checkpoints. After editing the velocity, call
    // refresh_ghosts() so halos and boundary values are consistent.
    Velocity& velocity() { return vel_; }
    Field2D& pressure() { return p_; }
    Velocity& previous_rhs() { return rhs_old_; }    // H^{n-1} of the AB2 scheme
    Field2D& previous_pressure() { return p_old_; }  // p^{n-3/2}, for the Poisson solver's starting guess
    double previous_dt() const { return dt_previous_; }
    // Whether the last step's diffusion was implicit (checkpoints carry it: `auto` switches with hysteresis).
    bool implicit_diffusion() const { return implicit_now_; }
    // The counters of a checkpoint's step. Ghosts are not filled: the caller does (refresh_ghosts()) once the solid
    // cells are those of the checkpoint (run/restart_state.cpp).
    void restore(long step, double time, double dt_previous, bool implicit_diffusion = false);
    // Cells taken out of the fluid (a body-fitted hole; null: none). The solver fills their faces whenever it
    // fills the boundaries' ghosts and leaves them out of the pressure problem; call again after the blocks
    // changed cells (core/grid/solid_cells.hpp). The object must outlive the solver or the next call.
    void set_solid_cells(const SolidCells* solid);
    // Project the velocity as it stands (u -= grad phi, laplacian phi = div u; pressure unchanged): what
    // set_solid_cells() does to the start, so that an impulsive start is divergence-free before the first step.
    void project_start();
    const SolidCells* solid_cells() const { return solid_; }
    // Sharp immersed surfaces (ibm/sharp_forcing.hpp with ghost faces, ibm/cut_faces.hpp): the pressure problem
    // follows them. `cells`: 1 in the cells that hold flow, 0 in those left out (their rows the identity);
    // `aperture_u`, `aperture_v`: the open fraction alpha of each face, which scales its coefficient A / d in the
    // problem; the flux of the continuity equation through a face is A (alpha (u* + offset) + (1 - alpha) U_b) with
    // U_b from `body_velocity` and the offset from `flux_offset` (null: 0), and the projection corrects the faces with
    // alpha > 0. The fields must outlive the solver or the
    // next call; call again when they changed (it rebuilds the matrix and its multigrid hierarchy). Not with solid
    // cells. Collective.
    struct PressureBoundary {
        const Field2D* cells = nullptr;
        const Field2D* aperture_u = nullptr;
        const Field2D* aperture_v = nullptr;
        const Velocity* body_velocity = nullptr;
        const Velocity* flux_offset = nullptr;
        // The convection transported by these fluxes instead of the velocities (core/operators/convection.hpp), and
        // the momentum of a face shut whole the body's velocity U_b in it, not the value the forcing set there (a
        // ghost face's mirror): a face whose open part closes holds U_b, so nothing the convection reads jumps as a
        // surface crosses a grid line (the study's block held in a stream read 5 % less drag just before its front
        // and back reached a line than on it; docs/validation.md, "Sharp interface", fourteenth step).
        bool cut_transport = false;
    };
    void set_pressure_boundary(const PressureBoundary& boundary);
    // Faces a sharp immersed surface sets from inside its bodies (nonzero; the owned faces, null: none): the
    // convective flux between one of them and its neighbour is the wall's (core/operators/convection.hpp). The field
    // must outlive the solver or the next call; it is read, with its halo exchanged here, at every step's prediction.
    void set_wall_faces(const Velocity* faces) { wall_faces_ = faces; }
    // The largest |divergence| of the velocity over the cells that hold flow: of the flux through the faces' open
    // parts and the bodies' through the rest, with a pressure boundary (what the projection makes zero). Collective.
    double max_divergence() const;
    // 1 in the cells that hold flow, 0 in the others (a hole's, or those set_pressure_boundary() left out); null: all.
    const Field2D* fluid_cells() const { return solid_ && !solid_->empty() ? &solid_->fluid() : cut_.cells; }
    // The momentum the last step's fluxes carried into a solid block, per unit time, density and depth (m^3/s^2:
    // the force on it / (rho depth)): the sum over the block's faces of V (H_step - grad p^{n+1/2}), H_step the
    // step's Adams-Bashforth combination of convection and diffusion. The operators are conservative, so the
    // fluxes inside the block cancel and what is left is what crossed its sides: the fluid's momentum balance
    // closes exactly. Explicit diffusion only (a body-fitted run refuses the implicit one). Collective.
    std::array<double, 2> solid_momentum_rate(const SolidBlock& block) const;
    // The flow's answer to a solid block's velocity U within a step (the strong coupling of a free body-fitted
    // body, band/body_fitted.hpp). The projection is linear in U, which enters only through the sides' normal
    // faces: changing U by dU after the step changes u^{n+1} by sum_k dU_k velocity[k] and p^{n+1/2} by
    // sum_k dU_k pressure[k] / dt, where pressure[k] = phi_k with laplacian(phi_k) = div(e_k on the sides) and
    // velocity[k] = -grad phi_k on the fluid faces (k = x, y). It depends on the grid's spacings alone, so one
    // computation serves a rigidly translating grid for the whole run. Collective: two Poisson solves.
    struct BodyResponse {
        std::vector<Velocity> velocity;
        std::vector<Field2D> pressure;
    };
    // `previous`: a response on a nearby grid (the lines stretched a little), the solves' starting guess. `along`:
    // the directions to solve for (a body locked along the other leaves its response there zero: one solve, not two).
    BodyResponse hole_response(std::size_t block, const BodyResponse* previous = nullptr,
                               std::array<bool, 2> along = {true, true});
    // The same for a body that a sharp surface cuts into the pressure problem (set_pressure_boundary), one entry per
    // motion k of the body: the shut parts of the faces moving at shut_velocity[k] (the body's surfaces in a unit
    // translation or rotation, every other face at rest: CutFaces::shut_velocity), the fluid at rest: pressure[k] =
    // phi_k with laplacian(phi_k) the divergence of A (1 - alpha) shut_velocity[k], velocity[k] = -grad phi_k on the
    // faces the projection corrects (alpha > 0), with the matrix of the step's projection. Collective: one Poisson
    // solve per entry.
    BodyResponse cut_response(const std::vector<Velocity>& shut_velocity);
    // The step's u^{n+1} and p^{n+1/2} changed by the response to the motions' changes `change` (one per entry), the
    // body already holding its new velocity (a hole's faces are filled from it). Collective.
    void add_body_response(const BodyResponse& response, const std::vector<double>& change, double dt);
    // The sum over a solid block's faces of V grad(q) (m^3 times q's unit per metre): the pressure part of
    // solid_momentum_rate for a field q. Collective.
    std::array<double, 2> solid_gradient_sum(const SolidBlock& block, const Field2D& q) const;
    // A grid that translates rigidly (a body-fitted block carrying it): shift every line by (dx, dy) and take w
    // as the grid's velocity, which the convective fluxes and the step's limit see relative to it
    // (core/operators/convection.hpp). Spacings do not change, so neither does the Poisson matrix.
    void translate_grid(double dx, double dy);
    void set_frame_velocity(std::array<double, 2> w) {
        set_grid_motion({{AxisMotion::whole(w[0]), AxisMotion::whole(w[1])}});
    }
    // Lines that move at their own velocities (core/grid/grid_motion.hpp): the fluxes and the step's limit see the
    // velocity relative to each face, and the domain's boundaries the velocity of their own lines.
    void set_grid_motion(const GridMotion& motion);
    const GridMotion& grid_motion() const { return motion_; }
    const LineVelocities* line_velocities() const { return lines_.zero() ? nullptr : &lines_; }
    // The moving lines' velocities the last step's fluxes used (a checkpoint carries them: with stretching lines the
    // next step's Adams-Bashforth combination sweeps the lines by them too).
    std::array<double, 2> previous_grid_velocity() const { return previous_grid_velocity_; }
    void set_previous_grid_velocity(std::array<double, 2> w) { previous_grid_velocity_ = w; }
    // Move grid lines (same counts): geometry and the Poisson matrix are rebuilt (the matrix is kept when the
    // spacings are the same to round-off: a translated grid). The pressure history (the Poisson solver's starting
    // guess) is dropped unless `keep_history` (lines moved and put back, as a restart does to recompute a response).
    void set_grid_lines(std::vector<double> x_lines, std::vector<double> y_lines, bool keep_history = false);
    // Move grid lines within a step (same counts, the same cells: a modifier layer stretching): the momentum is
    // carried to the new control volumes conservatively (core/operators/line_motion.hpp: u* between predict() and
    // project(), u^{n+1} after), the geometry and the Poisson matrix's coefficients follow, the multigrid hierarchy
    // and the pressure history are kept. The lines' velocities the step's fluxes used are set_grid_motion()'s.
    void stretch_grid_lines(std::vector<double> x_lines, std::vector<double> y_lines);
    // Set the Poisson solver's multigrid hierarchy up on these lines (nearby ones: the same cells), while PCG keeps
    // solving the matrix of the grid's own lines. A caller whose lines stretch every step calls it now and then,
    // on lines it can find again after a restart (band/body_fitted.cpp: the zone at a quantized place).
    void set_up_pressure_hierarchy(std::vector<double> x_lines, std::vector<double> y_lines);
    // A topology change between steps (band/layers.hpp: a layer of cells added on one side of a moving zone and
    // one removed on the other; the same counts): the lines replaced, and the velocity, the pressures, the AB2
    // history, the eddy viscosity and every field handed to remap_with_grid() remapped conservatively
    // (core/grid/remap.hpp). Rebuilds the Poisson matrix. The remapped velocity is not divergence-free on the new
    // cells: after the solid cells are set again, project_after_change() projects it. Collective.
    void change_grid_lines(std::vector<double> x_lines, std::vector<double> y_lines);
    // Fields of another model that change_grid_lines() remaps and shift_one_cell() shifts with the flow's
    // (cell-centred, ghosts exchanged here): the turbulence model's k and epsilon. The field must outlive the solver.
    void remap_with_grid(Field2D* field) { remapped_.push_back(field); }
    // A window that follows a body by whole cells (run/following_frame.hpp), between steps: the lines of a uniform
    // `axis` move by one cell towards its end (`direction` +1) or its start (-1), and every field keeps its values
    // where they are in space (the value at index k is the one that was at k + direction). What leaves the
    // domain is dropped; the row that enters copies the one beside it (zero gradient; a boundary face keeps its
    // value), and on a periodic axis the rows wrap. The AB2 history and the pressure history go along, so on a
    // periodic axis the step after a shift is the fixed grid's step, relabelled. Collective.
    void shift_one_cell(int axis, int direction);
    // The velocity of a window whose boundaries move on average with `w` while its lines stay (shift_one_cell): the
    // convective outflow carries the flow out at the speed relative to it. The fluxes do not see it.
    void set_boundary_frame_velocity(std::array<double, 2> w) { bc_->set_frame_velocity(w); }
    // Project the velocity once on the changed grid (OpenFOAM's correctPhi after a topology change): u -= grad
    // phi, laplacian phi = div u; the pressure stays. Returns the kinetic energy (m^4/s^2 per unit density and
    // depth, fluid cells) before and after. Collective.
    std::array<double, 2> project_after_change();
    void refresh_ghosts();
    // Time the stages of a step into `timer` (null: no timing): "momentum" (prediction with its boundary
    // conditions), "poisson" (right-hand side and hypre solve), "correction" (gradient, halo exchange).
    void set_timer(StageTimer* timer) { timer_ = timer; }

private:
    void explicit_rhs(const Velocity& vel, Velocity& rhs) const;          // H = -C(u) + nu L(u)
    double diffusion_limit() const;                                       // explicit limit with nu + max nu_t
    bool implicit_step(double dt) const;                                  // the scheme of a step of size dt
    void predict_velocity(double dt, double r);                           // u* from u^n, H^n, H^{n-1}, f, p
    void pressure_increment_guess(double r);                              // phi <- r (p^n - p^{n-1})
    double poisson_residual_floor(const Velocity& vel, double dt) const;  // absolute tolerance of the solve
    void solve_and_correct(StepStats& stats);                             // star_ projected, p_ += phi_
    void publish_velocity();                                              // vel_ <- star_, halos and boundaries
    void fill_boundaries(Velocity& vel) const;                            // domain boundaries, then solid cells
    void implicit_wall_momentum(Velocity& star);                          // implicit_wall_ from u*

    FlowConfig config_;
    std::unique_ptr<Grid> grid_;
    std::unique_ptr<HaloExchange> halo_;
    std::unique_ptr<BoundaryConditions> bc_;
    std::unique_ptr<PoissonSolver> poisson_;
    std::unique_ptr<ImplicitDiffusion> implicit_;  // made at the first implicit step
    bool implicit_now_ = false;                    // the scheme of the last step (numerics.diffusion auto switches)
    double inverse_h2_max_ = 0.0;                  // max of 1/dx^2 + 1/dy^2 over the grid (diffusion limit)
    Velocity vel_, star_, rhs_, rhs_old_;
    Field2D p_, p_old_, phi_, source_;
    void cut_flux(const Velocity& vel, Velocity& out) const;  // through the open and shut parts of each face
    void shut_to_body_velocity(Velocity& vel) const;          // the owned faces shut whole take U_b
    StepStats pending_;                                       // the predict() half of the step being taken
    EddyViscosity eddy_;
    bool eddy_on_ = false;
    bool pressure_history_ = false;  // p_old_ holds p^{n-1} (false on the first step and after a grid change)
    double time_ = 0.0, dt_previous_ = 0.0;
    long step_ = 0;
    StageTimer* timer_ = nullptr;
    const SolidCells* solid_ = nullptr;
    PressureBoundary cut_;                        // set_pressure_boundary()
    mutable Velocity flux_;                       // alpha u + (1 - alpha) U_b on the faces, with cut_ (cut_flux)
    mutable Velocity offset_;                     // cut_.flux_offset with its halo (cut_flux)
    mutable Velocity transported_;                // cut_transport: the velocities with U_b on the shut faces
    mutable Velocity transport_;                  // the cut fluxes that transport the momentum (cut_transport)
    const Velocity* wall_faces_ = nullptr;        // set_wall_faces()
    mutable Velocity wall_faces_halo_;            // *wall_faces_ with its halo (explicit_rhs)
    double weight_new_ = 1.0, weight_old_ = 0.0;  // the last step's AB2 weights of H^n and H^{n-1}
    GridMotion motion_;                           // how the grid's lines move (translate_grid, band/)
    LineVelocities lines_;                        // and their velocities on this patch
    std::vector<Field2D*> remapped_;              // other models' fields that follow topology changes
    // Stretching lines: how far each line was swept by the step's fluxes (dt AB2(w), m; consumed by the first
    // stretch_grid_lines() of the step), the grid velocities of the last step's fluxes, and whether u* is pending.
    std::array<std::vector<double>, 2> counted_;
    std::array<double, 2> previous_grid_velocity_{};
    bool predicted_ = false;
    bool history_dropped_ = false;                      // a topology change: the next step is forward Euler
    std::vector<std::array<double, 2>> implicit_wall_;  // per solid block: this rank's sum of V L_implicit(u*)
};

Axis build_axis(const AxisConfig& c, bool periodic);

}  // namespace chute
