#pragma once
// The turbulence model's part of a case (docs/case-file.md, `turbulence`). Plain data: read_turbulence()
// fills it (turbulence_keys.cpp, the schema's turbulence section).
#include <vector>

namespace chute {

// laminar: nu only. k_epsilon: standard k-epsilon (Launder & Spalding 1974) with log-law wall functions on
// no-slip sides and immersed surfaces; nu_t = C_mu k^2 / eps enters the momentum equation.
enum class TurbulenceModelType { laminar, k_epsilon };

struct TurbulenceConfig {
    TurbulenceModelType model = TurbulenceModelType::laminar;
    double intensity = 0.05;         // I: inflow and initial k = 3/2 (I U)^2
    double length_scale = 0.1;       // m: inflow and initial eps = C_mu^{3/4} k^{3/2} / l
    double velocity_scale = 0.0;     // m/s: U of the initial k; 0: the largest inflow or initial speed
    double production_limit = 10.0;  // P_k <= limit * eps (0: no limiter)
    bool kato_launder = false;       // P_k = nu_t S Omega (Kato & Launder 1993) instead of nu_t S^2
    double image_distance = 2.0;     // cells: where wall functions sample the flow beside an immersed surface
    int max_substeps = 1000;         // explicit transport sub-steps in one flow step before the run stops
};

// The schema's turbulence section (io/case_reader.hpp) and its reading.
struct CaseKey;
class CaseReader;
std::vector<CaseKey> turbulence_keys();
TurbulenceConfig read_turbulence(const CaseReader& reader);

}  // namespace chute
