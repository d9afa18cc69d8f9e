// The turbulence model's section of the case-file schema (turbulence_config.hpp) and its reading.
#include "case_reader.hpp"
#include "turbulence_config.hpp"

namespace chute {

std::vector<CaseKey> turbulence_keys() {
    using K = KeyType;
    return {
        {.path = "turbulence",
         .type = K::section,
         .meaning = "Turbulence model (turbulence/). Inflow and initial k and epsilon follow from an intensity "
                    "and a length scale."},
        {.path = "turbulence.model",
         .type = K::choice,
         .default_value = "laminar",
         .choices = {"laminar", "k_epsilon"},
         .meaning = "`laminar`: molecular viscosity only. `k_epsilon`: standard k-epsilon (Launder & Spalding "
                    "1974: C_mu 0.09, C_1 1.44, C_2 1.92, sigma_k 1.0, sigma_eps 1.3) with log-law wall "
                    "functions (kappa 0.41, E 9.8, switch at y+ 11.53) on wall sides and immersed surfaces."},
        {.path = "turbulence.intensity",
         .type = K::number,
         .default_value = "0.05",
         .min = above(0.0),
         .max = at_most(1.0),
         .meaning = "Turbulence intensity I of the inflow and the initial field: k = 3/2 (I U)^2."},
        {.path = "turbulence.length_scale",
         .type = K::number,
         .default_value = "0.1",
         .min = above(0.0),
         .units = "m",
         .meaning = "Turbulence length scale l of the inflow and the initial field: eps = C_mu^(3/4) k^(3/2) / l."},
        {.path = "turbulence.velocity_scale",
         .type = K::number,
         .default_value = "0.0",
         .min = at_least(0.0),
         .units = "m/s",
         .meaning = "Speed U of the initial k. 0: the largest inflow or initial speed; give it for a body "
                    "released in still water (for instance its expected fall speed)."},
        {.path = "turbulence.production_limit",
         .type = K::number,
         .default_value = "10.0",
         .min = at_least(0.0),
         .meaning = "Production limiter P_k <= limit * eps (Menter 1994), which stops k piling up at "
                    "stagnation points; 0 switches it off."},
        {.path = "turbulence.production",
         .type = K::choice,
         .default_value = "standard",
         .choices = {"standard", "kato_launder"},
         .meaning = "Production of k: `standard` P_k = nu_t S^2, or `kato_launder` P_k = nu_t S Omega (Kato & "
                    "Launder 1993; S and Omega the strain and rotation rates), which is zero in irrotational "
                    "strain and so removes the standard model's excess of k where the flow meets a bluff "
                    "body's front face; the same in simple shear."},
        {.path = "turbulence.image_distance",
         .type = K::number,
         .default_value = "2.0",
         .min = above(0.0),
         .meaning = "Distance from an immersed surface, in cells along the normal, of the image point where "
                    "the wall function samples the tangential velocity and k (outside the forcing's reach)."},
        {.path = "turbulence.max_substeps",
         .type = K::integer,
         .default_value = "1000",
         .min = at_least(1),
         .meaning = "Most sub-steps the explicit transport of k and epsilon may take in one flow step (each "
                    "within its diffusion limit, numerics.diffusion_number). A step that would need more "
                    "stops the run (exit code 3) with the diffusivity that asked for them: usually a "
                    "viscosity given in the wrong units, or a runaway eddy viscosity."},
    };
}

TurbulenceConfig read_turbulence(const CaseReader& r) {
    TurbulenceConfig c;
    c.model = r.choice<TurbulenceModelType>(
        "turbulence.model", {{"laminar", TurbulenceModelType::laminar}, {"k_epsilon", TurbulenceModelType::k_epsilon}});
    c.intensity = r.number("turbulence.intensity");
    c.length_scale = r.number("turbulence.length_scale");
    c.velocity_scale = r.number("turbulence.velocity_scale");
    c.production_limit = r.number("turbulence.production_limit");
    c.kato_launder = r.choice("turbulence.production") == "kato_launder";
    c.image_distance = r.number("turbulence.image_distance");
    c.max_substeps = static_cast<int>(r.integer("turbulence.max_substeps"));
    return c;
}

}  // namespace chute
