#pragma once
// A grid that follows a moving immersed body (bodies.<body>.follow; issue "speed": the domain a few block lengths
// around the block instead of its whole path). The grid stays at rest during a step, exactly the fixed grid of
// the case, and between steps it moves by whole cells (FlowSolver::shift_one_cell) so that the body stays within
// a cell of where it started on it: the fields keep their values in space, the row that leaves behind is dropped,
// the one that enters ahead copies its neighbour (water at rest far ahead: an `inflow` at velocity [0, 0]).
//
// Why whole cells and not a grid translating with the body (the arbitrary Lagrangian-Eulerian form the body-fitted
// carrier uses; the first version of this frame, 2026-11-25): on a translating grid the body keeps one place
// against the cells for the whole run, and the immersed boundary's drag of a sharp-cornered body depends on that
// place. The study's block, its edges on grid lines, fell 2.9 % faster than in the fixed domain; half a cell
// lower, 1.0 % slower (docs/validation.md, "A window that moves by whole cells"). Moving by whole cells, the body
// crosses the cells as on the fixed grid, and the flow near it is computed by the same discrete equations.
//
// The followed axis must be uniform (the lines a shift keeps are copied, so the spacings and the pressure
// solver's matrix do not change), and the sides across the motion open (inflow, outflow or periodic).
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
    FollowingFrame(std::size_t body, std::array<bool, 2> axes, std::array<double, 2> body_start,
                   std::array<double, 2> domain_start)
        : body_(body), axes_(axes), body_start_(body_start), domain_start_(domain_start) {}
    // The followed body of a case, if any. std::invalid_argument, naming the key, when two bodies ask to be followed,
    // a wall or slip side lies across the motion (it would move with the grid: give an inflow at rest ahead, an
    // outflow behind, or a periodic pair), or a followed axis is not uniform.
    static std::optional<FollowingFrame> of(const CaseConfig& config);

    std::size_t body() const { return body_; }
    // Before a step: move the grid by whole cells until the body is less than a cell from where it started on the
    // grid (the start's place on the lines is found again from the lines, so a restart needs nothing more). The
    // turbulence model's walls, ghosts and corner eddy viscosity are set again after a move.
    void follow(FlowSolver& flow, KEpsilon* turbulence, const Body& body) const;

private:
    std::size_t body_;
    std::array<bool, 2> axes_;
    std::array<double, 2> body_start_, domain_start_;  // the case's: where the body starts on the grid's first lines
};

}  // namespace chute
