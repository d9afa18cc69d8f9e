#pragma once
// A flow with immersed bodies, stepped as run_simulation steps it (predict, move, force, project), with the
// force histories the validation tests average. Kept to the loop itself so tests see what users run.
#include <mpi.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "case_file.hpp"
#include "flow_solver.hpp"
#include "coupled_step.hpp"

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
    BodyRun(const CaseConfig& c, MPI_Comm comm) : solver(c, comm), ibm(solver.grid(), c), free(c, ibm) {
        if (c.turbulence.model == TurbulenceModelType::k_epsilon)
            turbulence = std::make_unique<KEpsilon>(c, solver, ibm);
    }

    // One step; returns the forces on every body.
    const std::vector<BodyForces>& step(double dt = 0.0) {
        advance(solver, ibm, free, dt, turbulence.get());
        if (ibm.empty()) {
            history.push_back({solver.time(), BodyForces{}});
            return last;
        }
        last = ibm.forces(solver.velocity(), solver.pressure(), turbulence ? &turbulence->k() : nullptr);
        free.report(last);
        history.push_back({solver.time(), last.at(0)});
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

    FlowSolver solver;
    ImmersedBoundary ibm;
    FreeBodies free;
    std::unique_ptr<KEpsilon> turbulence;  // when the case asks for k-epsilon
    std::vector<BodyForces> last;
    std::vector<ForceSample> history;
};

}  // namespace chute::validation
