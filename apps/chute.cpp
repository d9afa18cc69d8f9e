// chute: the command-line tool.
//   chute run CASE.yaml [--out DIR] [--set key.path=value ...] [--restart CHECKPOINT|DIR] [--no-plots]
//             [--sweep key.path=v1,v2,... ...]   one run per combination, in DIR/<key>=<value>,...
//   chute hazard CASE.yaml [--out DIR] [--set key.path=value ...] [--no-plots]
//             a rockfall hazard analysis over a slope profile (hazard/; keys: docs/hazard-case-file.md)
//   chute calibrate SPEC.yaml [--out DIR] [--redo]
//             the CFD runs of one block and the wet lumped model's constants fitted to them (hazard/calibration.hpp)
//   chute keys [--hazard] prints every case-file key (the table of docs/case-file.md, or of the hazard case)
#include <HYPRE_utilities.h>
#include <mpi.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "calibrate_command.hpp"
#include "case_file.hpp"
#include "hazard_case.hpp"
#include "hazard_command.hpp"
#include "hdf5_file.hpp"
#include "leak_check.hpp"
#include "output_error.hpp"
#include "plausibility.hpp"
#include "restart_state.hpp"
#include "run_command.hpp"
#include "simulation.hpp"
#include "stop_request.hpp"
#include "text_file.hpp"

