#include "flow_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "convection.hpp"
#include "diagnostics.hpp"
#include "diffusion.hpp"
#include "direct_poisson.hpp"
#include "line_motion.hpp"
#include "projection.hpp"
#include "remap.hpp"
#include "time_step_control.hpp"

namespace chute {

Axis build_axis(const AxisConfig& c, bool periodic) { return Axis(axis_lines(c), periodic); }

namespace {
// The decomposition, where the case leaves it to Chute: with the direct Poisson solve, the patches split only the
// axis the tridiagonal systems run along, so that each holds whole lines along the transform and the systems are
// solved where they lie (direct_poisson.hpp: no transpose at all). With both axes uniform the transform runs along
// x, whose lines lie contiguous in memory (strided transforms along y cost FFTW copies). Else MPI's choice.
std::array<int, 2> choose_ranks(const FlowConfig& c, const Axis& x, const Axis& y, MPI_Comm comm) {
    if (c.ranks[0] > 0 || c.ranks[1] > 0 || c.poisson_method != PoissonMethod::automatic) return c.ranks;
    int ranks = 1;
    MPI_Comm_size(comm, &ranks);
    const bool ux = uniform_axis(x), uy = uniform_axis(y);
    if (ux && !y.periodic() && y.cells() >= kGhost * ranks) return {1, ranks};
    if (uy && !ux && !x.periodic() && x.cells() >= kGhost * ranks) return {ranks, 1};
    return c.ranks;
}
}  // namespace

FlowSolver::FlowSolver(const FlowConfig& config, MPI_Comm comm) : config_(config) {
    const bool px = config_.boundary[0].type == BoundaryType::periodic;
    const bool py = config_.boundary[2].type == BoundaryType::periodic;
    Axis x = build_axis(config_.x, px), y = build_axis(config_.y, py);
    const std::array<int, 2> ranks = choose_ranks(config_, x, y, comm);
    grid_ = std::make_unique<Grid>(std::move(x), std::move(y), comm, ranks[0], ranks[1]);
    halo_ = std::make_unique<HaloExchange>(*grid_);
    bc_ = std::make_unique<BoundaryConditions>(*grid_, config_.boundary);
    std::array<bool, 4> dirichlet{};
    for (Side s : kSides) dirichlet[static_cast<int>(s)] = bc_->pressure_dirichlet(s);
    poisson_ = std::make_unique<PoissonSolver>(*grid_, dirichlet, config_.poisson_tolerance,
                                               config_.poisson_max_iterations, config_.poisson_method);
    implicit_now_ = config_.diffusion == DiffusionScheme::implicit_euler;
    inverse_h2_max_ = max_inverse_square_spacing(*grid_);
    vel_ = star_ = rhs_ = rhs_old_ = Velocity(*grid_);
    p_ = p_old_ = phi_ = source_ = Field2D(*grid_);
    eddy_ = EddyViscosity(*grid_);
    set_initial_condition();
}

void FlowSolver::set_initial_condition() {
    const auto& X = grid_->lx();
    const auto& Y = grid_->ly();
    for (int j = -kGhost; j < grid_->ny() + kGhost; ++j)
        for (int i = -kGhost; i < grid_->nx() + kGhost; ++i) {
            if (config_.initial == InitialCondition::taylor_green) {
                // u = V0 cos x sin y, v = -V0 sin x cos y, p = -(V0^2/4)(cos 2x + cos 2y)  (kinematic p)
                const double V0 = config_.taylor_green_amplitude;
                vel_.u(i, j) = V0 * std::cos(X.f(i)) * std::sin(Y.c(j));
                vel_.v(i, j) = -V0 * std::sin(X.c(i)) * std::cos(Y.f(j));
                p_(i, j) = -0.25 * V0 * V0 * (std::cos(2.0 * X.c(i)) + std::cos(2.0 * Y.c(j)));
            } else {
                vel_.u(i, j) = config_.initial_velocity[0];
                // v = e sin(2 pi (x - x0) / Lx) is divergence-free; the first projection fits it to the walls.
                const double Lx = grid_->x_axis().length();
                vel_.v(i, j) = config_.initial_velocity[1] +
                               config_.initial_perturbation *
                                   std::sin(2.0 * std::numbers::pi * (X.c(i) - grid_->x_axis().start()) / Lx);
                p_(i, j) = 0.0;
            }
        }
    time_ = 0.0;
    step_ = 0;
    dt_previous_ = 0.0;
    pressure_history_ = false;
    refresh_ghosts();
}

void FlowSolver::fill_boundaries(Velocity& vel) const {
    bc_->apply(vel);
    if (!solid_ || solid_->empty()) return;
    // A hole's face in a halo may mirror a fluid face beyond it: its owner fills it, the exchange brings it.
    solid_->fill(vel);
    halo_->exchange(vel);
    bc_->apply(vel);
}

void FlowSolver::set_pressure_boundary(const PressureBoundary& boundary) {
    if (solid_ && boundary.cells) throw std::logic_error("FlowSolver: a pressure boundary and solid cells together");
    cut_ = boundary;
    if (flux_.u.raw().empty()) flux_ = Velocity(*grid_);
    poisson_->set_face_apertures(cut_.aperture_u, cut_.aperture_v);
    long long count = 0;
    for (int j = 0; j < grid_->ny(); ++j)
        for (int i = 0; i < grid_->nx(); ++i) count += (*cut_.cells)(i, j) != 0.0;
    MPI_Allreduce(MPI_IN_PLACE, &count, 1, MPI_LONG_LONG, MPI_SUM, grid_->comm());
    poisson_->set_fluid_cells(cut_.cells, count);
}

// Through a cut face the fluid's flux on its open part, the body's on the rest: alpha (u + offset) + (1 - alpha) U_b on
// the faces of the owned cells.
void FlowSolver::cut_flux(const Velocity& vel, Velocity& out) const {
    const Field2D &au = *cut_.aperture_u, &av = *cut_.aperture_v;
    const Velocity& U = *cut_.body_velocity;
    const Velocity* offset = nullptr;
    if (cut_.flux_offset) {  // set on the owned faces: the faces shared with the next rank from its halo
        offset_ = *cut_.flux_offset;
        halo_->exchange(offset_);
        offset = &offset_;
    }
    for (int j = 0; j < grid_->ny(); ++j)
        for (int i = 0; i <= grid_->nx(); ++i)
            out.u(i, j) = au(i, j) * (vel.u(i, j) + (offset ? offset->u(i, j) : 0.0)) + (1.0 - au(i, j)) * U.u(i, j);
    for (int j = 0; j <= grid_->ny(); ++j)
        for (int i = 0; i < grid_->nx(); ++i)
            out.v(i, j) = av(i, j) * (vel.v(i, j) + (offset ? offset->v(i, j) : 0.0)) + (1.0 - av(i, j)) * U.v(i, j);
}

void FlowSolver::shut_to_body_velocity(Velocity& vel) const {
    const Field2D &au = *cut_.aperture_u, &av = *cut_.aperture_v;
    const Velocity& U = *cut_.body_velocity;
    for (int j = 0; j < grid_->ny(); ++j)
        for (int i = 0; i <= grid_->nx(); ++i)
            if (au(i, j) == 0.0) vel.u(i, j) = U.u(i, j);
    for (int j = 0; j <= grid_->ny(); ++j)
        for (int i = 0; i < grid_->nx(); ++i)
            if (av(i, j) == 0.0) vel.v(i, j) = U.v(i, j);
}

double FlowSolver::max_divergence() const {
    if (!cut_.cells) return chute::max_divergence(*grid_, vel_, fluid_cells());
    cut_flux(vel_, flux_);
    return chute::max_divergence(*grid_, flux_, cut_.cells);
}

void FlowSolver::set_solid_cells(const SolidCells* solid) {
    solid_ = solid;
    if (implicit_) implicit_->set_solid_cells(solid_);
    poisson_->set_fluid_cells(fluid_cells(), solid_ ? solid_->fluid_cell_count() : grid_->global_cells());
    refresh_ghosts();
    if (step_ == 0 && fluid_cells()) project_start();
}

// u0 -= grad phi with laplacian(phi) = div(u0): the start made divergence-free against the hole's sides (the
// flow an impulsive start sets up at once). Without it the first step's convective flux carries the start's
// divergence, and a run is no longer Galilean invariant (the flux of a constant shift w is w div u).
void FlowSolver::project_start() {
    halo_->exchange(vel_);
    fill_boundaries(vel_);
    divergence(*grid_, vel_, 1.0, source_);
    phi_.fill(0.0);
    poisson_->solve(source_, phi_, poisson_residual_floor(vel_, 1.0));
    halo_->exchange(phi_);
    bc_->apply_pressure(phi_);
    subtract_pressure_gradient(*grid_, *bc_, phi_, 1.0, vel_);
    phi_.fill(0.0);
    halo_->exchange(vel_);
    fill_boundaries(vel_);
}

namespace {

// Visit the owned faces of a solid block: u faces on lines lower[0]..upper[0] across its rows, v faces on lines
// lower[1]..upper[1] across its columns. on_u(i, j) and on_v(i, j) take local indices.
template <class OnU, class OnV>
void for_each_block_face(const Grid& grid, const SolidBlock& b, OnU&& on_u, OnV&& on_v) {
    const int ox = grid.lx().offset, oy = grid.ly().offset;
    const int i0 = std::max(b.lower[0] - ox, 0), j0 = std::max(b.lower[1] - oy, 0);
    const int i1 = std::min(b.upper[0] - ox, grid.nx() - 1), j1 = std::min(b.upper[1] - oy, grid.ny() - 1);
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            if (j + oy < b.upper[1]) on_u(i, j);
            if (i + ox < b.upper[0]) on_v(i, j);
        }
}

}  // namespace

