// Implicit (backward-Euler) momentum diffusion (core/implicit_diffusion.hpp): its two parts add up to the
// explicit stress operator, and a wall-bounded shear mode decays by exactly the backward-Euler factor at a
// step far beyond the explicit limit. Also run on 2 ranks (ctest entry unit_np2).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "boundary_conditions.hpp"
#include "flow_solver.hpp"
#include "halo_exchange.hpp"
#include "implicit_diffusion.hpp"
#include "print_on_rank0.hpp"
#include "viscous_stress.hpp"

using namespace chute;

namespace {

double global_max(const Grid& g, double m) {
    MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_MAX, g.comm());
    return m;
}

// Shear flow between two sides of the given type, periodic along it: u(y) (walls at bottom and top) or,
// with `along_y`, v(x) (walls left and right). Uniform grid, nu = 0.01, no convection (a parallel shear
// flow has none), a fixed step 100 times the explicit diffusion limit.
struct ShearMode {
    CaseConfig c;
    double h, length, dt;
    ShearMode(BoundaryType sides, bool along_y, int n = 32) {
        length = 1.0;
        h = length / n;
        c.x = AxisConfig{0.0, along_y ? length : 0.5, along_y ? n : 8, "uniform", 2.0, 1.05, {}};
        c.y = AxisConfig{0.0, along_y ? 0.5 : length, along_y ? 8 : n, "uniform", 2.0, 1.05, {}};
        for (auto& b : c.boundary) b.type = BoundaryType::periodic;
        for (int s : along_y ? std::array{0, 1} : std::array{2, 3}) c.boundary[s].type = sides;
        c.viscosity = 0.01;
        c.diffusion = DiffusionScheme::implicit_euler;
        c.poisson_tolerance = 1e-12;
        dt = 100.0 * 0.25 * h * h / c.viscosity;
        c.fixed_dt = dt;
    }
};

// Decay factor of one backward-Euler step for the discrete mode: eigenvalue of the 3-point operator with
// mirrored ghosts, -nu (4 / h^2) sin^2(pi h / (2 L)), for sin (odd mirror, walls) and cos (even, slip) alike.
double backward_euler_factor(const ShearMode& m) {
    const double s = std::sin(std::numbers::pi * m.h / (2.0 * m.length));
    return 1.0 / (1.0 + m.dt * m.c.viscosity * 4.0 / (m.h * m.h) * s * s);
}

double decay_error(BoundaryType sides, bool along_y) {
    ShearMode m(sides, along_y);
    FlowSolver solver(m.c, MPI_COMM_WORLD);
    const Grid& g = solver.grid();
    auto shape = [&](double s) {
        const double phase = std::numbers::pi * s / m.length;
        return sides == BoundaryType::wall ? std::sin(phase) : std::cos(phase);
    };
    Velocity& vel = solver.velocity();
    for (int j = -kGhost; j < g.ny() + kGhost; ++j)
        for (int i = -kGhost; i < g.nx() + kGhost; ++i) {
            vel.u(i, j) = along_y ? 0.0 : shape(g.ly().c(j));
            vel.v(i, j) = along_y ? shape(g.lx().c(i)) : 0.0;
        }
    solver.refresh_ghosts();
    const Velocity before = solver.velocity();
    solver.advance();
    const double factor = backward_euler_factor(m);
    double err = 0.0;
    for (int j = 0; j < g.ny(); ++j)
        for (int i = 0; i < g.nx(); ++i) {
            const double a = along_y ? before.v(i, j) : before.u(i, j);
            const double b = along_y ? solver.velocity().v(i, j) : solver.velocity().u(i, j);
            err = std::max(err, std::abs(b - factor * a));
        }
    err = global_max(g, err);
    print_on_rank0(
        "shear mode (%s sides, %s): step %.0fx the explicit limit, factor %.6f, max |u - factor u0| = %.2e\n",
        sides == BoundaryType::wall ? "wall" : "slip", along_y ? "v(x)" : "u(y)",
        m.dt / (0.25 * m.h * m.h / m.c.viscosity), factor, err);
    return err;
}

}  // namespace

// One step at 100 times the explicit limit: the discrete mode must decay by 1 / (1 - dt lambda) to the
// linear solvers' tolerance (PCG relative residual 1e-10): any error in the matrix's wall or slip rows, or
// in the v path (its x-fastest transpose), shows up at O(1e-2).
TEST(ImplicitDiffusion, ShearModeDecaysByTheBackwardEulerFactor) {
    for (BoundaryType sides : {BoundaryType::wall, BoundaryType::slip})
        for (bool along_y : {false, true}) EXPECT_LT(decay_error(sides, along_y), 1e-8);
}

