#pragma once
// What each module is given of the case: the modules below run/ know their own config and the flow's
// (core/flow_config.hpp), never the whole case; these gather, from the case, the settings each one takes.
#include "body_fitted.hpp"
#include "case_config.hpp"
#include "free_bodies.hpp"
#include "immersed_boundary.hpp"
#include "k_epsilon.hpp"

namespace chute {

ImmersedBoundarySettings immersed_boundary_settings(const CaseConfig& config);
BodyFittedSettings body_fitted_settings(const CaseConfig& config);
FreeBodySettings free_body_settings(const CaseConfig& config);
KEpsilonSettings k_epsilon_settings(const CaseConfig& config);

}  // namespace chute
