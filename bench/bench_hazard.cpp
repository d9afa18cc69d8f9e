// bench_hazard: Monte Carlo trajectories per second of a hazard analysis (hazard/monte_carlo), the fjord example
// (examples/fjord_wall: 100 segments, the study's block, per-impact draws and roughness), water (with the
// calibration's ground effect and without) and dry.
//
//   mpirun -np R bench_hazard [--trajectories N] [--repeats K] [case.yaml]
//
// Each configuration runs K times (default 3; the best is quoted, the machine's noise is in the others); rank 0
// prints a Markdown table. The target of the hazard issue: 10^4 trajectories over 100 segments within 10 s on the
// 2-core machine.
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "hazard_statistics.hpp"
#include "monte_carlo.hpp"

using namespace chute;

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    long trajectories = 10000;
    int repeats = 3;
    std::string path = std::string(CHUTE_SOURCE_DIR) + "/examples/fjord_wall/case.yaml";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--trajectories" && i + 1 < argc)
            trajectories = std::atol(argv[++i]);
        else if (a == "--repeats" && i + 1 < argc)
            repeats = std::atoi(argv[++i]);
        else
            path = a;
    }
    if (rank == 0) {
        std::printf(
            "| case | water level | ground effect | ranks | trajectories | segments | best s | trajectories/s | "
            "impacts "
            "per trajectory | runs (s) |\n|---|---|---|---|---|---|---|---|---|---|\n");
    }
    // In water with the calibration's ground effect and without it (its cost: hazard/ground_effect.hpp), and dry.
    for (const auto& [level, ground] :
         {std::pair{"0.0", "true"}, std::pair{"0.0", "false"}, std::pair{"-1000.0", "true"}}) {
        const HazardCase c =
            load_hazard_case(path, {"trajectories=" + std::to_string(trajectories), std::string("water.level=") + level,
                                    std::string("model.ground_effect=") + ground, "output.paths=0"});
        double best = 1e300;
        std::string runs;
        double impacts = 0.0;
        for (int k = 0; k < repeats; ++k) {
            MPI_Barrier(MPI_COMM_WORLD);
            const HazardResults r = run_hazard(c, MPI_COMM_WORLD);
            best = std::min(best, r.seconds);
            char t[32];
            std::snprintf(t, sizeof t, "%s%.2f", k ? ", " : "", r.seconds);
            runs += t;
            if (rank == 0) {
                impacts = 0.0;
                for (const TrajectoryOutcome& o : r.outcomes) impacts += o.impacts;
                impacts /= static_cast<double>(r.outcomes.size());
            }
        }
        if (rank == 0)
            std::printf("| %s | %s | %s | %d | %ld | %zu | %.2f | %.0f | %.1f | %s |\n", c.name.c_str(), level,
                        c.settings.ground_effect.active() ? "yes" : "no", size, trajectories,
                        c.segment_materials.size(), best, trajectories / best, impacts, runs.c_str());
    }
    MPI_Finalize();
    return 0;
}