// With implicit diffusion the viscous flux across a hole's sides is not in H: it is taken here, from u* as the
// implicit solve left it (its hole faces filled as the solve's rows assumed), for solid_momentum_rate.
void FlowSolver::implicit_wall_momentum(Velocity& star) {
    implicit_wall_.assign(solid_ ? solid_->blocks().size() : 0, {0.0, 0.0});
    if (!solid_ || solid_->empty()) return;
    halo_->exchange(star);
    fill_boundaries(star);
    for (std::size_t k = 0; k < implicit_wall_.size(); ++k) {
        const auto& X = grid_->lx();
        const auto& Y = grid_->ly();
        std::array<double, 2>& m = implicit_wall_[k];
        for_each_block_face(
            *grid_, solid_->blocks()[k],
            [&](int i, int j) {
                m[0] += X.dc(i) * Y.w(j) * implicit_rate_u(*grid_, config_.viscosity, eddy_, star, i, j);
            },
            [&](int i, int j) {
                m[1] += X.w(i) * Y.dc(j) * implicit_rate_v(*grid_, config_.viscosity, eddy_, star, i, j);
            });
    }
}

std::array<double, 2> FlowSolver::solid_momentum_rate(const SolidBlock& b) const {
    // After the step, rhs_old_ holds H^n and rhs_ H^{n-1} (project() swapped them).
    const auto& X = grid_->lx();
    const auto& Y = grid_->ly();
    double m[2] = {0.0, 0.0};
    for_each_block_face(
        *grid_, b,
        [&](int i, int j) {
            const double H = weight_new_ * rhs_old_.u(i, j) + weight_old_ * rhs_.u(i, j);
            m[0] += X.dc(i) * Y.w(j) * (H - (p_(i, j) - p_(i - 1, j)) / X.dc(i));
        },
        [&](int i, int j) {
            const double H = weight_new_ * rhs_old_.v(i, j) + weight_old_ * rhs_.v(i, j);
            m[1] += X.w(i) * Y.dc(j) * (H - (p_(i, j) - p_(i, j - 1)) / Y.dc(j));
        });
    // The implicit diffusion's flux (this rank's faces; the sum below adds the ranks').
    if (implicit_now_ && solid_)
        for (std::size_t k = 0; k < implicit_wall_.size(); ++k) {
            const SolidBlock& h = solid_->blocks()[k];
            if (h.lower != b.lower || h.upper != b.upper) continue;
            m[0] += implicit_wall_[k][0];
            m[1] += implicit_wall_[k][1];
        }
    MPI_Allreduce(MPI_IN_PLACE, m, 2, MPI_DOUBLE, MPI_SUM, grid_->comm());
    return {m[0], m[1]};
}

