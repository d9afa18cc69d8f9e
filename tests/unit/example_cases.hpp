#pragma once
// The flow case files of examples/ (every .yaml under it but the hazard analysis's: examples/fjord_wall holds a
// hazard case, read by `chute hazard`, and examples/calibration a calibration spec, read by `chute calibrate`;
// their own tests are in test_hazard_run.cpp), in path order.
#include <algorithm>
#include <filesystem>
#include <vector>

namespace chute {

inline std::vector<std::filesystem::path> flow_example_cases() {
    namespace fs = std::filesystem;
    const fs::path root = fs::path(CHUTE_SOURCE_DIR) / "examples";
    std::vector<fs::path> cases;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        if (e.path().extension() != ".yaml") continue;
        const fs::path folder = *fs::relative(e.path(), root).begin();
        if (folder == "fjord_wall" || folder == "calibration") continue;
        cases.push_back(e.path());
    }
    std::sort(cases.begin(), cases.end());
    return cases;
}

}  // namespace chute
