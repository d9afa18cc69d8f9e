#pragma once
// chute hazard CASE.yaml [--out DIR] [--set key=value ...] [--no-plots]: a rockfall hazard analysis
// (hazard/monte_carlo.hpp) over MPI_COMM_WORLD; rank 0 writes the results (hazard/hazard_outputs.hpp) and the
// plots (python/hazard/plot_hazard.py).
#include <filesystem>
#include <string>
#include <vector>

int hazard_command(const std::filesystem::path& case_file, const std::filesystem::path& out_dir,
                   const std::vector<std::string>& overrides, bool no_plots);
