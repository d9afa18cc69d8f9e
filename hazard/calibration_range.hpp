#pragma once
// Where a hazard case uses the wet model outside what its calibration measured, one warning line each (in the
// run's summary, hazard_outputs.hpp; the run goes on). The calibration's slope law (wet_rebound.hpp) was measured on
// one slope angle, and steeper ground takes that angle's values: on a 45 degree slope the study's block bounced 3.5
// times as high in the CFD as the 30 degree law gives it (-72 % in height; docs/validation.md, docs/limitations.md).
// So:
//   wet segments steeper than the measured angle (by more than half a degree): how many, the steepest, where.
#include <string>
#include <vector>

#include "hazard_case.hpp"

namespace chute {

std::vector<std::string> calibration_range_warnings(const HazardCase& c);

}  // namespace chute
