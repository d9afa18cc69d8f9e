#pragma once
// chute run: one case, on MPI_COMM_WORLD (the run's header, warnings, stop handlers, summary and plots), and the
// case text a results folder keeps. Used by `chute run` and its sweeps, and by `chute calibrate` for its runs.
#include <filesystem>
#include <string>
#include <vector>

// The case as run: the file as written, followed by the --set overrides applied to it.
std::string case_as_run(const std::filesystem::path& file, const std::vector<std::string>& overrides);
// Returns the process's exit code (0, or 128 + the signal that stopped the run early).
int run_command(const std::filesystem::path& case_file, const std::filesystem::path& out_dir,
                const std::vector<std::string>& overrides, const std::string& restart, bool no_plots);