std::array<double, 2> FlowSolver::solid_gradient_sum(const SolidBlock& b, const Field2D& q) const {
    const auto& X = grid_->lx();
    const auto& Y = grid_->ly();
    double m[2] = {0.0, 0.0};
    for_each_block_face(
        *grid_, b, [&](int i, int j) { m[0] += Y.w(j) * (q(i, j) - q(i - 1, j)); },
        [&](int i, int j) { m[1] += X.w(i) * (q(i, j) - q(i, j - 1)); });
    MPI_Allreduce(MPI_IN_PLACE, m, 2, MPI_DOUBLE, MPI_SUM, grid_->comm());
    return {m[0], m[1]};
}

FlowSolver::BodyResponse FlowSolver::hole_response(std::size_t block, const BodyResponse* previous,
                                                   std::array<bool, 2> along) {
    if (!solid_ || block >= solid_->blocks().size())
        throw std::logic_error("FlowSolver::hole_response: no solid block " + std::to_string(block));
    BodyResponse r{{Velocity(*grid_), Velocity(*grid_)}, {Field2D(*grid_), Field2D(*grid_)}};
    for (int k = 0; k < 2; ++k) {
        if (!along[k]) continue;
        // The sides of `block` moving at e_k, everything else at rest: the source the projection sees.
        SolidCells unit = *solid_;
        for (std::size_t b = 0; b < unit.blocks().size(); ++b) unit.set_velocity(b, {0.0, 0.0});
        unit.set_velocity(block, {k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0});
        Velocity d(*grid_);
        unit.fill(d);
        divergence(*grid_, d, 1.0, source_);
        Field2D phi = previous ? previous->pressure[k] : Field2D(*grid_);
        poisson_->solve(source_, phi, poisson_residual_floor(d, 1.0));
        halo_->exchange(phi);
        bc_->apply_pressure(phi);
        Velocity v(*grid_);
        subtract_pressure_gradient(*grid_, *bc_, phi, 1.0, v);
        halo_->exchange(v);
        r.velocity[k] = std::move(v);
        r.pressure[k] = std::move(phi);
    }
    return r;
}

