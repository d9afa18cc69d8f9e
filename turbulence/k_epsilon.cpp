#include "k_epsilon.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "run_failure.hpp"
#include "scalar_transport.hpp"
#include "wall_function.hpp"

namespace chute {

namespace {

using C = KEpsilonConstants;

bool is_wall(const KEpsilonSettings& c, Side s) { return c.boundary[static_cast<int>(s)].type == BoundaryType::wall; }

// The speed that sets the inflow and initial k.
double velocity_scale(const KEpsilonSettings& c) {
    if (c.model.velocity_scale > 0.0) return c.model.velocity_scale;
    double u = std::hypot(c.initial_velocity[0], c.initial_velocity[1]);
    for (const BoundaryConfig& b : c.boundary)
        if (b.type == BoundaryType::inflow)
            u = std::max(u, b.profile == InflowProfile::parabolic ? b.peak : std::hypot(b.velocity[0], b.velocity[1]));
    return u;
}

}  // namespace

KEpsilon::KEpsilon(const KEpsilonSettings& settings, FlowSolver& flow, Carrier& carrier)
    : settings_(settings), flow_(flow), grid_(flow.grid()), carrier_(carrier), halo_(flow.grid()) {
    const TurbulenceConfig& config = settings_.model;
    const double U = velocity_scale(settings_);
    if (U <= 0.0)
        throw std::invalid_argument(
            "turbulence.velocity_scale: the case has no inflow and no initial speed, so it must give the speed "
            "that sets the initial k (for a body released in still water, about its fall speed)");
    k_in_ = 1.5 * std::pow(config.intensity * U, 2);
    eps_in_ = std::pow(C::c_mu, 0.75) * std::pow(k_in_, 1.5) / config.length_scale;
    // Floors far below any physical level: they only keep eps / k and C_mu k^2 / eps defined.
    k_floor_ = 1e-10 * k_in_;
    eps_floor_ = 1e-10 * eps_in_;
    k_ = eps_ = model_nu_t_ = P_ = tk_ = te_ = wall_nu_ = Field2D(grid_);
    was_fluid_ = Field2D(grid_, 1.0);
    // A body-fitted grid's topology changes (band/layers.hpp) carry them along with the flow's fields.
    for (Field2D* f : {&k_, &eps_, &model_nu_t_, &was_fluid_}) flow_.remap_with_grid(f);
    set_initial_condition();
}

void KEpsilon::set_initial_condition() {
    k_.fill(k_in_);
    eps_.fill(eps_in_);
    restored();
}

void KEpsilon::restored(bool eddy_cells_read) {
    carrier_.locate_walls();
    was_fluid_ = carrier_.fluid_cells();
    set_ghosts(k_, &k_in_);
    set_ghosts(eps_, &eps_in_);
    sample_walls();
    refresh_eddy_viscosity(eddy_cells_read);
}

void KEpsilon::shifted() {
    carrier_.locate_walls();
    set_ghosts(k_, &k_in_);
    set_ghosts(eps_, &eps_in_);
    sample_walls();  // where the near-wall cells are now (the next update samples again)
    refresh_eddy_viscosity(true);
}

// The log law at the carrier's samples beside the bodies (y = the sample's distance from the surface):
//   nu_w   the wall eddy viscosity; the band cells get nu_t >= nu_w, so the momentum flux through the band,
//          (nu + nu_w) U_t / y, is the log-law wall shear
//   tau_w  the wall shear, which sets the production of k in the wall-function cells
void KEpsilon::sample_walls() {
    const double nu = settings_.viscosity;
    near_wall_.clear();
    for (const WallSample& s : carrier_.sample_walls(flow_.velocity(), k_)) {
        const WallFunction wf(s.k, s.image_distance, nu);
        near_wall_.push_back({s.i, s.j, s.distance, s.size, s.image_distance, wf.nu_wall,
                              wf.shear(s.slip_speed, s.image_distance, nu), s.wall_function});
    }
}

WallTurbulence KEpsilon::at_walls() const {
    const double nu = settings_.viscosity;
    return {k_, [nu](double k, double y) { return WallFunction(k, y, nu).nu_wall; }};
}

// Ghosts of k and eps: inflow values on inflow sides, zero gradient elsewhere (walls: no flux of k; outflow;
// slip); periodic sides and patch edges by the halo exchange.
void KEpsilon::set_ghosts(Field2D& f, const double* inflow) const {
    halo_.exchange(f);
    const int nx = grid_.nx(), ny = grid_.ny();
    for (Side s : kSides) {
        if (!grid_.touches(s)) continue;
        const BoundaryType type = settings_.boundary[static_cast<int>(s)].type;
        if (type == BoundaryType::periodic) continue;
        const bool in = inflow && type == BoundaryType::inflow;
        for (int g = 1; g <= kGhost; ++g) {
            if (s == Side::left || s == Side::right)
                for (int j = -kGhost; j < ny + kGhost; ++j) {
                    const int ghost = s == Side::left ? -g : nx - 1 + g, mirror = s == Side::left ? g - 1 : nx - g;
                    f(ghost, j) = in ? *inflow : f(mirror, j);
                }
            else
                for (int i = -kGhost; i < nx + kGhost; ++i) {
                    const int ghost = s == Side::bottom ? -g : ny - 1 + g, mirror = s == Side::bottom ? g - 1 : ny - g;
                    f(i, ghost) = in ? *inflow : f(i, mirror);
                }
        }
    }
}

// P_k = nu_t S^2 with S^2 = 2 (du/dx^2 + dv/dy^2) + (du/dy + dv/dx)^2, the shear strain taken at the four
// corners of the cell and its square averaged; with turbulence.production kato_launder, P_k = nu_t S Omega,
// Omega = |dv/dx - du/dy| (Kato & Launder 1993), the vorticity's square averaged over the corners likewise.
void KEpsilon::production(Field2D& P) const {
    const auto& X = grid_.lx();
    const auto& Y = grid_.ly();
    const Velocity& vel = flow_.velocity();
    auto shear = [&](int a, int b) {
        return (vel.u(a, b) - vel.u(a, b - 1)) / Y.dc(b) + (vel.v(a, b) - vel.v(a - 1, b)) / X.dc(a);
    };
    auto vorticity = [&](int a, int b) {
        return (vel.v(a, b) - vel.v(a - 1, b)) / X.dc(a) - (vel.u(a, b) - vel.u(a, b - 1)) / Y.dc(b);
    };
    const bool kato_launder = settings_.model.kato_launder;
    const double limit = settings_.model.production_limit;
    for (int j = 0; j < grid_.ny(); ++j)
        for (int i = 0; i < grid_.nx(); ++i) {
            const double dudx = (vel.u(i + 1, j) - vel.u(i, j)) / X.w(i);
            const double dvdy = (vel.v(i, j + 1) - vel.v(i, j)) / Y.w(j);
            const double s00 = shear(i, j), s10 = shear(i + 1, j), s01 = shear(i, j + 1), s11 = shear(i + 1, j + 1);
            const double S2 =
                2.0 * (dudx * dudx + dvdy * dvdy) + 0.25 * (s00 * s00 + s10 * s10 + s01 * s01 + s11 * s11);
            double p = model_nu_t_(i, j) * S2;
            if (kato_launder) {
                const double w00 = vorticity(i, j), w10 = vorticity(i + 1, j), w01 = vorticity(i, j + 1),
                             w11 = vorticity(i + 1, j + 1);
                const double W2 = 0.25 * (w00 * w00 + w10 * w10 + w01 * w01 + w11 * w11);
                p = model_nu_t_(i, j) * std::sqrt(S2 * W2);
            }
            if (limit > 0.0) p = std::min(p, limit * eps_(i, j));
            P(i, j) = p;
        }
}

// The cells whose eps and P_k come from the log law: the first cell beside each wall side, and the
// wall-function cells beside immersed surfaces.
std::vector<KEpsilon::WallCell> KEpsilon::wall_cells() const {
    std::vector<WallCell> out;
    const auto& X = grid_.lx();
    const auto& Y = grid_.ly();
    const Velocity& vel = flow_.velocity();
    const double nu = settings_.viscosity;
    const int nx = grid_.nx(), ny = grid_.ny();
    for (Side s : kSides) {
        if (!grid_.touches(s) || !is_wall(settings_, s)) continue;
        const auto& wall = settings_.boundary[static_cast<int>(s)].velocity;
        if (s == Side::bottom || s == Side::top) {
            const int j = s == Side::bottom ? 0 : ny - 1;
            const double y = 0.5 * Y.w(j);
            for (int i = 0; i < nx; ++i) {
                const double speed = std::abs(0.5 * (vel.u(i, j) + vel.u(i + 1, j)) - wall[0]);
                const WallFunction wf(k_(i, j), y, nu);
                out.push_back({i, j, y, wf.production(wf.shear(speed, y, nu), y)});
            }
        } else {
            const int i = s == Side::left ? 0 : nx - 1;
            const double y = 0.5 * X.w(i);
            for (int j = 0; j < ny; ++j) {
                const double speed = std::abs(0.5 * (vel.v(i, j) + vel.v(i, j + 1)) - wall[1]);
                const WallFunction wf(k_(i, j), y, nu);
                out.push_back({i, j, y, wf.production(wf.shear(speed, y, nu), y)});
            }
        }
    }
    // Beside an immersed surface the cell centre may be anywhere from on the surface to a cell away: its
    // fluid part spans about [0, d + h/2], whose middle stands for its distance.
    for (const NearWallCell& c : near_wall_)
        if (c.wall_function) {
            const double y = 0.5 * (c.distance + 0.5 * c.size);
            out.push_back({c.i, c.j, y, WallFunction(k_(c.i, c.j), y, nu).production(c.tau_wall, y)});
        }
    return out;
}

void KEpsilon::update(double dt) {
    const double nu = settings_.viscosity;
    carrier_.locate_walls();
    const Field2D& fluid = carrier_.fluid_cells();
    // k and eps ghosts are current: set at the end of the last update (or by restored()).
    sample_walls();

    production(P_);
    const std::vector<WallCell> walls = wall_cells();
    for (const WallCell& w : walls) P_(w.i, w.j) = w.production;
    // The transport is explicit: when the flow step (with implicit momentum diffusion free of the eddy
    // viscosity's limit) exceeds the diffusion limit of k and eps, the update is split into equal sub-steps.
    const int substeps = substeps_for(dt);
    const double h = dt / substeps;
    for (int sub = 0; sub < substeps; ++sub) {
        if (sub > 0) {
            set_ghosts(k_, &k_in_);
            set_ghosts(eps_, &eps_in_);
        }
        scalar_transport(grid_, flow_.velocity(), model_nu_t_, nu, fluid,
                         {{&k_, C::sigma_k, &tk_}, {&eps_, C::sigma_eps, &te_}}, flow_.line_velocities());
        for (int j = 0; j < grid_.ny(); ++j)
            for (int i = 0; i < grid_.nx(); ++i) {
                if (fluid(i, j) == 0.0) continue;
                const double k = k_(i, j), e = eps_(i, j), rate = e / k;
                k_(i, j) = std::max(k_floor_, (k + h * (tk_(i, j) + P_(i, j))) / (1.0 + h * rate));
                eps_(i, j) =
                    std::max(eps_floor_, (e + h * (te_(i, j) + C::c1 * rate * P_(i, j))) / (1.0 + h * C::c2 * rate));
            }
        for (const WallCell& w : walls)
            eps_(w.i, w.j) =
                std::max(eps_floor_, WallFunction(k_(w.i, w.j), w.y, nu).dissipation(k_(w.i, w.j), w.y, nu));
    }
    last_substeps_ = substeps;

    // Cells the bodies uncovered this step start from their fluid neighbours.
    for (int j = 0; j < grid_.ny(); ++j)
        for (int i = 0; i < grid_.nx(); ++i) {
            if (fluid(i, j) == 0.0 || was_fluid_(i, j) != 0.0) continue;
            double sk = 0.0, se = 0.0, n = 0.0;
            for (auto [a, b] : {std::pair{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}})
                if (was_fluid_(a, b) != 0.0 && fluid(a, b) != 0.0) sk += k_(a, b), se += eps_(a, b), n += 1.0;
            k_(i, j) = n > 0.0 ? sk / n : k_in_;
            eps_(i, j) = n > 0.0 ? se / n : eps_in_;
        }
    was_fluid_ = fluid;
    set_ghosts(k_, &k_in_);
    set_ghosts(eps_, &eps_in_);
    refresh_eddy_viscosity();
}

// Explicit diffusion of k (the larger diffusivity, sigma_k <= sigma_eps) is stable for
// h (nu + nu_t / sigma_k)(1/dx^2 + 1/dy^2) <= numerics.diffusion_number (time_step_control.hpp).
// More than turbulence.max_substeps is not a run that will end: it stops, naming the diffusivity that asked
// for them (fluid.viscosity 1000 for water's 1e-6 asks for ~1e9 sub-steps in a 0.01 s step).
int KEpsilon::substeps_for(double dt) const {
    const auto& X = grid_.lx();
    const auto& Y = grid_.ly();
    const Field2D& fluid = carrier_.fluid_cells();
    double peak[2] = {0.0, 0.0};  // the limit's rate 1/h, and the largest nu_t
    for (int j = 0; j < grid_.ny(); ++j)
        for (int i = 0; i < grid_.nx(); ++i)
            if (fluid(i, j) != 0.0) {
                peak[0] = std::max(peak[0], (settings_.viscosity + model_nu_t_(i, j) / C::sigma_k) *
                                                (1.0 / (X.w(i) * X.w(i)) + 1.0 / (Y.w(j) * Y.w(j))));
                peak[1] = std::max(peak[1], model_nu_t_(i, j));
            }
    MPI_Allreduce(MPI_IN_PLACE, peak, 2, MPI_DOUBLE, MPI_MAX, grid_.comm());
    const double needed = std::max(1.0, std::ceil(dt * peak[0] / settings_.diffusion_number));
    if (!(needed <= settings_.model.max_substeps)) throw RunFailure(too_many_substeps(needed, dt, peak[1]));
    return static_cast<int>(needed);
}

std::string KEpsilon::too_many_substeps(double needed, double dt, double max_nu_t) const {
    constexpr double water = 1.0e-6;  // m^2/s at 20 C
    const double nu = settings_.viscosity;
    std::ostringstream m;
    m << "the k-epsilon transport would need " << std::setprecision(2) << needed << " sub-steps in one step of "
      << std::setprecision(3) << dt << " s (turbulence.max_substeps = " << settings_.model.max_substeps << "): ";
    if (!std::isfinite(max_nu_t))
        m << "the eddy viscosity is no longer finite";
    else if (nu >= max_nu_t / C::sigma_k)
        m << "fluid.viscosity " << std::setprecision(6) << nu << " m^2/s is " << std::setprecision(2) << nu / water
          << " times water's (1e-06 m^2/s); check its units (kinematic viscosity, m^2/s)";
    else
        m << "the eddy viscosity reaches " << std::setprecision(3) << max_nu_t << " m^2/s, " << std::setprecision(2)
          << max_nu_t / nu
          << " times fluid.viscosity (a runaway nu_t: refine the grid, lower numerics.cfl or check "
             "turbulence.intensity and turbulence.length_scale)";
    return m.str();
}

// nu_t = C_mu k^2 / eps in the fluid, 0 inside bodies, at least the wall eddy viscosity in the immersed
// near-wall band; corners average their four cells, except on wall sides: the wall-function value there.
void KEpsilon::refresh_eddy_viscosity(bool cells_kept) {
    EddyViscosity& e = flow_.eddy_viscosity();
    const Field2D& fluid = carrier_.fluid_cells();
    const double nu = settings_.viscosity;
    const int nx = grid_.nx(), ny = grid_.ny();
    for (int j = -kGhost; j < ny + kGhost; ++j)
        for (int i = -kGhost; i < nx + kGhost; ++i)
            model_nu_t_(i, j) = fluid(i, j) != 0.0 ? C::c_mu * k_(i, j) * k_(i, j) / eps_(i, j) : 0.0;
    if (!cells_kept)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) e.cell(i, j) = model_nu_t_(i, j);
    // Beside an immersed surface the near-wall band takes at least the wall's eddy viscosity; a body-fitted
    // hole's sides are walls like the domain's (their corners below).
    const SolidCells* holes = flow_.solid_cells();
    const bool between_cells = carrier_.walls_between_cells();
    if (!holes && !cells_kept && !between_cells)
        for (const NearWallCell& c : near_wall_) e.cell(c.i, c.j) = std::max(e.cell(c.i, c.j), c.nu_wall);
    set_ghosts(e.cell, nullptr);  // zero gradient across every domain side
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
            e.corner(i, j) = 0.25 * (e.cell(i - 1, j - 1) + e.cell(i, j - 1) + e.cell(i - 1, j) + e.cell(i, j));
    // Wall sides: the corners on the wall carry the wall eddy viscosity of the two cells beside them, so
    // that (nu + nu_w) times the mirrored-ghost gradient U_t / y is the log-law shear.
    const auto& X = grid_.lx();
    const auto& Y = grid_.ly();
    for (Side s : kSides) {
        if (!grid_.touches(s) || !is_wall(settings_, s)) continue;
        if (s == Side::bottom || s == Side::top) {
            const int j = s == Side::bottom ? 0 : ny - 1, jc = s == Side::bottom ? 0 : ny;
            const double y = 0.5 * Y.w(j);
            for (int i = 0; i <= nx; ++i)
                e.corner(i, jc) =
                    0.5 * (WallFunction(k_(i - 1, j), y, nu).nu_wall + WallFunction(k_(i, j), y, nu).nu_wall);
        } else {
            const int i = s == Side::left ? 0 : nx - 1, ic = s == Side::left ? 0 : nx;
            const double y = 0.5 * X.w(i);
            for (int j = 0; j <= ny; ++j)
                e.corner(ic, j) =
                    0.5 * (WallFunction(k_(i, j - 1), y, nu).nu_wall + WallFunction(k_(i, j), y, nu).nu_wall);
        }
    }
    if (holes) set_hole_corners(*holes);
    if (between_cells) set_surface_corners();
    double mx = 0.0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) mx = std::max(mx, e.cell(i, j));
    MPI_Allreduce(MPI_IN_PLACE, &mx, 1, MPI_DOUBLE, MPI_MAX, grid_.comm());
    e.max = mx;
}

