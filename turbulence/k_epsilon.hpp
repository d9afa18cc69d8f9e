#pragma once
// The standard k-epsilon model (Launder & Spalding 1974), the model Turmel & Locat (2008) ran:
//
//   dk/dt   + div(u k)   = div[(nu + nu_t/sigma_k) grad k]     + P_k - eps
//   deps/dt + div(u eps) = div[(nu + nu_t/sigma_eps) grad eps] + (C_1 P_k - C_2 eps) eps / k
//   nu_t = C_mu k^2 / eps,     P_k = nu_t S^2,  S^2 = 2 S_ij S_ij
//
// One update per flow step, after the projection (docs/design.md data flow), from u^{n+1}:
//   transport  explicit, bounded (scalar_transport.hpp), in sub-steps when dt exceeds its diffusion limit
//   sources    P_k explicit (optionally limited, P_k <= limit * eps), the sinks implicit:
//              k^{n+1} = (k^n + dt (T_k + P_k)) / (1 + dt eps^n / k^n), likewise for eps with C_2,
//              so neither can turn negative from its source (Patankar 1980, source linearisation)
//   walls      the first cell beside a wall side, and the cells beside a body's surface (the carrier's
//              wall samples, body/carrier.hpp), take eps and P_k from the log law (wall_function.hpp); k
//              sees no flux through the wall
//   nu_t       into the flow solver (core/viscous_stress.hpp), with the wall eddy viscosity at wall
//              corners and in the immersed near-wall band
// Inflow values: k = 3/2 (I U)^2, eps = C_mu^{3/4} k^{3/2} / l (turbulence.intensity, length_scale).
#include <optional>
#include <string>

#include "carrier.hpp"
#include "flow_config.hpp"
#include "flow_solver.hpp"
#include "halo_exchange.hpp"
#include "turbulence_config.hpp"

namespace chute {

// What the model needs of a case (run/case_settings.hpp gathers it).
struct KEpsilonSettings {
    TurbulenceConfig model;
    double viscosity = 1e-6;
    double diffusion_number = 0.2;  // explicit transport's limit (numerics.diffusion_number)
    std::array<BoundaryConfig, 4> boundary;
    std::array<double, 2> initial_velocity{0.0, 0.0};
};

class KEpsilon {
public:
    // Throws std::invalid_argument naming the key when the case gives no speed for the initial k.
    // `carrier` tells where the bodies' walls are.
    KEpsilon(const KEpsilonSettings& settings, FlowSolver& flow, Carrier& carrier);

    // Uniform k and eps of the inflow (or the initial speed); nu_t into the flow solver.
    void set_initial_condition();
    // Advance k and eps over the flow step just taken (dt), then refresh nu_t.
    void update(double dt);
    // After k and eps were read from a checkpoint; `eddy_cells_read`: the flow's cell eddy viscosity too, as the
    // last step left it (the cells beside an immersed surface keep the wall's values of that step).
    void restored(bool eddy_cells_read = false);
    // After the grid moved by whole cells (FlowSolver::shift_one_cell moved k, eps and the eddy viscosity along):
    // the walls located on the new lines, the ghosts and the corner eddy viscosity set again.
    void shifted();
    // P_k of the current velocity and nu_t on owned cells (before the wall cells' log-law values).
    void production(Field2D& P) const;
    // Sub-steps of the last update (1 unless dt exceeded the explicit diffusion limit of k and eps).
    int last_substeps() const { return last_substeps_; }
    // Empty, or what went wrong (non-finite k or eps, nu_t beyond 1e8 nu): collective.
    std::optional<std::string> check() const;

    Field2D& k() { return k_; }
    Field2D& epsilon() { return eps_; }
    const Field2D& k() const { return k_; }
    const Field2D& epsilon() const { return eps_; }
    const Field2D& eddy_viscosity() const { return flow_.eddy_viscosity().cell; }
    double inflow_k() const { return k_in_; }
    double inflow_epsilon() const { return eps_in_; }
    // k and the wall law, for the turbulent part of the surface forces.
    WallTurbulence at_walls() const;

private:
    // A cell beside a body's surface with the wall law applied to the carrier's sample there.
    struct NearWallCell {
        int i, j;            // local indices (owned cell)
        double distance;     // of the cell centre from the surface (m); negative inside the body
        double size;         // h (m)
        double y;            // distance from the surface of the point the carrier sampled (m)
        double nu_wall;      // m^2/s
        double tau_wall;     // kinematic wall shear, m^2/s^2
        bool wall_function;  // 0 <= d < h: epsilon and the production of k come from the wall function
    };
    void sample_walls();
    void set_hole_corners(const SolidCells& holes);
    void set_surface_corners();
    struct WallCell {
        int i, j;
        double y;           // distance the log law is applied at
        double production;  // P_k from the wall shear
    };
    // Halo exchange, then the domain sides: `inflow` on inflow sides (null: zero gradient there too), zero
    // gradient on the others; periodic sides by the exchange.
    void set_ghosts(Field2D& f, const double* inflow) const;
    std::vector<WallCell> wall_cells() const;  // domain walls and immersed surfaces: this rank's
    // nu_t from k and eps, the flow's cell eddy viscosity from it with the cells beside an immersed surface at least
    // the wall's (unless `cells_kept`: the cells as a step left them, read or moved), then the ghosts and corners.
    void refresh_eddy_viscosity(bool cells_kept = false);
    int substeps_for(double dt) const;
    std::string too_many_substeps(double needed, double dt, double max_nu_t) const;

    KEpsilonSettings settings_;
    FlowSolver& flow_;
    const Grid& grid_;
    Carrier& carrier_;
    mutable HaloExchange halo_;
    Field2D k_, eps_, model_nu_t_, P_, tk_, te_, was_fluid_, wall_nu_;
    std::vector<NearWallCell> near_wall_;
    double k_in_ = 0.0, eps_in_ = 0.0, k_floor_ = 0.0, eps_floor_ = 0.0;
    int last_substeps_ = 1;
};

}  // namespace chute