namespace {
// The response's relative residual, against the projection's: its added mass and the correction it makes to the flow
// scale a change of the body's velocity within one step, and the next step's projection takes out what a looser
// solve leaves. 1e-4 by default: 2 PCG iterations where 1e-8 took 4 (the free fall's step 54 against 66 ms).
constexpr double kResponseLooser = 1e4;
}  // namespace

FlowSolver::BodyResponse FlowSolver::cut_response(const std::vector<Velocity>& shut_velocity) {
    if (!cut_.cells) throw std::logic_error("FlowSolver::cut_response: no pressure boundary is set");
    BodyResponse r;
    const Field2D &au = *cut_.aperture_u, &av = *cut_.aperture_v;
    for (const Velocity& U : shut_velocity) {
        // The flux through the shut parts alone: the fluid at rest, the surfaces moving at U.
        Velocity flux(*grid_);
        for (int j = 0; j < grid_->ny(); ++j)
            for (int i = 0; i <= grid_->nx(); ++i) flux.u(i, j) = (1.0 - au(i, j)) * U.u(i, j);
        for (int j = 0; j <= grid_->ny(); ++j)
            for (int i = 0; i < grid_->nx(); ++i) flux.v(i, j) = (1.0 - av(i, j)) * U.v(i, j);
        divergence(*grid_, flux, 1.0, source_);
        Field2D phi(*grid_);
        poisson_->solve(source_, phi, poisson_residual_floor(flux, 1.0),
                        std::min(1e-2, kResponseLooser * config_.poisson_tolerance));
        halo_->exchange(phi);
        bc_->apply_pressure(phi);
        Velocity v(*grid_);
        subtract_pressure_gradient(*grid_, *bc_, phi, 1.0, v, cut_.aperture_u, cut_.aperture_v);
        halo_->exchange(v);
        r.velocity.push_back(std::move(v));
        r.pressure.push_back(std::move(phi));
    }
    return r;
}

void FlowSolver::add_body_response(const BodyResponse& r, const std::vector<double>& change, double dt) {
    for (int j = -kGhost; j < grid_->ny() + kGhost; ++j)
        for (int i = -kGhost; i < grid_->nx() + kGhost; ++i) {
            for (std::size_t k = 0; k < change.size(); ++k) {
                vel_.u(i, j) += change[k] * r.velocity[k].u(i, j);
                vel_.v(i, j) += change[k] * r.velocity[k].v(i, j);
                p_(i, j) += change[k] * r.pressure[k](i, j) / dt;
            }
        }
    halo_->exchange(vel_);
    fill_boundaries(vel_);
    halo_->exchange(p_);
    bc_->apply_pressure(p_);
}

void FlowSolver::refresh_ghosts() {
    halo_->exchange(vel_);
    fill_boundaries(vel_);
    halo_->exchange(p_);
    bc_->apply_pressure(p_);
}

void FlowSolver::restore(long step, double time, double dt_previous, bool implicit_diffusion) {
    step_ = step;
    if (config_.diffusion == DiffusionScheme::automatic) implicit_now_ = implicit_diffusion;
    time_ = time;
    dt_previous_ = dt_previous;
    pressure_history_ = step > 0;  // the checkpoint carries p^{n-1}
}

void FlowSolver::translate_grid(double dx, double dy) {
    std::vector<double> x = grid_->x_axis().lines(), y = grid_->y_axis().lines();
    for (double& l : x) l += dx;
    for (double& l : y) l += dy;
    grid_->set_lines(std::move(x), std::move(y));
}

void FlowSolver::set_grid_motion(const GridMotion& motion) {
    motion_ = motion;
    lines_ = LineVelocities(*grid_, motion_);
    // The boundaries move with their own lines: the inflow and outflow conditions are those of the inertial frame
    // seen from there (at rest when the lines between the moving zone and the boundaries stretch).
    bc_->set_frame_velocity({motion_.axis[0].at(0), motion_.axis[1].at(0)});
}

