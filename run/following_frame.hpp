#pragma once
// A grid that follows a moving immersed body (bodies.<body>.follow; issue "speed": the domain a few block lengths
// around the block instead of its whole path). Two ways, by the carrier's interface:
//
// - Sharp interface: the grid translates with the body (the arbitrary Lagrangian-Eulerian form of the body-fitted
//   carrier's translating grid, FlowSolver::translate_grid / set_frame_velocity): the unknowns stay the inertial
//   velocity and pressure, the convective fluxes see the velocity relative to the moving faces, a rigid translation
//   keeps every cell's area. The body keeps its place against the cells, so its thin boundary layer is not carried
//   across the grid. On a grid at rest a sharp surface moving oblique to the grid lines smears its boundary layer
//   over the cells it crosses: the study's block moved at 2 m/s along its diagonal read 34 % less drag than held in
//   the same stream (t = 0.1-0.2 s), and an accelerated one 23 % less than the body-fitted block, converging at
//   order 0.5 at most; on the translating grid it reads the held drag to 0.1 % (docs/validation.md, "Sharp
//   interface", ninth step). Each step the fluxes see the grid at the body's velocity at the start of the step, and
//   the lines are moved to the body's place on them once the bodies are placed at the step's end (a free body's
//   prediction is v dt + a dt^2 / 2 away) and again after its update (dt (v^{n+1} - v^n) / 2 from the prediction);
//   the fields stay on their lines, as on the body-fitted carrier's translating grid. So the body keeps its place on
//   the grid to round-off.
// - Diffuse interface: between steps the grid moves by whole cells (FlowSolver::shift_one_cell) so that the body
//   stays within a cell of where it started on it: the fields keep their values in space, the row that leaves behind
//   is dropped, the one that enters ahead copies its neighbour (water at rest far ahead: an `inflow` at velocity
//   [0, 0]). The grid is at rest during a step, the body crosses the cells as on the fixed grid and the flow near it
//   is computed by the same discrete equations. (Translating, the diffuse body kept one place against the cells, and
//   its drag depends on that place: the study's block, its edges on grid lines, fell 2.9 % faster than in the fixed
//   domain; half a cell lower, 1.0 % slower; docs/validation.md, "A window that moves by whole cells".) The followed
//   axis must be uniform (the lines a shift keeps are copied, so the spacings and the pressure solver's matrix do
//   not change).
//
// Either way the sides across the motion are open (inflow, outflow or periodic). Other bodies (a fixed plane below a
// falling block) move against the grid: what the carriers place once on the grid for a static body is placed again
// after each move of the lines (Grid::lines_version).
#include <array>
#include <cstddef>
#include <optional>

#include "body.hpp"
#include "case_config.hpp"
#include "flow_solver.hpp"
#include "k_epsilon.hpp"

namespace chute {

class FollowingFrame {
public:
    // quantum: translating, the step (m) the lines move by (a power of two: lines on its multiples move exactly).
    FollowingFrame(std::size_t body, std::array<bool, 2> axes, std::array<double, 2> body_start,
                   std::array<double, 2> domain_start, bool translate, double quantum)
        : body_(body),
          axes_(axes),
          body_start_(body_start),
          domain_start_(domain_start),
          translate_(translate),
          quantum_(quantum) {}
    // The followed body of a case, if any. std::invalid_argument, naming the key, when two bodies ask to be followed,
    // a wall or slip side lies across the motion (it would move with the grid: give an inflow at rest ahead, an
    // outflow behind, or a periodic pair), or (whole cells) a followed axis is not uniform.
    static std::optional<FollowingFrame> of(const CaseConfig& config);

    std::size_t body() const { return body_; }
    // Before a step, whole cells: move the grid until the body is less than a cell from where it started on it;
    // the turbulence model's walls, ghosts and corner eddy viscosity are set again after a move. Translating:
    // nothing (after_step() left the grid with the body).
    void before_step(FlowSolver& flow, KEpsilon* turbulence, const Body& body) const;
    // Translating: the lines to the body's place on them, once the bodies are placed at the step's end; the fields
    // stay on their lines. Whole cells: nothing.
    void place(FlowSolver& flow, const Body& body) const;
    // Translating: the lines to the body's place after the step's update and the grid's velocity for the next step,
    // so that its limit sees the relative velocities the step will have (also after the model is built and after a
    // restore; a second call finds nothing to move). Whole cells: nothing.
    // Either way the start's place on the lines is found again from the lines, so a restart needs nothing more.
    void after_step(FlowSolver& flow, const Body& body) const;

private:
    std::size_t body_;
    std::array<bool, 2> axes_;
    std::array<double, 2> body_start_, domain_start_;  // the case's: where the body starts on the grid's first lines
    bool translate_;                                   // the grid translates (sharp), else moves by whole cells
    double quantum_;                                   // translating: what the lines move by is a multiple of it
    // The body's distance along an axis from where it started on the grid.
    double offset(const FlowSolver& flow, const Body& body, int axis) const;
    // Translating: the followed axes' lines on multiples of the quantum (once; a restart finds them there).
    void snap_lines(FlowSolver& flow) const;
    static const Axis& along(const FlowSolver& flow, int axis) {
        return axis == 0 ? flow.grid().x_axis() : flow.grid().y_axis();
    }
};

}  // namespace chute
