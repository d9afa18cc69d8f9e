// bench_free_fall: cost of one time step with a free body, split into the flow, the body (forcing, rigid-body
// update, contact), the turbulence model (when the case runs k-epsilon) and the force measures written to
// the time series.
//
//   mpirun -np R bench_free_fall [--steps N] [--warmup N] [case.yaml]
//
// Case: examples/free_fall_block/case.yaml by default (the study's 0.3 m block in water, k-epsilon, 20 cells
// across, 150 x 767 cells). `--warmup` steps (default 100: the block is moving), then `--steps` (default 300) are
// timed. Rank 0 prints a Markdown table.
#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <memory>

#include "case_file.hpp"
#include "coupled_step.hpp"

using namespace chute;

namespace {

void run(const std::string& path, int steps, int warmup, int rank, int size) {
    const CaseConfig c = load_case(path, {"time.end=100.0"});
    FlowSolver flow(c, MPI_COMM_WORLD);
    ImmersedBoundary ibm(flow.grid(), c);
    FreeBodies free(c, ibm);
    std::unique_ptr<KEpsilon> turbulence;
    if (c.turbulence.model == TurbulenceModelType::k_epsilon) turbulence = std::make_unique<KEpsilon>(c, flow, ibm);
    using clock = std::chrono::steady_clock;
    double total = 0, momentum = 0, poisson = 0, correction = 0, bodies = 0, forces = 0, turb = 0;
    for (int n = 0; n < warmup + steps; ++n) {
        MPI_Barrier(MPI_COMM_WORLD);
        const auto t0 = clock::now();
        const StepStats st = advance(flow, ibm, free, 0.0, turbulence.get());
        const auto t1 = clock::now();
        std::vector<BodyForces> f = ibm.forces(flow.velocity(), flow.pressure(), turbulence ? &turbulence->k() : nullptr);
        free.report(f);
        MPI_Barrier(MPI_COMM_WORLD);
        const auto t2 = clock::now();
        if (n < warmup) continue;
        total += std::chrono::duration<double>(t2 - t0).count();
        forces += std::chrono::duration<double>(t2 - t1).count();
        momentum += st.seconds_momentum;
        poisson += st.seconds_poisson;
        correction += st.seconds_correction;
        bodies += st.seconds_forcing;
        turb += st.seconds_turbulence;
    }
    if (rank == 0) {
        const double per = 1e3 / steps;
        std::printf("case %s, %d x %d cells, %d rank(s), %d steps timed after %d (t = %.3f s, block speed %.3f m/s)\n\n",
                    path.c_str(), c.x.cells, c.y.cells, size, steps, warmup, flow.time(),
                    ibm.bodies()[0].state().velocity.norm());
        std::printf("| ms / step | momentum | Poisson | correction | body: forcing, update, contact | turbulence | force measures (a), (b) |\n");
        std::printf("|---|---|---|---|---|---|---|\n");
        std::printf("| %.2f | %.2f (%.0f %%) | %.2f (%.0f %%) | %.2f (%.0f %%) | %.2f (%.1f %%) | %.2f (%.1f %%) | %.2f (%.1f %%) |\n",
                    total * per, momentum * per, 100 * momentum / total, poisson * per, 100 * poisson / total,
                    correction * per, 100 * correction / total, bodies * per, 100 * bodies / total, turb * per,
                    100 * turb / total, forces * per, 100 * forces / total);
    }
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    int steps = 300, warmup = 100;
    std::string path = std::string(CHUTE_SOURCE_DIR) + "/examples/free_fall_block/case.yaml";
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        if (a == "--steps" && k + 1 < argc) steps = std::atoi(argv[++k]);
        else if (a == "--warmup" && k + 1 < argc) warmup = std::atoi(argv[++k]);
        else path = a;
    }
    run(path, steps, warmup, rank, size);  // its solver objects are gone before MPI_Finalize
    MPI_Finalize();
    return 0;
}
