#pragma once
// A flow with bodies (immersed or body-fitted), the model run_simulation builds (run/model.hpp) stepped as it steps it
// (run/step.hpp), with the force histories the validation tests average. Tests see what users run.
#include <mpi.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "case_file.hpp"
#include "immersed_boundary.hpp"
#include "model.hpp"
#include "step.hpp"

namespace chute::validation {

inline const std::string kExamples = std::string(CHUTE_SOURCE_DIR) + "/examples/";

// Rank 0 of the run prints what a test measured.
inline bool root() {
    int r = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r == 0;
}

struct ForceSample {
    double t = 0.0;
    BodyForces f;
};

class BodyRun {
public:
    // The model keeps its own copy of the case: a temporary `c` is fine.
    BodyRun(const CaseConfig& c, MPI_Comm comm)
        : model(c, comm),
          solver(model.flow()),
          carrier(model.carrier()),
          ibm(dynamic_cast<ImmersedBoundary*>(&model.carrier())),
          free(model.free_bodies()),
          turbulence(model.turbulence()) {}

    // One step (dt <= 0: the stable one); returns the forces on every body.
    const std::vector<BodyForces>& step(double dt = 0.0) {
        take_step(model, dt > 0.0 ? dt : model.stable_dt());
        last = measure_forces(model);
        history.push_back({solver.time(), last.empty() ? BodyForces{} : last.at(0)});
        return last;
    }
    void run_to(double t_end, double dt = 0.0) {
        while (solver.time() < t_end - 1e-12) step(dt);
    }
    // Mean over the samples with t in [t0, t1] of a scalar taken from body 0's forces.
    template <class Get>
    double mean(double t0, double t1, Get get) const {
        double s = 0.0;
        int n = 0;
        for (const auto& h : history)
            if (h.t >= t0 && h.t <= t1) s += get(h.f), ++n;
        return n ? s / n : NAN;
    }

    Model model;
    FlowSolver& solver;
    Carrier& carrier;
    ImmersedBoundary* ibm;  // when the bodies are immersed (null: body-fitted)
    FreeBodies& free;
    KEpsilon* turbulence;  // when the case asks for k-epsilon
    std::vector<BodyForces> last;
    std::vector<ForceSample> history;
};

}  // namespace chute::validation
