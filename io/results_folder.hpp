#pragma once
// The results folder, checked before a run writes anything in it.
#include <filesystem>
#include <string>
#include <vector>

namespace chute {

// Makes `folder` if needed and writes (then removes) a small probe file in it, so that a folder that cannot be
// made (a path under a regular file) or written (read-only, no permission, a full disk) stops the run before
// its first step, with an OutputError naming the folder and the system's reason, and nothing written.
// Then removes the temporary files (<output>.tmp, hdf5_file.hpp) that a run killed while writing left there,
// and returns their names.
std::vector<std::string> prepare_results_folder(const std::filesystem::path& folder);

}  // namespace chute
