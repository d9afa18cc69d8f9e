// Taylor-Green vortex on the periodic square [-pi, pi]^2 (exact solution in docs/validation-targets.md):
//   u = V0 cos x sin y e^{-2 nu t},  v = -V0 sin x cos y e^{-2 nu t}
// The scheme is second order in space (central convection, MAC grid) and time (AB2 + projection).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flow_solver.hpp"
#include "print_on_rank0.hpp"

using namespace chute;

namespace {

CaseConfig taylor_green_case(int n, double nu) {
    CaseConfig c;
    const double pi = std::numbers::pi;
    c.x = AxisConfig{-pi, pi, n, "uniform", 2.0, 1.05, {}};
    c.y = c.x;
    for (auto& b : c.boundary) b.type = BoundaryType::periodic;
    c.viscosity = nu;
    c.initial = InitialCondition::taylor_green;
    c.taylor_green_amplitude = 1.0;
    c.convection = ConvectionScheme::central;
    c.poisson_tolerance = 1e-12;
    return c;
}

// Max-norm error of u and v against the exact solution at the solver's current time.
double velocity_error(const FlowSolver& s, double nu) {
    const auto& X = s.grid().lx();
    const auto& Y = s.grid().ly();
    const double decay = std::exp(-2.0 * nu * s.time());
    double err = 0.0;
    for (int j = 0; j < s.grid().ny(); ++j)
        for (int i = 0; i < s.grid().nx(); ++i) {
            err = std::max(err, std::abs(s.velocity().u(i, j) - std::cos(X.f(i)) * std::sin(Y.c(j)) * decay));
            err = std::max(err, std::abs(s.velocity().v(i, j) + std::sin(X.c(i)) * std::cos(Y.f(j)) * decay));
        }
    MPI_Allreduce(MPI_IN_PLACE, &err, 1, MPI_DOUBLE, MPI_MAX, s.grid().comm());
    return err;
}

double run(int n, double dt, double t_end, double nu) {
    FlowSolver solver(taylor_green_case(n, nu), MPI_COMM_WORLD);
    const long steps = std::lround(t_end / dt);
    for (long k = 0; k < steps; ++k) solver.advance(dt);
    return velocity_error(solver, nu);
}

}  // namespace

// Spatial order: dt = 1e-3 fixed, small enough that the time error (~1e-8) is negligible next to the
// spatial one (~1e-4); grids 16, 32, 64. VALIDATION.md asks for an observed order >= 1.9.
TEST(TaylorGreen, SecondOrderInSpace) {
    const double nu = 0.1, t_end = 0.5, dt = 1e-3;
    const double e16 = run(16, dt, t_end, nu), e32 = run(32, dt, t_end, nu), e64 = run(64, dt, t_end, nu);
    const double p1 = std::log2(e16 / e32), p2 = std::log2(e32 / e64);
    print_on_rank0("TGV space: errors %.3e %.3e %.3e, orders %.3f %.3f\n", e16, e32, e64, p1, p2);
    EXPECT_GE(p1, 1.9);
    EXPECT_GE(p2, 1.9);
}

// Temporal order: grid fixed (64^2), dt halved three times; the spatial error is removed by
// differencing successive runs (Richardson: e(dt) - e(dt/2) ~ C dt^p).
TEST(TaylorGreen, SecondOrderInTime) {
    const double nu = 0.1, t_end = 0.4;
    const int n = 64;
    FlowSolver a(taylor_green_case(n, nu), MPI_COMM_WORLD), b(taylor_green_case(n, nu), MPI_COMM_WORLD),
        c(taylor_green_case(n, nu), MPI_COMM_WORLD), d(taylor_green_case(n, nu), MPI_COMM_WORLD);
    const double dt0 = 0.01;  // below the AB2 diffusion limit 0.25 h^2 / (2 nu) = 0.012
    auto advance_to = [&](FlowSolver& s, double dt) {
        const long steps = std::lround(t_end / dt);
        for (long k = 0; k < steps; ++k) s.advance(dt);
    };
    advance_to(a, dt0);
    advance_to(b, dt0 / 2);
    advance_to(c, dt0 / 4);
    advance_to(d, dt0 / 8);
    auto diff = [&](const FlowSolver& s1, const FlowSolver& s2) {
        double m = 0.0;
        for (int j = 0; j < s1.grid().ny(); ++j)
            for (int i = 0; i < s1.grid().nx(); ++i) {
                m = std::max(m, std::abs(s1.velocity().u(i, j) - s2.velocity().u(i, j)));
                m = std::max(m, std::abs(s1.velocity().v(i, j) - s2.velocity().v(i, j)));
            }
        MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_MAX, s1.grid().comm());
        return m;
    };
    const double d1 = diff(a, b), d2 = diff(b, c), d3 = diff(c, d);
    const double p1 = std::log2(d1 / d2), p2 = std::log2(d2 / d3);
    print_on_rank0("TGV time: differences %.3e %.3e %.3e, orders %.3f %.3f\n", d1, d2, d3, p1, p2);
    EXPECT_GE(p1, 1.9);
    EXPECT_GE(p2, 1.9);
}

// The pressure of the step t^n -> t^{n+1} solves laplacian(p) = div(u*)/dt with u* from the AB2 update
// centred at t^{n+1/2}: it approximates p(t^{n+1/2}) (what a body force computed from it must be paired
// with). Measured against p(t - dt/2) it is second order in space: orders >= 1.9 over 32, 64, 128.
TEST(TaylorGreen, PressureSecondOrderAtHalfStep) {
    const double nu = 0.1, t_end = 0.4, dt = 1e-3;
    double errors[3];
    int k = 0;
    for (int n : {32, 64, 128}) {
        FlowSolver s(taylor_green_case(n, nu), MPI_COMM_WORLD);
        for (long step = 0; step < std::lround(t_end / dt); ++step) s.advance(dt);
        const auto& X = s.grid().lx();
        const auto& Y = s.grid().ly();
        const double decay = std::exp(-4.0 * nu * (s.time() - 0.5 * dt));
        double err = 0.0;
        for (int j = 0; j < s.grid().ny(); ++j)
            for (int i = 0; i < s.grid().nx(); ++i)
                err = std::max(
                    err, std::abs(s.pressure()(i, j) + 0.25 * (std::cos(2 * X.c(i)) + std::cos(2 * Y.c(j))) * decay));
        MPI_Allreduce(MPI_IN_PLACE, &err, 1, MPI_DOUBLE, MPI_MAX, s.grid().comm());
        errors[k++] = err;
    }
    const double p1 = std::log2(errors[0] / errors[1]), p2 = std::log2(errors[1] / errors[2]);
    print_on_rank0("TGV pressure at t - dt/2: errors %.3e %.3e %.3e, orders %.3f %.3f\n", errors[0], errors[1],
                   errors[2], p1, p2);
    EXPECT_GE(p1, 1.9);
    EXPECT_GE(p2, 1.9);
}
