#pragma once
// The whole case (docs/case-file.md for every key): the flow's part (core/flow_config.hpp) and each module's
// own config, with the run's own keys (its name and its outputs). Plain data: run/case_file.cpp assembles it
// from the modules' schema sections; run/ hands each module its part (case_settings.hpp).
#include <array>
#include <string>
#include <vector>

#include "body_config.hpp"
#include "contact_config.hpp"
#include "flow_config.hpp"
#include "ibm_config.hpp"
#include "rigidbody_config.hpp"
#include "turbulence_config.hpp"

namespace chute {

// The flow's members (x, y, viscosity, boundary, cfl, ...) are inherited, so a case reads c.viscosity and
// FlowSolver takes the case as the FlowConfig it is.
struct CaseConfig : FlowConfig {
    std::string name = "case";

    std::array<double, 2> gravity{0.0, -9.81};  // m/s^2, on free bodies (rigidbody/)
    std::vector<BodyConfig> bodies;             // body/
    IbmConfig ibm;                              // ibm/
    ContactConfig contact;                      // contact/
    LumpedConfig lumped;                        // rigidbody/
    CouplingConfig coupling;                    // rigidbody/
    TurbulenceConfig turbulence;                // turbulence/

    // Outputs
    double field_interval = 0.0;       // s between field snapshots; 0: first and last only
    double checkpoint_interval = 0.0;  // s between checkpoints; 0: last only
    int checkpoints_kept = 2;
    int timeseries_every = 1;        // steps
    double progress_interval = 2.0;  // wall seconds between progress lines
    std::vector<std::array<double, 2>> probes;
    bool plots = true;
};

}  // namespace chute
