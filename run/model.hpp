#pragma once
// The model of a run, built once from the case (docs/design.md, run/): the flow, the bodies, the carrier that
// imposes them on the flow, free-body dynamics and the turbulence model, wired together. The run loop, the
// tests, the benchmarks and the parallel comparisons all build it here, so they step what users run.
#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

#include "carrier.hpp"
#include "case_config.hpp"
#include "flow_solver.hpp"
#include "following_frame.hpp"
#include "free_bodies.hpp"
#include "k_epsilon.hpp"

namespace chute {

class Model {
public:
    // std::invalid_argument for a case the grid, the bodies or the turbulence model cannot take (naming the
    // key); `carrier` a name registered in carriers.hpp (empty: the one the bodies ask for, bodies.<body>.carrier).
    Model(const CaseConfig& config, MPI_Comm comm, const std::string& carrier = {});
    Model(const Model&) = delete;
    Model& operator=(const Model&) = delete;

    // The largest stable step: the flow's (CFL, diffusion, fixed) and the moving bodies' (numerics.cfl cells per step).
    double stable_dt() const;
    // k and the wall law when a turbulence model runs (the turbulent part of the surface forces), else empty.
    std::optional<WallTurbulence> wall_turbulence() const;

    const CaseConfig& config() const { return config_; }
    FlowSolver& flow() { return *flow_; }
    const FlowSolver& flow() const { return *flow_; }
    const std::vector<Body>& bodies() const { return bodies_; }
    Carrier& carrier() { return *carrier_; }
    const Carrier& carrier() const { return *carrier_; }
    FreeBodies& free_bodies() { return *free_; }
    const FreeBodies& free_bodies() const { return *free_; }
    KEpsilon* turbulence() { return turbulence_.get(); }
    const KEpsilon* turbulence() const { return turbulence_.get(); }
    // The following grid brought to its body at the step's three moments (run/following_frame.hpp): before the step
    // (whole cells), once the bodies are placed at its end and after it (translating; after_step also once the
    // model is built and after a restore). Nothing when no body is followed.
    void window_before_step();
    void window_to_placed_body();
    void window_after_step();

private:
    CaseConfig config_;
    std::unique_ptr<FlowSolver> flow_;
    std::vector<Body> bodies_;
    std::unique_ptr<Carrier> carrier_;
    std::unique_ptr<FreeBodies> free_;
    std::unique_ptr<KEpsilon> turbulence_;
    std::optional<FollowingFrame> frame_;
};

}  // namespace chute