namespace {

// A --sweep value "key=v1,v2,...": the key and its values. Commas inside [] or {} belong to a value, so
// vectors sweep too: bodies.block.centre=[0, 1],[0, 2].
std::pair<std::string, std::vector<std::string>> parse_sweep(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw chute::CaseError("--sweep " + text + ": expected key.path=value1,value2,...");
    std::vector<std::string> values(1);
    int depth = 0;
    for (const char ch : text.substr(eq + 1)) {
        if (ch == '[' || ch == '{') ++depth;
        if (ch == ']' || ch == '}') --depth;
        if (ch == ',' && depth == 0)
            values.emplace_back();
        else
            values.back() += ch;
    }
    for (auto& v : values) {
        v.erase(0, v.find_first_not_of(' '));
        v.erase(v.find_last_not_of(' ') + 1);
        if (v.empty()) throw chute::CaseError("--sweep " + text + ": an empty value");
    }
    return {text.substr(0, eq), values};
}

// Runs every combination of the sweeps, one after the other, each in its own folder; the cases are all read
// (and checked) first, so a bad value stops the sweep before anything runs. sweep.txt gathers the summaries.
int sweep_command(const std::filesystem::path& case_file, const std::filesystem::path& out_dir,
                  const std::vector<std::string>& overrides, const std::vector<std::string>& sweeps, bool no_plots) {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    std::vector<std::vector<std::string>> runs = {{}};  // the --set lists of the combinations
    for (const std::string& s : sweeps) {
        const auto [key, values] = parse_sweep(s);
        std::vector<std::vector<std::string>> next;
        for (const auto& r : runs)
            for (const auto& v : values) {
                next.push_back(r);
                next.back().push_back(key + "=" + v);
            }
        runs = next;
    }
    const std::string name = chute::load_case(case_file, overrides).name;
    const std::filesystem::path base = out_dir.empty() ? std::filesystem::path("results") / name : out_dir;
    std::vector<std::filesystem::path> folders;
    for (const auto& r : runs) {
        std::vector<std::string> all = overrides;
        all.insert(all.end(), r.begin(), r.end());
        (void)chute::load_case(case_file, all);  // checks every combination before the first run
        std::string folder;
        for (const auto& o : r) folder += (folder.empty() ? "" : ",") + o;
        for (char& ch : folder)
            if (ch == '/' || ch == ' ' || ch == '[' || ch == ']' || ch == '{' || ch == '}') ch = '_';
        folders.push_back(base / folder);
    }
    std::string report;
    for (std::size_t k = 0; k < runs.size(); ++k) {
        std::vector<std::string> all = overrides;
        all.insert(all.end(), runs[k].begin(), runs[k].end());
        if (rank == 0)
            std::printf("chute: sweep run %zu of %zu: %s\n", k + 1, runs.size(), folders[k].string().c_str());
        const int code = run_command(case_file, folders[k], all, "", no_plots);
        if (rank == 0) {
            report += "== " + folders[k].filename().string() + "\n" +
                      chute::read_text_file(folders[k] / "summary.txt") + "\n";
            chute::write_text_atomically(base / "sweep.txt", report);
        }
        if (code != 0) return code;
    }
    if (rank == 0)
        std::printf("chute: sweep of %zu runs done; summaries in %s\n", runs.size(),
                    (base / "sweep.txt").string().c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CHUTE_LSAN_IGNORE_BEGIN;
    MPI_Init(&argc, &argv);
    HYPRE_Init();
    CHUTE_LSAN_IGNORE_END;
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);

    CLI::App app{"Chute: a rock block falling in water (and air). 2D incompressible flow solver."};
    app.require_subcommand(1);
    auto* run = app.add_subcommand("run", "run a case file");
    std::filesystem::path case_file, out_dir;
    std::vector<std::string> overrides;
    std::string restart;
    bool no_plots = false;
    run->add_option("case", case_file, "case file (YAML)")->required();
    run->add_option("--out", out_dir, "results folder (default results/<case name>)");
    run->add_option("--set", overrides, "override a key: --set domain.x.cells=128 (repeatable)");
    run->add_option(
        "--restart", restart,
        "continue from this checkpoint file, or from the newest readable checkpoint of this results folder");
    run->add_flag("--no-plots", no_plots, "do not make the PNG plots");
    std::vector<std::string> sweeps;
    run->add_option("--sweep", sweeps,
                    "run once per value: --sweep bodies.block.density=2400,2500,2600 (repeatable: every combination)");
    auto* hazard = app.add_subcommand("hazard", "run a rockfall hazard analysis (Monte Carlo lumped trajectories)");
    std::filesystem::path hazard_case, hazard_out;
    std::vector<std::string> hazard_overrides;
    bool hazard_no_plots = false;
    hazard->add_option("case", hazard_case, "hazard case file (YAML)")->required();
    hazard->add_option("--out", hazard_out, "results folder (default results/<case name>)");
    hazard->add_option("--set", hazard_overrides, "override a key: --set trajectories=10000 (repeatable)");
    hazard->add_flag("--no-plots", hazard_no_plots, "do not make the PNG plots");
    auto* calibrate = app.add_subcommand("calibrate", "calibrate the wet lumped model by CFD runs of one block");
    std::filesystem::path spec_file, calibrate_out;
    bool redo = false;
    calibrate->add_option("spec", spec_file, "calibration spec (YAML: the runs)")->required();
    calibrate->add_option("--out", calibrate_out,
                          "folder of the runs and the fit (default results/calibration/<name>)");
    calibrate->add_flag("--redo", redo, "make every run again even if its folder holds it");
    auto* keys = app.add_subcommand("keys", "print every case-file key with its type, default and range");
    bool hazard_keys = false;
    keys->add_flag("--hazard", hazard_keys, "the keys of a hazard case");

    int code = 0;
    try {
        app.parse(argc, argv);
        if (*keys) {
            if (rank == 0)
                std::cout << (hazard_keys ? chute::hazard_keys_markdown() + "\n" + calibration_spec_keys_markdown()
                                          : chute::schema_markdown());
        } else if (*calibrate) {
            code = calibrate_command(spec_file, calibrate_out, redo);
        } else if (*hazard) {
            code = hazard_command(hazard_case, hazard_out, hazard_overrides, hazard_no_plots);
        } else {
            if (!sweeps.empty() && !restart.empty()) throw chute::CaseError("--sweep and --restart do not go together");
            code = sweeps.empty() ? run_command(case_file, out_dir, overrides, restart, no_plots)
                                  : sweep_command(case_file, out_dir, overrides, sweeps, no_plots);
        }
    } catch (const CLI::ParseError& e) {
        code = rank == 0 ? app.exit(e) : 2;
        if (code == 0 && !e.get_exit_code()) code = 0;
    } catch (const chute::CaseError& e) {
        if (rank == 0) std::fprintf(stderr, "chute: error in the case: %s\n", e.what());
        code = 2;
    } catch (const chute::RunFailure& e) {
        if (rank == 0) std::fprintf(stderr, "chute: %s\n", e.what());
        code = 3;
    } catch (const chute::OutputError& e) {
        // A result file could not be written (full disk, file size limit, unwritable folder). Rank 0 writes
        // them all and says so; other ranks may be waiting in a collective call, so the job is stopped, by
        // rank 0 first, so that its message is not cut off.
        if (rank == 0) std::fprintf(stderr, "chute: %s\n", e.what());
        int size = 1;
        MPI_Comm_size(MPI_COMM_WORLD, &size);
        if (size > 1 && rank != 0) std::this_thread::sleep_for(std::chrono::seconds(1));
        if (size > 1) MPI_Abort(MPI_COMM_WORLD, 4);
        code = 4;
    } catch (const std::exception& e) {
        // Errors other than the above may be raised on one rank only (rank 0's file I/O): the others may be
        // waiting in a collective call, so the whole job is stopped.
        std::fprintf(stderr, "chute: %s\n", e.what());
        int size = 1;
        MPI_Comm_size(MPI_COMM_WORLD, &size);
        if (size > 1) MPI_Abort(MPI_COMM_WORLD, 1);
        code = 1;
    }
    CHUTE_LSAN_IGNORE_BEGIN;
    HYPRE_Finalize();
    MPI_Finalize();
    CHUTE_LSAN_IGNORE_END;
    return code;
}