// The implicit part (recovered from one step at a tiny dt, where du = dt L u + O(dt^2)) plus the explicit
// cross terms must equal the full Boussinesq stress of viscous_stress.hpp on a stretched grid with walls,
// inflow and outflow, a smooth non-solenoidal field and a variable eddy viscosity.
TEST(ImplicitDiffusion, PartsSumToTheFullStress) {
    CaseConfig c;
    c.x = AxisConfig{0.0, 2.0, 40, "tanh", 1.5, 1.05, {}};
    c.y = AxisConfig{0.0, 1.0, 24, "geometric", 2.0, 1.04, {}};
    c.boundary[0] =
        BoundaryConfig{BoundaryType::inflow, {1.0, 0.2}, InflowProfile::uniform, 1.0, OutflowKind::convective};
    c.boundary[1] = BoundaryConfig{BoundaryType::outflow, {0, 0}, InflowProfile::uniform, 0.0, OutflowKind::convective};
    c.boundary[2].type = BoundaryType::wall;
    c.boundary[3].type = BoundaryType::slip;
    const double nu = 1e-3;
    Grid g(build_axis(c.x, false), build_axis(c.y, false), MPI_COMM_WORLD);
    HaloExchange halo(g);
    BoundaryConditions bc(g, c.boundary);
    Velocity vel(g);
    EddyViscosity eddy(g);
    for (int j = -kGhost; j < g.ny() + kGhost; ++j)
        for (int i = -kGhost; i < g.nx() + kGhost; ++i) {
            const double x = g.lx().c(i), y = g.ly().c(j);
            vel.u(i, j) = std::sin(2.0 * x) * std::cos(3.0 * y) + y;
            vel.v(i, j) = std::cos(x * y) - 0.5 * x;
            eddy.cell(i, j) = 0.02 * (1.0 + std::sin(x + 2.0 * y) * std::sin(x + 2.0 * y));
            eddy.corner(i, j) = 0.02 * (1.5 + std::cos(3.0 * x - y));  // any positive corner values
        }
    halo.exchange(vel);
    bc.apply(vel);
    Velocity full(g), split(g);
    add_viscous_stress(g, nu, eddy, vel, bc.u_first(), bc.v_first(), full);
    add_cross_stress(g, nu, eddy, vel, bc.u_first(), bc.v_first(), split);
    const double dt = 1e-9;
    Velocity stepped = vel;
    ImplicitDiffusion implicit(g, bc, 1e-14);
    implicit.apply(nu, eddy, dt, stepped);
    double err = 0.0, scale = 0.0;
    for (int j = 0; j < g.ny(); ++j)
        for (int i = bc.u_first(); i < g.nx(); ++i) {
            const double total = split.u(i, j) + (stepped.u(i, j) - vel.u(i, j)) / dt;
            err = std::max(err, std::abs(total - full.u(i, j)));
            scale = std::max(scale, std::abs(full.u(i, j)));
        }
    for (int j = bc.v_first(); j < g.ny(); ++j)
        for (int i = 0; i < g.nx(); ++i) {
            const double total = split.v(i, j) + (stepped.v(i, j) - vel.v(i, j)) / dt;
            err = std::max(err, std::abs(total - full.v(i, j)));
            scale = std::max(scale, std::abs(full.v(i, j)));
        }
    err = global_max(g, err);
    scale = global_max(g, scale);
    print_on_rank0("implicit + cross against the full stress: max difference %.2e of max |stress| %.3e\n", err, scale);
    // du is computed to round-off of u (1e-16) divided by dt (1e-9): 1e-7 absolute, about 1e-6 relative.
    EXPECT_LT(err, 1e-5 * scale);
}

// numerics.diffusion auto: explicit without an eddy viscosity; with one, the step follows the CFL number
// alone, and a step is implicit once it exceeds the explicit diffusion limit, explicit again once it is
// below 2/3 of it (hysteresis), and the flag is what checkpoints carry.
TEST(ImplicitDiffusion, AutoSwitchesAtTheExplicitLimit) {
    CaseConfig c;
    const double L = 2.0 * std::numbers::pi;
    c.x = AxisConfig{0.0, L, 16, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{0.0, L, 16, "uniform", 2.0, 1.05, {}};
    for (auto& b : c.boundary) b.type = BoundaryType::periodic;
    c.initial = InitialCondition::taylor_green;
    c.viscosity = 1e-3;
    c.cfl = 0.3;
    FlowSolver s(c, MPI_COMM_WORLD);
    s.advance();
    EXPECT_FALSE(s.implicit_diffusion()) << "laminar: explicit";
    const double h = L / 16;
    auto set_eddy = [&](double nu_t) {
        EddyViscosity& e = s.eddy_viscosity();
        e.cell.fill(nu_t);
        e.corner.fill(nu_t);
        e.max = nu_t;
    };
    // The explicit limit for nu_e is d / (nu_e 2 / h^2); pick nu_t so that limit = factor * CFL step.
    auto nu_t_for = [&](double factor) {
        const double dt = s.next_dt();
        return c.diffusion_number * h * h / (2.0 * factor * dt) - c.viscosity;
    };
    set_eddy(nu_t_for(0.5));
    const double cfl_step = s.next_dt();
    s.advance();
    EXPECT_TRUE(s.implicit_diffusion()) << "limit at half the CFL step: implicit";
    EXPECT_NEAR(s.previous_dt(), cfl_step, 1e-12) << "the step follows the CFL number";
    set_eddy(nu_t_for(1.2));
    s.advance();
    EXPECT_TRUE(s.implicit_diffusion()) << "step at 1/1.2 of the limit, above 2/3: stays implicit";
    set_eddy(nu_t_for(2.0));
    s.advance();
    EXPECT_FALSE(s.implicit_diffusion()) << "step at half the limit: back to explicit";
}