// The corners along a body-fitted hole's sides carry the wall eddy viscosity of the two fluid cells beside
// them, as the domain's walls do (refresh_eddy_viscosity); a side's two end corners keep their average.
void KEpsilon::set_hole_corners(const SolidCells& holes) {
    EddyViscosity& e = flow_.eddy_viscosity();
    const double nu = settings_.viscosity;
    const Axis& X = grid_.x_axis();
    const Axis& Y = grid_.y_axis();
    const int ox = grid_.lx().offset, oy = grid_.ly().offset, nx = grid_.nx(), ny = grid_.ny();
    // Corner (gi, gj) between fluid cells a and b, each y from the side.
    auto set = [&](int gi, int gj, std::array<int, 2> a, std::array<int, 2> b, double y) {
        const int i = gi - ox, j = gj - oy;
        if (i < 0 || i > nx || j < 0 || j > ny) return;
        const double ka = k_(a[0] - ox, a[1] - oy), kb = k_(b[0] - ox, b[1] - oy);
        e.corner(i, j) = 0.5 * (WallFunction(ka, y, nu).nu_wall + WallFunction(kb, y, nu).nu_wall);
    };
    // A block across a whole periodic direction has no ends there: every corner of its side is a wall corner.
    for (const SolidBlock& h : holes.blocks()) {
        const int end_x = holes.spans_periodic(h, 0) ? 0 : 1, end_y = holes.spans_periodic(h, 1) ? 0 : 1;
        for (const bool top : {false, true}) {  // corners on the bottom and top sides, fluid row below / above
            const int gj = top ? h.upper[1] : h.lower[1], row = top ? h.upper[1] : h.lower[1] - 1;
            const double y = 0.5 * Y.width(row);
            for (int gi = h.lower[0] + end_x; gi <= h.upper[0] - end_x; ++gi) set(gi, gj, {gi - 1, row}, {gi, row}, y);
        }
        for (const bool right : {false, true}) {  // corners on the left and right sides
            const int gi = right ? h.upper[0] : h.lower[0], col = right ? h.upper[0] : h.lower[0] - 1;
            const double y = 0.5 * X.width(col);
            for (int gj = h.lower[1] + end_y; gj <= h.upper[1] - end_y; ++gj) set(gi, gj, {col, gj - 1}, {col, gj}, y);
        }
    }
}

