#include "hazard_command.hpp"

#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include "hazard_outputs.hpp"
#include "run_command.hpp"

int hazard_command(const std::filesystem::path& case_file, const std::filesystem::path& out_dir,
                   const std::vector<std::string>& overrides, bool no_plots) {
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    chute::HazardCase c = chute::load_hazard_case(case_file, overrides);
    if (no_plots) c.plots = false;
    const std::filesystem::path out = out_dir.empty() ? std::filesystem::path("results") / c.name : out_dir;
    if (rank == 0) {
        std::printf("chute hazard: '%s', %ld trajectories over %zu segments on %d rank(s), results in %s\n",
                    c.name.c_str(), c.trajectories, c.segment_materials.size(), size, out.string().c_str());
        std::fflush(stdout);
    }
    const chute::HazardResults results = chute::run_hazard(c, MPI_COMM_WORLD, true);
    if (rank != 0) return 0;
    const chute::HazardSummary summary = chute::summarize(c, results);
    chute::write_hazard_outputs(c, results, summary, case_as_run(case_file, overrides), size, out);
    std::printf("%s", chute::format_hazard_summary(c, summary, results.seconds, size).c_str());
    if (c.plots) {
        const std::string cmd = "/usr/bin/python3 " CHUTE_PYTHON_DIR "/hazard/plot_hazard.py '" + out.string() + "'";
        if (std::system(cmd.c_str()) != 0) std::fprintf(stderr, "chute: plotting failed (results are complete)\n");
    }
    return 0;
}
