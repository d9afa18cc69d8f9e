// The same case on 1 and on 2 MPI ranks gives the same fields to within the linear-solver tolerance.
// Run under `mpirun -np 2` (ctest entry unit_np2); on one rank the tests are skipped. Rank 0 also
// runs the case alone on MPI_COMM_SELF and compares the gathered fields.
#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>
#include <utility>

#include "body_fitted.hpp"
#include "flow_solver.hpp"
#include "gather.hpp"
#include "model.hpp"
#include "step.hpp"

using namespace chute;

namespace {

int rank() {
    int r = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
}

int world_size() {
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return size;
}

// Max difference of u, v, p between the run on all ranks and the run on rank 0 alone, relative to the
// max speed (for u, v) and to the max |p| (for p). Every rank gets the result.
std::array<double, 2> compare_np(CaseConfig c, int steps, std::array<int, 2> ranks) {
    c.ranks = ranks;
    FlowSolver parallel(c, MPI_COMM_WORLD);
    for (int k = 0; k < steps; ++k) parallel.advance();
    const Grid& g = parallel.grid();
    const auto u = gather_global(g, parallel.velocity().u, 1, 0);
    const auto v = gather_global(g, parallel.velocity().v, 0, 1);
    const auto p = gather_global(g, parallel.pressure());
    std::array<double, 2> diff{0.0, 0.0};
    if (g.rank() == 0) {
        CaseConfig serial_case = c;
        serial_case.ranks = {0, 0};
        FlowSolver serial(serial_case, MPI_COMM_SELF);
        for (int k = 0; k < steps; ++k) serial.advance();
        const auto us = gather_global(serial.grid(), serial.velocity().u, 1, 0);
        const auto vs = gather_global(serial.grid(), serial.velocity().v, 0, 1);
        const auto ps = gather_global(serial.grid(), serial.pressure());
        double umax = 0, pmax = 0, du = 0, dp = 0;
        for (std::size_t k = 0; k < u.size(); ++k)
            umax = std::max(umax, std::abs(us[k])), du = std::max(du, std::abs(u[k] - us[k]));
        for (std::size_t k = 0; k < v.size(); ++k)
            umax = std::max(umax, std::abs(vs[k])), du = std::max(du, std::abs(v[k] - vs[k]));
        for (std::size_t k = 0; k < p.size(); ++k)
            pmax = std::max(pmax, std::abs(ps[k])), dp = std::max(dp, std::abs(p[k] - ps[k]));
        diff = {du / umax, dp / pmax};
        std::printf("np=%d (%dx%d patches) vs np=1 after %d steps: max |du|/|u|max = %.2e, max |dp|/|p|max = %.2e\n",
                    g.size(), g.ranks()[0], g.ranks()[1], steps, diff[0], diff[1]);
    }
    MPI_Bcast(diff.data(), 2, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    return diff;
}

// run(comm, ranks) -> std::array<double, N> on all ranks split {1, 2}, and on rank 0 alone; the second
// (serial) result is broadcast so every rank can compare.
template <class Run>
auto parallel_and_serial(Run run) {
    const auto parallel = run(MPI_COMM_WORLD, std::array<int, 2>{1, 2});
    std::remove_const_t<decltype(parallel)> serial{};
    if (rank() == 0) serial = run(MPI_COMM_SELF, std::array<int, 2>{0, 0});
    MPI_Bcast(serial.data(), static_cast<int>(serial.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
    return std::pair{parallel, serial};
}

// Body 0's force (a) and the pressure and viscous parts of (b) after `steps` steps of `dt`.
std::array<double, 6> forces_after(Model& model, int steps, double dt) {
    std::vector<BodyForces> f;
    for (int k = 0; k < steps; ++k) {
        take_step(model, dt);
        f = measure_forces(model);
    }
    const BodyForces& b = f.at(0);
    return {b.forcing.x(),          b.forcing.y(),         b.surface.pressure.x(),
            b.surface.pressure.y(), b.surface.viscous.x(), b.surface.viscous.y()};
}

// The largest difference between the parallel and the serial forces, relative to the serial drag (a).
double worst_force_difference(const std::array<double, 6>& parallel, const std::array<double, 6>& serial) {
    double worst = 0.0;
    for (int k = 0; k < 6; ++k) worst = std::max(worst, std::abs(parallel[k] - serial[k]) / std::abs(serial[0]));
    return worst;
}

// A channel 8 x 4 from x_start, 16 cells per metre, a uniform stream of 1 m/s from the left between slip walls.
CaseConfig stream_channel(double x_start) {
    CaseConfig c;
    c.x = AxisConfig{x_start, x_start + 8.0, 128, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{-2.0, 2.0, 64, "uniform", 2.0, 1.05, {}};
    c.boundary[0] =
        BoundaryConfig{BoundaryType::inflow, {1.0, 0.0}, InflowProfile::uniform, 0.0, OutflowKind::convective};
    c.boundary[1] = BoundaryConfig{BoundaryType::outflow, {0, 0}, InflowProfile::uniform, 0.0, OutflowKind::convective};
    c.boundary[2].type = c.boundary[3].type = BoundaryType::slip;
    c.initial_velocity = {1.0, 0.0};
    return c;
}

// A square of side 1 at the origin, carried body-fitted.
BodyConfig body_fitted_square() {
    BodyConfig square;
    square.name = "square";
    square.shape = BodyShape::rectangle;
    square.centre = {0.0, 0.0};
    square.size = {1.0, 1.0};
    square.carrier = CarrierKind::body_fitted;
    return square;
}

CaseConfig cavity() {
    CaseConfig c;
    c.x = AxisConfig{0.0, 1.0, 48, "tanh", 1.2, 1.05, {}};
    c.y = AxisConfig{0.0, 1.0, 40, "uniform", 2.0, 1.05, {}};
    for (auto& b : c.boundary) b.type = BoundaryType::wall;
    c.boundary[3].velocity = {1.0, 0.0};
    c.viscosity = 1e-3;
    c.poisson_tolerance = 1e-10;
    return c;
}

// Inflow (parabolic) on the left, zero-stress outflow on the right, walls top and bottom, a uniform
// initial current that the projection must first make consistent with the walls: exercises the
// Dirichlet pressure side and the corrected boundary faces.
CaseConfig channel(OutflowKind outflow) {
    CaseConfig c;
    c.x = AxisConfig{0.0, 3.0, 60, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{0.0, 1.0, 24, "tanh", 1.5, 1.05, {}};
    c.boundary[0] =
        BoundaryConfig{BoundaryType::inflow, {0, 0}, InflowProfile::parabolic, 1.0, OutflowKind::convective};
    c.boundary[1] = BoundaryConfig{BoundaryType::outflow, {0, 0}, InflowProfile::uniform, 0.0, outflow};
    c.boundary[2].type = c.boundary[3].type = BoundaryType::wall;
    c.initial_velocity = {0.5, 0.1};
    c.viscosity = 1e-2;
    c.convection = ConvectionScheme::van_leer;
    c.poisson_tolerance = 1e-10;
    return c;
}

// Periodic in x, slip walls in y, Taylor-Green start: exercises the periodic halo across ranks.
CaseConfig periodic() {
    CaseConfig c;
    const double pi = 3.141592653589793;
    c.x = AxisConfig{-pi, pi, 32, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{-pi, pi, 32, "uniform", 2.0, 1.05, {}};
    for (auto& b : c.boundary) b.type = BoundaryType::periodic;
    c.initial = InitialCondition::taylor_green;
    c.viscosity = 1e-2;
    c.convection = ConvectionScheme::koren;
    c.poisson_tolerance = 1e-10;
    return c;
}

// The linear solver stops at a relative residual of 1e-10; the difference between decompositions is
// round-off amplified by at most the iteration count and the step count, so 1e-7 of the field's scale
// is a bound the solver must meet (a halo or boundary bug gives O(1e-2) or worse).
constexpr double kTolerance = 1e-7;

}  // namespace

TEST(Parallel, CavitySplitInX) {
    if (world_size() < 2) GTEST_SKIP() << "needs 2 ranks";
    const auto d = compare_np(cavity(), 200, {2, 1});
    EXPECT_LT(d[0], kTolerance);
    EXPECT_LT(d[1], kTolerance);
}

TEST(Parallel, CavitySplitInY) {
    if (world_size() < 2) GTEST_SKIP() << "needs 2 ranks";
    const auto d = compare_np(cavity(), 200, {1, 2});
    EXPECT_LT(d[0], kTolerance);
    EXPECT_LT(d[1], kTolerance);
}

TEST(Parallel, ChannelZeroStressOutflow) {
    if (world_size() < 2) GTEST_SKIP() << "needs 2 ranks";
    const auto d = compare_np(channel(OutflowKind::zero_stress), 200, {2, 1});
    EXPECT_LT(d[0], kTolerance);
    EXPECT_LT(d[1], kTolerance);
}

TEST(Parallel, ChannelConvectiveOutflowSplitInY) {
    if (world_size() < 2) GTEST_SKIP() << "needs 2 ranks";
    const auto d = compare_np(channel(OutflowKind::convective), 200, {1, 2});
    EXPECT_LT(d[0], kTolerance);
    EXPECT_LT(d[1], kTolerance);
}

TEST(Parallel, PeriodicKoren) {
    if (world_size() < 2) GTEST_SKIP() << "needs 2 ranks";
    const auto d1 = compare_np(periodic(), 100, {2, 1});
    const auto d2 = compare_np(periodic(), 100, {1, 2});
    EXPECT_LT(std::max(d1[0], d2[0]), kTolerance);
    EXPECT_LT(std::max(d1[1], d2[1]), kTolerance);
}

// Implicit diffusion (core/implicit_diffusion.hpp): the hypre systems of u and v span both patches, with
// wall, inflow and outflow rows, and periodic ones. The step follows the CFL number alone (about 1.5 times
// the explicit diffusion limit in the channels, whose tanh grid has 0.02-wide cells at the walls).
TEST(Parallel, ImplicitDiffusionChannelAndPeriodic) {
    if (world_size() < 2) GTEST_SKIP() << "needs 2 ranks";
    auto implicit = [](CaseConfig c) {
        c.diffusion = DiffusionScheme::implicit_euler;
        return c;
    };
    for (const auto& d :
         {compare_np(implicit(channel(OutflowKind::zero_stress)), 100, {2, 1}),
          compare_np(implicit(channel(OutflowKind::convective)), 100, {1, 2}),
          compare_np(implicit(periodic()), 100, {2, 1}), compare_np(implicit(periodic()), 100, {1, 2})}) {
        EXPECT_LT(d[0], kTolerance);
        EXPECT_LT(d[1], kTolerance);
    }
}

// The same fixed-cylinder case (DFG 2D-1 geometry, D/h = 20, 60 steps) gives the same forces on 1 and 2 ranks:
// the markers' stencils straddle the patch boundary (the split runs through the cylinder), interpolation and
// spreading are summed over ranks. Tolerance 1e-8 relative: the Poisson solves stop at 1e-10.
TEST(Parallel, FixedCylinderForcesMatchOneRank) {
    if (world_size() < 2) GTEST_SKIP() << "needs 2 ranks";
    CaseConfig c;
    c.x = AxisConfig{0.0, 0.8, 160, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{0.0, 0.41, 82, "uniform", 2.0, 1.05, {}};
    c.boundary[0] =
        BoundaryConfig{BoundaryType::inflow, {0, 0}, InflowProfile::parabolic, 0.3, OutflowKind::convective};
    c.boundary[1] =
        BoundaryConfig{BoundaryType::outflow, {0, 0}, InflowProfile::uniform, 0.0, OutflowKind::zero_stress};
    c.viscosity = 1e-3;
    c.density = 1.0;
    c.cfl = 0.5;
    c.poisson_tolerance = 1e-10;
    BodyConfig cyl;
    cyl.name = "cylinder";
    cyl.shape = BodyShape::circle;
    cyl.centre = {0.2, 0.2};
    cyl.diameter = 0.1;
    c.bodies = {cyl};
    auto run = [&](MPI_Comm comm, std::array<int, 2> ranks) {
        CaseConfig cc = c;
        cc.ranks = ranks;
        Model model(cc, comm);
        return forces_after(model, 60, 0.002);
    };
    // Two patches split in y: 82 cells at 41 puts the patch boundary at y = 0.205, through the cylinder.
    const auto [parallel, serial] = parallel_and_serial(run);
    const double worst = worst_force_difference(parallel, serial);
    if (rank() == 0)
        std::printf(
            "fixed cylinder, np=2 (split in y through the cylinder) vs np=1: max force difference %.2e of "
            "the drag\n",
            worst);
    EXPECT_LT(worst, 1e-8);
}

// k-epsilon with wall functions on an immersed square, split in y through the square: the forces (all
// three parts of the surface stress) and k match the single-rank run to the linear-solver tolerance.
TEST(Parallel, KEpsilonSquareMatchesOneRank) {
    if (world_size() < 2) GTEST_SKIP() << "needs 2 ranks";
    CaseConfig c = stream_channel(-2.0);
    c.viscosity = 1e-5;
    c.density = 1.0;
    c.convection = ConvectionScheme::van_leer;
    c.poisson_tolerance = 1e-10;
    c.turbulence.model = TurbulenceModelType::k_epsilon;
    c.turbulence.intensity = 0.02;
    BodyConfig sq;
    sq.name = "square";
    sq.shape = BodyShape::rectangle;
    sq.centre = {0.0, 0.0};
    sq.size = {1.0, 1.0};
    c.bodies = {sq};
    auto run = [&](MPI_Comm comm, std::array<int, 2> ranks) {
        CaseConfig cc = c;
        cc.ranks = ranks;
        Model model(cc, comm);
        const FlowSolver& solver = model.flow();
        const KEpsilon& turbulence = *model.turbulence();
        std::vector<BodyForces> f;
        for (int k = 0; k < 60; ++k) {
            take_step(model, 0.01);
            f = measure_forces(model);
        }
        double kmax = 0.0;
        for (int j = 0; j < solver.grid().ny(); ++j)
            for (int i = 0; i < solver.grid().nx(); ++i) kmax = std::max(kmax, turbulence.k()(i, j));
        MPI_Allreduce(MPI_IN_PLACE, &kmax, 1, MPI_DOUBLE, MPI_MAX, comm);
        const BodyForces& b = f[0];
        return std::array<double, 8>{
            b.forcing.x(),           b.forcing.y(),           b.surface.pressure.x(), b.surface.viscous.x(),
            b.surface.turbulent.x(), b.surface.turbulent.y(), b.surface.pressure.y(), kmax};
    };
    const auto [parallel, serial] = parallel_and_serial(run);
    double worst = 0.0;
    for (int k = 0; k < 7; ++k) worst = std::max(worst, std::abs(parallel[k] - serial[k]) / std::abs(serial[0]));
    const double k_difference = std::abs(parallel[7] - serial[7]) / serial[7];
    if (rank() == 0)
        std::printf(
            "k-epsilon square, np=2 (split in y through the square) vs np=1: max force difference %.2e of "
            "the drag (turbulent x part %.3e N), max k difference %.2e\n",
            worst, serial[4], k_difference);
    EXPECT_LT(worst, 1e-8);
    EXPECT_LT(k_difference, 1e-8);
}

// A body-fitted square (band/) in a channel, split through the square in x and then in y: the hole's faces are
// filled across the patch boundary (mirrors of fluid faces on the other patch) and both force measures summed
// over ranks. The same forces as on one rank to the Poisson tolerance.
TEST(Parallel, BodyFittedSquareMatchesOneRank) {
    if (world_size() < 2) GTEST_SKIP() << "needs 2 ranks";
    CaseConfig c = stream_channel(-4.0);
    c.initial_perturbation = 0.05;
    c.viscosity = 0.01;
    c.density = 1.0;
    c.cfl = 0.5;
    c.poisson_tolerance = 1e-10;
    c.bodies = {body_fitted_square()};
    for (const std::array<int, 2> split : {std::array<int, 2>{2, 1}, std::array<int, 2>{1, 2}}) {
        auto run = [&](MPI_Comm comm, std::array<int, 2> ranks) {
            CaseConfig cc = c;
            cc.ranks = comm == MPI_COMM_SELF ? ranks : split;
            Model model(cc, comm);
            return forces_after(model, 40, 0.01);
        };
        const auto [parallel, serial] = parallel_and_serial(run);
        const double worst = worst_force_difference(parallel, serial);
        if (rank() == 0)
            std::printf(
                "body-fitted square, np=2 split %dx%d through it vs np=1: max force difference %.2e of the drag\n",
                split[0], split[1], worst);
        EXPECT_LT(worst, 1e-8);
    }
}

// The same square free to move along the stream (y and rotation locked, twice the water's density), coupled
// strongly: the grid moves with it, by the same amount on both ranks; forces and the body's motion match.
TEST(Parallel, FreeBodyFittedSquareMatchesOneRank) {
    if (world_size() < 2) GTEST_SKIP() << "needs 2 ranks";
    CaseConfig c = stream_channel(-4.0);
    c.initial_perturbation = 0.05;
    c.viscosity = 0.01;
    c.density = 1.0;
    c.poisson_tolerance = 1e-10;
    BodyConfig square = body_fitted_square();
    square.density = 2.0;
    square.motion.type = MotionType::free;
    square.motion.locked = {false, true, true};
    c.bodies = {square};
    auto run = [&](MPI_Comm comm, std::array<int, 2> ranks) {
        CaseConfig cc = c;
        cc.ranks = comm == MPI_COMM_SELF ? ranks : std::array<int, 2>{2, 1};
        Model model(cc, comm);
        std::array<double, 6> f = forces_after(model, 40, 0.01);
        const BodyState& s = model.carrier().bodies()[0].state();
        f[4] = s.centre.x();  // in place of the viscous force: where the body (and the grid) went
        f[5] = s.velocity.x();
        return f;
    };
    const auto [parallel, serial] = parallel_and_serial(run);
    const double worst = worst_force_difference(parallel, serial);
    if (rank() == 0)
        std::printf(
            "free body-fitted square, np=2 vs np=1: max difference %.2e of the drag (moved %.4f m at %.4f m/s)\n",
            worst, serial[4], serial[5]);
    EXPECT_GT(serial[4], 1e-3);  // it moves
    EXPECT_LT(worst, 1e-8);
}

// The square falling free along y with modifier layers (band/layers.hpp), split across y so that the renumbered
// rigid zone and the remap cross the ranks' boundary: layer changes in 100 steps, forces and motion match.
TEST(Parallel, BodyFittedLayersMatchOneRank) {
    if (world_size() < 2) GTEST_SKIP() << "needs 2 ranks";
    CaseConfig c;
    c.x = AxisConfig{-2.0, 2.0, 16, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{-8.0, 4.0, 0, "clustered", 2.0, 1.2, {}, {-1.0, 1.0}, 8, 0.0, 0.5};
    c.boundary[0].type = c.boundary[1].type = BoundaryType::slip;
    c.boundary[2].type = c.boundary[3].type = BoundaryType::wall;
    c.viscosity = 1e-2;
    c.convection = ConvectionScheme::van_leer;
    c.poisson_tolerance = 1e-10;
    BodyConfig square = body_fitted_square();
    square.layers = true;
    c.contact.distance = 0.1;  // the bed's gap (it does not get there)
    square.density = 2500.0;
    square.motion.type = MotionType::free;
    square.motion.locked = {true, false, true};
    c.bodies = {square};
    auto run = [&](MPI_Comm comm, std::array<int, 2> ranks) {
        CaseConfig cc = c;
        cc.ranks = ranks;
        Model model(cc, comm);
        std::array<double, 6> f = forces_after(model, 100, 0.01);
        const BodyState& s = model.carrier().bodies()[0].state();
        f[4] = s.centre.y();
        f[5] = dynamic_cast<const BodyFitted&>(model.carrier()).layer_changes()[1];
        return f;
    };
    const auto [parallel, serial] = parallel_and_serial(run);
    double worst = 0.0;
    for (int k = 0; k < 4; ++k) worst = std::max(worst, std::abs(parallel[k] - serial[k]) / std::abs(serial[1]));
    if (rank() == 0)
        std::printf("body-fitted layers, np=2 vs np=1: max difference %.2e of the drag; fell %.4f m with %g changes\n",
                    worst, serial[4], serial[5]);
    EXPECT_GE(serial[5], 2.0);
    EXPECT_EQ(parallel[5], serial[5]);
    EXPECT_NEAR(parallel[4], serial[4], 1e-9);
    EXPECT_LT(worst, 1e-8);
}
