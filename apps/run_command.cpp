#include "run_command.hpp"

#include <mpi.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "case_file.hpp"
#include "hdf5_file.hpp"
#include "plausibility.hpp"
#include "restart_state.hpp"
#include "simulation.hpp"
#include "stop_request.hpp"
#include "text_file.hpp"

std::string case_as_run(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
    std::string text = chute::read_text_file(file);
    if (!overrides.empty()) {
        text += "\n# Overrides given on the command line (--set), applied on top of the keys above:\n";
        for (const auto& o : overrides) text += "#   " + o + "\n";
    }
    return text;
}

int run_command(const std::filesystem::path& case_file, const std::filesystem::path& out_dir,
                const std::vector<std::string>& overrides, const std::string& restart, bool no_plots) {
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    chute::CaseConfig config = chute::load_case(case_file, overrides);
    if (no_plots) config.plots = false;
    chute::RunOptions options;
    options.out_dir = out_dir.empty() ? std::filesystem::path("results") / config.name : out_dir;
    if (!restart.empty()) options.restart = chute::restart_checkpoint(restart, rank == 0);
    options.case_yaml = case_as_run(case_file, overrides);
    if (rank == 0)
        std::printf("chute: case '%s', %d x %d cells on %d rank(s), t_end = %g s, results in %s\n", config.name.c_str(),
                    config.x.cells, config.y.cells, size, config.end_time, options.out_dir.string().c_str());
    if (rank == 0)
        for (const std::string& w : chute::plausibility_warnings(config))
            std::fprintf(stderr, "chute: warning: %s\n", w.c_str());
    std::fflush(stdout);  // the header is out before anything else happens, even when stdout is a file
    chute::install_stop_handlers(options.out_dir);
    std::signal(SIGXFSZ, SIG_IGN);  // past `ulimit -f` a write then fails (EFBIG) and is reported, not killed
    const chute::RunSummary summary = chute::run_simulation(config, options, MPI_COMM_WORLD);
    if (rank == 0) {
        const std::string text = chute::format_summary(summary, 1LL * config.x.cells * config.y.cells);
        std::printf("%s", text.c_str());
        chute::write_text_atomically(options.out_dir / "summary.txt", text);
        if (config.plots) {
            const std::string cmd =
                "/usr/bin/python3 " CHUTE_PYTHON_DIR "/plot_run.py '" + options.out_dir.string() + "'";
            if (std::system(cmd.c_str()) != 0) std::fprintf(stderr, "chute: plotting failed (results are complete)\n");
        }
    }
    if (summary.stopped_by_signal) {
        if (rank == 0)
            std::printf("chute: stopped early; continue with: chute run %s --out %s --restart %s\n",
                        case_file.string().c_str(), options.out_dir.string().c_str(),
                        summary.last_checkpoint.string().c_str());
        return 128 + summary.stopped_by_signal;  // the shell's convention for "ended by signal N"
    }
    return 0;
}