void FlowSolver::stretch_grid_lines(std::vector<double> x_lines, std::vector<double> y_lines) {
    const std::vector<double> x_before = grid_->x_axis().lines(), y_before = grid_->y_axis().lines();
    if (x_lines == x_before && y_lines == y_before) return;
    // Before the projection the step's u* moves with the lines (its face values from u^n), after it u^{n+1}; the
    // AB2 history (H^n) is kept per unit volume of the current cells.
    const Velocity face = vel_;
    Velocity& target = predicted_ ? star_ : vel_;
    Velocity& history = predicted_ ? rhs_ : rhs_old_;
    for (int axis = 0; axis < 2; ++axis) {
        std::vector<double>& counted = counted_[axis];
        const std::vector<double>& before = axis == 0 ? x_before : y_before;
        const std::vector<double>& after = axis == 0 ? x_lines : y_lines;
        if (after == before) continue;
        counted.resize(before.size(), 0.0);
        grid_->set_lines(axis == 0 ? after : grid_->x_axis().lines(), axis == 0 ? y_before : after);
        move_momentum_with_lines(*grid_, axis, before, counted, face, target, {&history});
        std::fill(counted.begin(), counted.end(), 0.0);
    }
    halo_->exchange(target);
    if (!predicted_) fill_boundaries(vel_);
    inverse_h2_max_ = max_inverse_square_spacing(*grid_);
    // PCG solves the new matrix with the multigrid hierarchy of the last set_up_pressure_hierarchy() (or rebuild).
    poisson_->update_coefficients();
}

void FlowSolver::set_up_pressure_hierarchy(std::vector<double> x_lines, std::vector<double> y_lines) {
    std::vector<double> x = grid_->x_axis().lines(), y = grid_->y_axis().lines();
    grid_->set_lines(std::move(x_lines), std::move(y_lines));
    poisson_->update_matrix();
    grid_->set_lines(std::move(x), std::move(y));
    poisson_->update_coefficients();
}

void FlowSolver::set_grid_lines(std::vector<double> x_lines, std::vector<double> y_lines, bool keep_history) {
    // The same spacings to round-off (a grid that translated, as a restart of a body-fitted run finds it): the
    // lines move, the matrix stays the one the run was solving with, so that the restart continues bit for bit.
    auto same_spacings = [](const Axis& a, const std::vector<double>& lines) {
        if (lines.size() != a.lines().size()) return false;
        for (std::size_t k = 0; k + 1 < lines.size(); ++k)
            if (std::abs((lines[k + 1] - lines[k]) - a.width(static_cast<int>(k))) >
                1e-12 * a.width(static_cast<int>(k)))
                return false;
        return true;
    };
    if (same_spacings(grid_->x_axis(), x_lines) && same_spacings(grid_->y_axis(), y_lines)) {
        grid_->set_lines(std::move(x_lines), std::move(y_lines));
        return;
    }
    grid_->set_lines(std::move(x_lines), std::move(y_lines));
    inverse_h2_max_ = max_inverse_square_spacing(*grid_);
    poisson_->update_matrix();
    if (!keep_history) pressure_history_ = false;
}

void FlowSolver::change_grid_lines(std::vector<double> x_lines, std::vector<double> y_lines) {
    // The fields remapped, each with where it lives along x and y (on the axis's lines or at cell centres).
    struct Remapped {
        Field2D* field;
        bool on_x_lines, on_y_lines;
    };
    std::vector<Remapped> fields = {{&vel_.u, true, false},      {&vel_.v, false, true},     {&rhs_old_.u, true, false},
                                    {&rhs_old_.v, false, true},  {&p_, false, false},        {&p_old_, false, false},
                                    {&eddy_.cell, false, false}, {&eddy_.corner, true, true}};
    for (Field2D* f : remapped_) fields.push_back({f, false, false});
    for (const Remapped& r : fields) halo_->exchange(*r.field);
    std::vector<double> x_before = grid_->x_axis().lines(), y_before = grid_->y_axis().lines();
    const bool x_changed = x_lines != x_before, y_changed = y_lines != y_before;
    if (x_changed) {
        grid_->set_lines(std::move(x_lines), y_before);
        for (const Remapped& r : fields) remap_along_axis(*grid_, 0, x_before, r.on_x_lines, *r.field);
        if (y_changed)
            for (const Remapped& r : fields) halo_->exchange(*r.field);
    }
    if (y_changed) {
        grid_->set_lines(grid_->x_axis().lines(), std::move(y_lines));
        for (const Remapped& r : fields) remap_along_axis(*grid_, 1, y_before, r.on_y_lines, *r.field);
    }
    for (const Remapped& r : fields) halo_->exchange(*r.field);
    inverse_h2_max_ = max_inverse_square_spacing(*grid_);
    poisson_->update_matrix();
    history_dropped_ = true;
    // The domain's boundaries only: the solid cells are those of the old numbering until the carrier sets them
    // again (set_solid_cells() fills the holes' faces then); filling them now would write hole values into the
    // fluid faces the renumbering moved there.
    halo_->exchange(vel_);
    bc_->apply(vel_);
    halo_->exchange(p_);
    bc_->apply_pressure(p_);
}

