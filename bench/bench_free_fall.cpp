// bench_free_fall: cost of one time step with a free body, split by the stages of the step (run/step.hpp):
// the flow (momentum, Poisson, correction), the bodies (carrier forcing, rigid-body update, contact), the
// turbulence model (when the case runs k-epsilon) and the force measures written to the time series.
//
//   mpirun -np R bench_free_fall [--steps N] [--warmup N] [--set key=value ...] [case.yaml]
//
// Case: examples/free_fall_block/case.yaml by default (the study's 0.3 m block in water, k-epsilon, 20 cells
// across, 150 x 767 cells). `--warmup` steps (default 100: the block is moving), then `--steps` (default 300) are
// timed. Rank 0 prints a Markdown table.
#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "case_file.hpp"
#include "model.hpp"
#include "step.hpp"

using namespace chute;

namespace {

void run(const std::string& path, std::vector<std::string> settings, int steps, int warmup, int rank, int size) {
    settings.insert(settings.begin(), "time.end=100.0");
    const CaseConfig c = load_case(path, settings);
    Model model(c, MPI_COMM_WORLD);
    StageTimer stages(kStepStages);
    using clock = std::chrono::steady_clock;
    double total = 0;
    for (int n = 0; n < warmup + steps; ++n) {
        if (n == warmup) stages.reset();
        MPI_Barrier(MPI_COMM_WORLD);
        const auto t0 = clock::now();
        take_step(model, model.stable_dt(), &stages);
        measure_forces(model, &stages);
        MPI_Barrier(MPI_COMM_WORLD);
        if (n >= warmup) total += std::chrono::duration<double>(clock::now() - t0).count();
    }
    if (rank == 0) {
        const double per = 1e3 / steps;
        std::printf(
            "case %s%s, %d x %d cells, %d rank(s), %d steps timed after %d (t = %.3f s, block speed %.3f m/s)\n\n",
            path.c_str(), settings.size() > 1 ? (" with " + settings.back()).c_str() : "", c.x.cells, c.y.cells, size,
            steps, warmup, model.flow().time(), model.bodies()[0].state().velocity.norm());
        std::printf("| ms / step |");
        for (const auto& [stage, seconds] : stages.stages()) std::printf(" %s |", stage.c_str());
        std::printf("\n|---|");
        for (std::size_t k = 0; k < stages.stages().size(); ++k) std::printf("---|");
        std::printf("\n| %.2f |", total * per);
        for (const auto& [stage, seconds] : stages.stages())
            std::printf(" %.2f (%.1f %%) |", seconds * per, 100 * seconds / total);
        std::printf("\n");
    }
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    int steps = 300, warmup = 100;
    std::vector<std::string> settings;  // --set key=value: the case changed as `chute run --set` does
    std::string path = std::string(CHUTE_SOURCE_DIR) + "/examples/free_fall_block/case.yaml";
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        if (a == "--steps" && k + 1 < argc)
            steps = std::atoi(argv[++k]);
        else if (a == "--warmup" && k + 1 < argc)
            warmup = std::atoi(argv[++k]);
        else if (a == "--set" && k + 1 < argc)
            settings.push_back(argv[++k]);
        else if (a.starts_with("-")) {
            const bool help = a == "--help" || a == "-h";
            if (rank == 0 && !help) std::fprintf(stderr, "bench_free_fall: unknown option %s\n", a.c_str());
            if (rank == 0)
                std::fprintf(help ? stdout : stderr,
                             "usage: mpirun -np R bench_free_fall [--steps N] [--warmup N] [--set key=value ...] "
                             "[case.yaml]\n");
            MPI_Finalize();
            return help ? 0 : 2;
        } else
            path = a;
    }
    try {
        run(path, settings, steps, warmup, rank, size);  // its solver objects are gone before MPI_Finalize
    } catch (const std::exception& e) {                  // a case that cannot be read: its message, not a stack trace
        if (rank == 0) std::fprintf(stderr, "bench_free_fall: %s\n", e.what());
        MPI_Finalize();
        return 2;
    }
    MPI_Finalize();
    return 0;
}