// A sharp surface between fluid and solid cells (Carrier::walls_between_cells): every corner with a solid cell and a
// wall-function cell among its four carries the wall eddy viscosity of those wall-function cells (their k now, at
// the distance the carrier sampled them), so that (nu + nu_w) times the ghost faces' mirrored gradient across the
// surface is the log-law shear, as on a body-fitted hole's sides (set_hole_corners).
void KEpsilon::set_surface_corners() {
    EddyViscosity& e = flow_.eddy_viscosity();
    const Field2D& fluid = carrier_.fluid_cells();
    const double nu = settings_.viscosity;
    wall_nu_.fill(-1.0);
    for (const NearWallCell& c : near_wall_)
        if (c.wall_function) wall_nu_(c.i, c.j) = WallFunction(k_(c.i, c.j), c.y, nu).nu_wall;
    halo_.exchange(wall_nu_);
    for (int j = 0; j <= grid_.ny(); ++j)
        for (int i = 0; i <= grid_.nx(); ++i) {
            bool solid = false;
            double sum = 0.0, n = 0.0;
            for (auto [a, b] : {std::pair{i - 1, j - 1}, {i, j - 1}, {i - 1, j}, {i, j}}) {
                solid = solid || fluid(a, b) == 0.0;
                if (wall_nu_(a, b) >= 0.0) sum += wall_nu_(a, b), n += 1.0;
            }
            if (solid && n > 0.0) e.corner(i, j) = sum / n;
        }
}

std::optional<std::string> KEpsilon::check() const {
    int bad[2] = {0, 0};  // non-finite k or eps; runaway nu_t
    const double limit = 1e8 * settings_.viscosity;
    for (int j = 0; j < grid_.ny(); ++j)
        for (int i = 0; i < grid_.nx(); ++i) {
            if (!std::isfinite(k_(i, j)) || !std::isfinite(eps_(i, j))) bad[0] = 1;
            if (!(flow_.eddy_viscosity().cell(i, j) < limit)) bad[1] = 1;
        }
    MPI_Allreduce(MPI_IN_PLACE, bad, 2, MPI_INT, MPI_MAX, grid_.comm());
    if (bad[0]) return "k-epsilon: k or epsilon is no longer finite";
    if (bad[1]) return "k-epsilon: the eddy viscosity exceeds 1e8 times the molecular viscosity";
    return std::nullopt;
}

}  // namespace chute