void FlowSolver::shift_one_cell(int axis, int direction) {
    const Axis& along = axis == 0 ? grid_->x_axis() : grid_->y_axis();
    struct Shifted {
        Field2D* field;
        bool on_lines;  // on the axis's lines (u for x, v for y, the corners), else at cell centres along it
    };
    std::vector<Shifted> fields = {{&vel_.u, axis == 0},     {&vel_.v, axis == 1}, {&rhs_old_.u, axis == 0},
                                   {&rhs_old_.v, axis == 1}, {&p_, false},         {&p_old_, false},
                                   {&eddy_.cell, false},     {&eddy_.corner, true}};
    for (Field2D* f : remapped_) fields.push_back({f, false});
    const bool open_low = grid_->touches(axis == 0 ? Side::left : Side::bottom) && !along.periodic();
    const bool open_high = grid_->touches(axis == 0 ? Side::right : Side::top) && !along.periodic();
    const int n = axis == 0 ? grid_->nx() : grid_->ny(), across = axis == 0 ? grid_->ny() : grid_->nx();
    Field2D old;
    for (const Shifted& s : fields) {
        Field2D& f = *s.field;
        halo_->exchange(f);  // a patch's first or last row comes from its neighbour (or the periodic wrap)
        old = f;
        // The last index along the axis that holds a value of the domain: a boundary face for a field on the lines.
        const int last = s.on_lines ? n : n - 1;
        for (int k = 0; k < n; ++k) {
            int from = k + direction;
            if (open_low && from < 0) from = 0;
            if (open_high && from > last) from = last;
            for (int m = -kGhost; m < across + kGhost; ++m) {
                if (axis == 0)
                    f(k, m) = old(from, m);
                else
                    f(m, k) = old(m, from);
            }
        }
        halo_->exchange(f);
    }
    // Lines: a uniform axis moves by one of its (equal) widths; the lines kept are copied, so the spacings do not
    // change and neither does the Poisson matrix.
    std::vector<double> lines = along.lines();
    const std::size_t count = lines.size();
    if (direction > 0) {
        std::rotate(lines.begin(), lines.begin() + 1, lines.end());
        lines[count - 1] = lines[count - 2] + (lines[count - 2] - lines[count - 3]);
    } else {
        std::rotate(lines.rbegin(), lines.rbegin() + 1, lines.rend());
        lines[0] = lines[1] - (lines[2] - lines[1]);
    }
    set_grid_lines(axis == 0 ? lines : grid_->x_axis().lines(), axis == 1 ? lines : grid_->y_axis().lines(), true);
    refresh_ghosts();
}

std::array<double, 2> FlowSolver::project_after_change() {
    const double before = kinetic_energy(*grid_, vel_, fluid_cells());
    project_start();
    return {before, kinetic_energy(*grid_, vel_, fluid_cells())};
}

double FlowSolver::next_dt() const {
    if (config_.fixed_dt) return *config_.fixed_dt;
    const bool cfl_only = config_.diffusion == DiffusionScheme::implicit_euler ||
                          (config_.diffusion == DiffusionScheme::automatic && eddy_on_);
    const double nu = cfl_only ? 0.0 : config_.viscosity + (eddy_on_ ? eddy_.max : 0.0);
    const auto limits = time_step_limits(*grid_, vel_, nu, config_.cfl, config_.diffusion_number, line_velocities());
    return std::min(limits.stable(), config_.max_dt);
}

// The same limit time_step_limits() finds, without a pass over the velocity: it depends on the grid alone.
double FlowSolver::diffusion_limit() const {
    const double nu = config_.viscosity + (eddy_on_ ? eddy_.max : 0.0);
    return nu > 0.0 ? config_.diffusion_number / (nu * inverse_h2_max_) : std::numeric_limits<double>::infinity();
}

// `auto` goes implicit when the step exceeds the explicit limit and back once it is below 2/3 of it, so that
// a limit hovering near the CFL step does not switch (and drop to a forward-Euler step) every few steps.
bool FlowSolver::implicit_step(double dt) const {
    switch (config_.diffusion) {
        case DiffusionScheme::explicit_ab2:
            return false;
        case DiffusionScheme::implicit_euler:
            return true;
        case DiffusionScheme::automatic:
            break;
    }
    if (!eddy_on_) return false;
    return dt > (implicit_now_ ? 2.0 / 3.0 : 1.0) * diffusion_limit();
}

