// Plane Poiseuille flow on wall-stretched grids (VALIDATION.md: "exact parabola; stretched grids
// included"). Channel of height H = 1 between no-slip walls, u = 4 U y (H - y) / H^2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "steady_state.hpp"

using namespace chute;
using namespace chute::validation;

namespace {

// Periodic in x, driven by the body force f = 8 nu U / H^2 that balances the wall friction of the parabola.
double periodic_channel_error(int ny, double beta) {
    const double nu = 0.1, U = 1.0;
    CaseConfig c;
    c.x = AxisConfig{0.0, 0.5, 4, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{0.0, 1.0, ny, "tanh", beta, 1.05, {}};
    c.boundary[0].type = c.boundary[1].type = BoundaryType::periodic;
    c.boundary[2].type = c.boundary[3].type = BoundaryType::wall;
    c.viscosity = nu;
    c.body_force = {8.0 * nu * U, 0.0};
    c.poisson_tolerance = 1e-12;
    FlowSolver s(c, MPI_COMM_WORLD);
    run_to_steady_state(s, 1e-9, 0.5, 40.0);
    double err = 0.0;
    for (int j = 0; j < s.grid().ny(); ++j) {
        const double y = s.grid().ly().c(j);
        for (int i = 0; i < s.grid().nx(); ++i)
            err = std::max(err, std::abs(s.velocity().u(i, j) - 4 * U * y * (1 - y)));
    }
    MPI_Allreduce(MPI_IN_PLACE, &err, 1, MPI_DOUBLE, MPI_MAX, s.grid().comm());
    return err / U;
}

}  // namespace

// The finite-volume Laplacian on a smoothly stretched grid is second-order accurate (the first-order
// truncation terms cancel for a smooth mapping), so the max error must fall as h^2: observed order >= 1.9
// over 16 -> 32 -> 64 cells with tanh clustering (beta = 1.5, wall cells ~2.3x finer than uniform).
TEST(Poiseuille, StretchedGridSecondOrder) {
    const double e16 = periodic_channel_error(16, 1.5), e32 = periodic_channel_error(32, 1.5),
                 e64 = periodic_channel_error(64, 1.5);
    const double p1 = std::log2(e16 / e32), p2 = std::log2(e32 / e64);
    std::printf("Poiseuille, tanh-stretched: max error / U = %.3e %.3e %.3e, orders %.3f %.3f\n", e16, e32, e64, p1,
                p2);
    EXPECT_GE(p1, 1.9);
    EXPECT_GE(p2, 1.9);
}

// Parabolic inflow, convective outflow, stretched in y, starting from rest: at steady state the profile
// near the outlet (x = 3.5 H) must be the inflow parabola. Re = U H / nu = 20, development length
// ~0.05 Re H = 1 H. Tolerance 1 % of U: the 32-cell stretched grid's own error is 0.27 % (test above),
// the rest is the outflow condition's upstream influence.
TEST(Poiseuille, InflowOutflowChannelKeepsTheParabola) {
    CaseConfig c;
    c.x = AxisConfig{0.0, 4.0, 64, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{0.0, 1.0, 32, "tanh", 1.5, 1.05, {}};
    c.boundary[0] =
        BoundaryConfig{BoundaryType::inflow, {0, 0}, InflowProfile::parabolic, 1.0, OutflowKind::convective};
    c.boundary[1] = BoundaryConfig{BoundaryType::outflow, {0, 0}, InflowProfile::uniform, 0.0, OutflowKind::convective};
    c.boundary[2].type = c.boundary[3].type = BoundaryType::wall;
    c.viscosity = 0.05;
    c.poisson_tolerance = 1e-10;
    FlowSolver s(c, MPI_COMM_WORLD);
    const double rate = run_to_steady_state(s, 1e-6, 0.5, 60.0);
    double err = 0.0, vmax = 0.0;
    const auto& X = s.grid().lx();
    for (int i = 0; i < s.grid().nx(); ++i) {
        if (std::abs(X.f(i) - 3.5) > 1e-12) continue;  // the u-face line x = 3.5
        for (int j = 0; j < s.grid().ny(); ++j) {
            const double y = s.grid().ly().c(j);
            err = std::max(err, std::abs(s.velocity().u(i, j) - 4 * y * (1 - y)));
            vmax = std::max(vmax, std::abs(s.velocity().v(i, j)));
        }
    }
    MPI_Allreduce(MPI_IN_PLACE, &err, 1, MPI_DOUBLE, MPI_MAX, s.grid().comm());
    MPI_Allreduce(MPI_IN_PLACE, &vmax, 1, MPI_DOUBLE, MPI_MAX, s.grid().comm());
    if (s.grid().rank() == 0)
        std::printf(
            "Poiseuille inflow/outflow: max |u - parabola| at x = 3.5: %.3e, max |v| %.3e, steady rate %.1e at t = "
            "%.1f\n",
            err, vmax, rate, s.time());
    EXPECT_LT(rate, 1e-6);
    EXPECT_LT(err, 0.01);
    EXPECT_LT(vmax, 0.01);
}

// Zero-stress outflow (p = 0 on the outlet): at steady state the pressure gradient of the developed
// channel must be the exact one, dp/dx = -8 nu U / H^2 (kinematic pressure), and the outlet flux must
// equal the inflow flux (2/3 U H). Measured between x = 2 H and x = 3 H on the centreline cells.
// Tolerance 1 %: the grid's own error on the profile is 0.27 % (first test), the wall shear that sets
// the gradient carries about twice that.
TEST(Poiseuille, ZeroStressOutflowGivesTheExactPressureGradient) {
    const double nu = 0.05, U = 1.0;
    CaseConfig c;
    c.x = AxisConfig{0.0, 4.0, 64, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{0.0, 1.0, 32, "tanh", 1.5, 1.05, {}};
    c.boundary[0] = BoundaryConfig{BoundaryType::inflow, {0, 0}, InflowProfile::parabolic, U, OutflowKind::convective};
    c.boundary[1] =
        BoundaryConfig{BoundaryType::outflow, {0, 0}, InflowProfile::uniform, 0.0, OutflowKind::zero_stress};
    c.boundary[2].type = c.boundary[3].type = BoundaryType::wall;
    c.viscosity = nu;
    c.poisson_tolerance = 1e-10;
    FlowSolver s(c, MPI_COMM_WORLD);
    const double rate = run_to_steady_state(s, 1e-6, 0.5, 60.0);
    // Pressure on the cell row nearest the centreline at the cell centres nearest x = 2 and x = 3.
    const auto& X = s.grid().lx();
    const auto& Y = s.grid().ly();
    double p2 = 0.0, x2 = 0.0, p3 = 0.0, x3 = 0.0, outflux = 0.0;
    for (int j = 0; j < s.grid().ny(); ++j) {
        if (s.grid().touches(Side::right)) outflux += s.velocity().u(s.grid().nx(), j) * Y.w(j);
        if (!(Y.f(j) <= 0.5 && 0.5 < Y.f(j + 1))) continue;
        for (int i = 0; i < s.grid().nx(); ++i) {
            if (X.f(i) <= 2.0 && 2.0 < X.f(i + 1)) p2 = s.pressure()(i, j), x2 = X.c(i);
            if (X.f(i) <= 3.0 && 3.0 < X.f(i + 1)) p3 = s.pressure()(i, j), x3 = X.c(i);
        }
    }
    double sums[5] = {p2, x2, p3, x3, outflux};
    MPI_Allreduce(MPI_IN_PLACE, sums, 5, MPI_DOUBLE, MPI_SUM, s.grid().comm());
    const double gradient = (sums[2] - sums[0]) / (sums[3] - sums[1]);
    const double exact = -8.0 * nu * U;
    if (s.grid().rank() == 0)
        std::printf(
            "Poiseuille zero-stress outflow: dp/dx = %.5f (exact %.5f, error %.2f %%), outflow flux %.6f "
            "(inflow 2/3), steady rate %.1e at t = %.1f\n",
            gradient, exact, 100 * std::abs(gradient / exact - 1), sums[4], rate, s.time());
    EXPECT_LT(rate, 1e-6);
    EXPECT_NEAR(gradient, exact, 0.01 * std::abs(exact));
    EXPECT_NEAR(sums[4], 2.0 / 3.0, 1e-10);
}
