#pragma once
// Values a case may hold but that are physically odd for this solver: each gets a warning before the run
// starts, naming the key and what is expected, and the run goes on (the schema, case_file.hpp, has already
// refused what cannot run at all). The checks, with the scale they compare against:
//   fluid.viscosity above 1 m^2/s (water 1e-6, air 1.5e-5, glycerol 1e-3): a unit slip (dynamic for
//     kinematic, or mm^2/s for m^2/s) makes a run crawl or stop;
//   fluid.density outside [0.05, 20000] kg/m^3 (air 1.2, water 1000, mercury 13 500);
//   a body's density above 25 000 kg/m^3 (denser than any solid), or a free body lighter than the fluid
//     (it will rise, which a rockfall case rarely means);
//   a closed body narrower than two cells where it starts: the immersed boundary cannot represent it
//     (docs/validation.md resolves the block with 20);
//   a first time step the CFL and diffusion limits would put below 1e-9 s, or a run that would need more
//     than 1e8 steps to time.end, estimated from the case's speeds (inflow, walls, initial current, bodies'
//     reference and prescribed velocities) and its finest cell;
//   gravity pointing up or stronger than 100 m/s^2 when free bodies feel it.
#include <string>
#include <vector>

#include "case_config.hpp"

namespace chute {

// One line per odd value, "key: what is odd; what is expected" (empty for a plausible case).
std::vector<std::string> plausibility_warnings(const CaseConfig& config);

}  // namespace chute