void FlowSolver::explicit_rhs(const Velocity& vel, Velocity& rhs) const {
    if (cut_.cells && cut_.cut_transport) {
        // The cut fluxes transport the momentum, and a face the surfaces shut whole carries the body's: the fluid's
        // momentum is transported as its mass is (FlowSolver::PressureBoundary::cut_transport). The limiter's ratio
        // still reads the ghost faces' mirrors two faces away, the flow's linear extension through the wall (with U_b
        // there it saw half the gradient of a wall layer's first cell: the face-on square +3.1 % instead of +1.3 %).
        transport_ = vel;  // the domain's boundary faces and the halo, then the cut fluxes on the owned faces
        cut_flux(vel, transport_);
        halo_->exchange(transport_);
        transported_ = vel;
        shut_to_body_velocity(transported_);
        halo_->exchange(transported_);
        convection(*grid_, config_.convection, transported_, bc_->u_first(), bc_->v_first(), rhs, line_velocities(),
                   nullptr, &transport_, &vel);
    } else {
        const Velocity* wall = nullptr;
        if (wall_faces_) {  // set on the owned faces: those shared with the next rank from its halo
            wall_faces_halo_ = *wall_faces_;
            halo_->exchange(wall_faces_halo_);
            wall = &wall_faces_halo_;
        }
        convection(*grid_, config_.convection, vel, bc_->u_first(), bc_->v_first(), rhs, line_velocities(), wall);
    }
    if (implicit_now_)
        add_cross_stress(*grid_, config_.viscosity, eddy_, vel, bc_->u_first(), bc_->v_first(), rhs);
    else if (eddy_on_)
        add_viscous_stress(*grid_, config_.viscosity, eddy_, vel, bc_->u_first(), bc_->v_first(), rhs);
    else
        add_diffusion(*grid_, config_.viscosity, vel, bc_->u_first(), bc_->v_first(), rhs);
}

void FlowSolver::predict_velocity(double dt, double r) {
    const double c_new = dt * (1.0 + 0.5 * r), c_old = -dt * 0.5 * r;
    weight_new_ = 1.0 + 0.5 * r;
    weight_old_ = -0.5 * r;
    const double fx = dt * config_.body_force[0], fy = dt * config_.body_force[1];
    const int nx = grid_->nx(), ny = grid_->ny();
    for (int j = 0; j < ny; ++j)
        for (int i = bc_->u_first(); i < nx; ++i)
            star_.u(i, j) = vel_.u(i, j) + c_new * rhs_.u(i, j) + c_old * rhs_old_.u(i, j) + fx;
    for (int j = bc_->v_first(); j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            star_.v(i, j) = vel_.v(i, j) + c_new * rhs_.v(i, j) + c_old * rhs_old_.v(i, j) + fy;
    subtract_pressure_gradient(*grid_, *bc_, p_, dt, star_);
}

// Starting guess phi = r (p^n - p^{n-1}), i.e. p^{n+1} guessed as the linear extrapolation: it saves a
// third of the PCG iterations against phi = 0 (6 -> 4 on the Re 1000 cavity, docs/performance.md).
// (A direct solve needs no guess: p^n is only kept as p^{n-1}.)
void FlowSolver::pressure_increment_guess(double r) {
    const bool guess = !poisson_->direct();
    for (int j = 0; j < grid_->ny(); ++j)
        for (int i = 0; i < grid_->nx(); ++i) {
            if (guess) phi_(i, j) = pressure_history_ ? r * (p_(i, j) - p_old_(i, j)) : 0.0;
            p_old_(i, j) = p_(i, j);
        }
    pressure_history_ = true;
}

// The round-off level of the Poisson right-hand side V div(u*)/dt: div(u*) sums face velocities of size
// |u| / h, so its rounding error is ~eps |u| / h per cell. Asking for a smaller residual would never stop
// when the flow is (nearly) at rest; 1e-14 is ~50 eps.
double FlowSolver::poisson_residual_floor(const Velocity& vel, double dt) const {
    if (poisson_->direct()) return 0.0;  // no iterations to stop
    const auto& X = grid_->lx();
    const auto& Y = grid_->ly();
    double sum = 0.0;
    for (int j = 0; j < grid_->ny(); ++j)
        for (int i = 0; i < grid_->nx(); ++i) {
            const double b = std::abs(vel.u(i, j)) * Y.w(j) + std::abs(vel.v(i, j)) * X.w(i);  // V |u|/h
            sum += b * b;
        }
    MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_DOUBLE, MPI_SUM, grid_->comm());
    return 1e-14 * std::sqrt(sum) / dt;
}

StepStats FlowSolver::advance(double dt) {
    predict(dt);
    return project();
}

