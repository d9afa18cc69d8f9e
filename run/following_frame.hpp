#pragma once
// A grid that follows a moving immersed body (bodies.<body>.follow; issue "speed": the domain a few block lengths
// around the block instead of its whole path). The grid translates rigidly with the body's velocity along the
// followed axes, in the arbitrary Lagrangian-Eulerian form the body-fitted carrier's translating grid uses
// (FlowSolver::translate_grid / set_frame_velocity): the unknowns stay the inertial velocity and pressure, the
// convective fluxes see the velocity relative to the moving faces, and a rigid translation keeps every cell's area,
// so the geometric conservation law holds exactly (FreeStream.UniformCurrentThroughATranslatingGridIsPreserved).
// No fictitious force enters, and the body's forces, positions and the fields need no change of frame.
//
// Each step: the grid's velocity w is the body's velocity at the start of the step (begin_step), the momentum
// prediction runs with the fluxes relative to w, and the lines then move by w dt (move), before the body is
// placed and imposed at t + dt. The body drifts against the grid by the change of its velocity over a step,
// (v^{n+1} - v^n) dt / 2 per step: about a millimetre over the study's whole fall (docs/validation.md).
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "body.hpp"
#include "case_config.hpp"
#include "flow_solver.hpp"

namespace chute {

class FollowingFrame {
public:
    FollowingFrame(std::size_t body, std::array<bool, 2> axes) : body_(body), axes_(axes) {}
    // The followed body of a case, if any. std::invalid_argument, naming the key, when two bodies ask to be followed
    // or a wall or slip side lies across the motion (it would move with the grid: give an inflow at rest ahead, an
    // outflow behind, or a periodic pair).
    static std::optional<FollowingFrame> of(const CaseConfig& config);

    std::size_t body() const { return body_; }
    // The grid's velocity for the step: the body's, along the followed axes.
    void begin_step(FlowSolver& flow, const Body& body);
    // After the prediction: the lines to where the step's travel takes them.
    void move(FlowSolver& flow, double dt) const;

private:
    std::size_t body_;
    std::array<bool, 2> axes_;
    std::array<double, 2> velocity_{0.0, 0.0};
};

}  // namespace chute