double FlowSolver::predict(double dt) {
    pending_ = StepStats{};
    if (dt <= 0.0) dt = next_dt();
    pending_.dt = dt;
    // 0: forward Euler on the first step, and after a topology change: the remapped history of the cells that
    // changed would not sweep their volumes as their lines do (the geometric conservation law).
    double r = dt_previous_ > 0.0 && !history_dropped_ ? dt / dt_previous_ : 0.0;
    history_dropped_ = false;
    // H^{n-1} holds the stress of the last step's scheme: after a switch this step is forward Euler.
    const bool implicit = implicit_step(dt);
    if (implicit != implicit_now_) r = 0.0;
    implicit_now_ = implicit;

    // Lines that stretch: how far the fluxes below sweep each line (stretch_grid_lines() moves the momentum of the
    // rest of the lines' motion).
    if (lines_.stretching())
        for (int axis = 0; axis < 2; ++axis) {
            const AxisMotion& m = motion_.axis[axis];
            std::vector<double>& counted = counted_[axis];
            counted.assign((axis == 0 ? grid_->global_nx() : grid_->global_ny()) + 1, 0.0);
            const double w = (1.0 + 0.5 * r) * m.velocity - 0.5 * r * previous_grid_velocity_[axis];
            for (int k = std::max(m.first, 0); k <= std::min<int>(m.last, counted.size() - 1); ++k) counted[k] = dt * w;
        }
    previous_grid_velocity_ = {motion_.axis[0].velocity, motion_.axis[1].velocity};
    predicted_ = true;

    // Momentum prediction (AB2 with the last pressure gradient), then the boundary faces of u*
    // (prescribed, convective or zero-stress).
    StageTimer::Scope timed(timer_, "momentum");
    explicit_rhs(vel_, rhs_);
    predict_velocity(dt, r);
    bc_->set_outflow(vel_, star_, dt);
    if (implicit_now_) {
        if (!implicit_) {
            implicit_ = std::make_unique<ImplicitDiffusion>(*grid_, *bc_);
            implicit_->set_solid_cells(solid_);
        }
        halo_->exchange(star_);
        fill_boundaries(star_);
        pending_.diffusion_iterations = implicit_->apply(config_.viscosity, eddy_, dt, star_);
        bc_->set_outflow(vel_, star_, dt);  // a zero-stress outflow face copies the corrected interior
        implicit_wall_momentum(star_);
    }
    pressure_increment_guess(r);
    return dt;
}

StepStats FlowSolver::project() {
    StepStats stats = pending_;
    stats.coupling_passes = 1;
    solve_and_correct(stats);
    publish_velocity();
    predicted_ = false;
    std::swap(rhs_, rhs_old_);
    time_ += stats.dt;
    dt_previous_ = stats.dt;
    ++step_;
    return stats;
}

Velocity& FlowSolver::reopen() {
    star_ = vel_;
    return star_;
}

StepStats FlowSolver::reproject() {
    StepStats stats;
    stats.dt = dt_previous_;
    phi_.fill(0.0);  // the first pass's increment is in p already: this pass's is small
    solve_and_correct(stats);
    publish_velocity();
    return stats;
}

void FlowSolver::forget_impulsive_pressure() {
    p_ = p_old_;
    halo_->exchange(p_);
    bc_->apply_pressure(p_);
}

void FlowSolver::solve_and_correct(StepStats& stats) {
    const double dt = stats.dt;
    // 1. Pressure-increment Poisson equation laplacian(phi) = div(u*) / dt.
    {
        StageTimer::Scope timed(timer_, "poisson");
        halo_->exchange(star_);
        if (solid_) solid_->fill(star_);  // the sides' normal velocity: the hole's Neumann condition
        if (cut_.cells) {
            cut_flux(star_, flux_);
            divergence(*grid_, flux_, 1.0 / dt, source_);
        } else
            divergence(*grid_, star_, 1.0 / dt, source_);
        const PoissonStats ps = poisson_->solve(source_, phi_, poisson_residual_floor(star_, dt));
        stats.poisson_iterations = ps.iterations;
        stats.poisson_residual = ps.relative_residual;
    }

    // 2. Projection onto divergence-free fields: u = u* - dt grad phi, p^{n+1/2} = p^{n-1/2} + phi.
    StageTimer::Scope timed(timer_, "correction");
    halo_->exchange(phi_);
    bc_->apply_pressure(phi_);
    subtract_pressure_gradient(*grid_, *bc_, phi_, dt, star_, cut_.aperture_u, cut_.aperture_v);
    for (int j = 0; j < grid_->ny(); ++j)
        for (int i = 0; i < grid_->nx(); ++i) p_(i, j) += phi_(i, j);
    halo_->exchange(p_);
    bc_->apply_pressure(p_);
}

void FlowSolver::publish_velocity() {
    StageTimer::Scope timed(timer_, "correction");
    std::swap(vel_, star_);
    halo_->exchange(vel_);
    fill_boundaries(vel_);
}

}  // namespace chute
