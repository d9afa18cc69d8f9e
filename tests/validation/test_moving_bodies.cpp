// Bodies with prescribed motion, and static planes (docs/validation-targets.md, docs/validation.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>
#include <utility>

#include "body_run.hpp"
#include "case_file.hpp"
#include "diagnostics.hpp"
#include "euler_lagrange.hpp"

using namespace chute;
using namespace chute::validation;

namespace {

// A square of side d = 1 in a 20 d x 20 d box of fluid at rest (slip walls), accelerated from rest with
// a = 1 m/s^2 in `direction`. Grid: 40 cells per side in the window [-0.75, 0.75]^2, growing by 4 % per cell
// to the walls; dt = 0.002 s. nu = 1e-6: the boundary layer (~sqrt(nu t) = 1e-4 d) carries a negligible force.
//
// The added mass is read from the impulse: C_a = -(integral of F dt from 0 to T) / (rho d^2 U(T)), so the
// few-step start-up transient of the explicit forcing-projection coupling (an overshoot that rings for ~10
// steps) integrates out. T = 0.02 s (10 steps, displacement 2e-4 d): "early time". Later the separation at
// the corners adds a growing vortex force (C_a read this way is 1.21 at T = 0.1 s, docs/validation.md).
struct AddedMass {
    double ca_forcing, ca_surface;
};

AddedMass accelerated_square(Vec2 direction, CarrierKind carrier = CarrierKind::immersed) {
    CaseConfig c;
    for (AxisConfig* a : {&c.x, &c.y}) {
        a->spacing = "clustered";
        a->start = -10.0;
        a->end = 10.0;
        a->core = {-0.75, 0.75};
        a->core_cells = 60;
        a->ratio = 1.04;
    }
    for (auto& b : c.boundary) b.type = BoundaryType::slip;
    if (carrier == CarrierKind::body_fitted) {
        // The grid (and its boundaries) moves with the square along x: water at rest enters ahead, leaves behind.
        c.boundary[static_cast<int>(Side::right)].type = BoundaryType::inflow;
        c.boundary[static_cast<int>(Side::right)].velocity = {0.0, 0.0};
        c.boundary[static_cast<int>(Side::left)].type = BoundaryType::outflow;
        c.boundary[static_cast<int>(Side::left)].outflow = OutflowKind::convective;
    }
    c.density = 1000.0;
    c.viscosity = 1e-6;
    c.fixed_dt = 0.002;
    c.poisson_tolerance = 1e-10;
    BodyConfig square;
    square.name = "square";
    square.shape = BodyShape::rectangle;
    square.size = {1.0, 1.0};
    square.motion.type = MotionType::uniform_acceleration;
    direction.normalize();
    square.motion.acceleration = {direction.x(), direction.y()};
    square.carrier = carrier;
    c.bodies = {square};
    BodyRun run(c, MPI_COMM_WORLD);
    const double T = 0.02, a = 1.0;
    run.run_to(T);
    double impulse_forcing = 0.0, impulse_surface = 0.0, t_previous = 0.0;
    for (const auto& h : run.history) {
        impulse_forcing += (h.t - t_previous) * h.f.forcing.dot(direction);
        impulse_surface += (h.t - t_previous) * (h.f.surface.pressure + h.f.surface.viscous).dot(direction);
        t_previous = h.t;
    }
    const double rho_d2_U = c.density * 1.0 * a * T;  // rho d^2 U(T), depth 1
    AddedMass r{-impulse_forcing / rho_d2_U, -impulse_surface / rho_d2_U};
    if (run.solver.grid().rank() == 0)
        std::printf("square accelerated along (%.3f, %.3f): C_a forcing %.4f, surface %.4f (potential flow 1.1885)\n",
                    direction.x(), direction.y(), r.ca_forcing, r.ca_surface);
    return r;
}

}  // namespace

// Potential flow: the added mass of a square of side d is 1.1885 rho d^2 per unit span for translation in
// any direction (Sedov 1965; VALIDATION.md). Tolerance 5 % (the issue's), for both force measures.
TEST(MovingBodies, AddedMassOfSquareAlongFaceNormal) {
    const AddedMass r = accelerated_square({1.0, 0.0});
    EXPECT_NEAR(r.ca_forcing, 1.1885, 0.05 * 1.1885);
    EXPECT_NEAR(r.ca_surface, 1.1885, 0.05 * 1.1885);
}

// The same carried body-fitted (band/): the grid moves with the square, 40 cells across it. Tolerance 3 % (the
// body-fitted issue's). Measured 2026-11-24: C_a 1.1777 (a), 1.2027 (b).
TEST(MovingBodies, AddedMassOfSquareBodyFitted) {
    const AddedMass r = accelerated_square({1.0, 0.0}, CarrierKind::body_fitted);
    EXPECT_NEAR(r.ca_forcing, 1.1885, 0.03 * 1.1885);
    EXPECT_NEAR(r.ca_surface, 1.1885, 0.03 * 1.1885);
}

TEST(MovingBodies, AddedMassOfSquareAlongDiagonal) {
    const AddedMass r = accelerated_square({1.0, 1.0});
    EXPECT_NEAR(r.ca_forcing, 1.1885, 0.05 * 1.1885);
    EXPECT_NEAR(r.ca_surface, 1.1885, 0.05 * 1.1885);
}

namespace {

// Flow along a plane inclined at 30 degrees to the grid (examples/inclined_plane): in the doubly periodic box
// the plane and its images bound an inclined channel of width W = cos 30; a body force f along the plane
// drives the exact Poiseuille flow u_t = f n (W - n) / (2 nu), peak 1 m/s, and no flow may cross the plane.
struct PlaneFlow {
    double net_flux, gross_flux, profile_error;  // relative to u_max L, u_max L, u_max
};

PlaneFlow inclined_channel(int cells_x, int cells_y) {
    const CaseConfig c =
        load_case(std::string(CHUTE_SOURCE_DIR) + "/examples/inclined_plane/case.yaml",
                  {"domain.x.cells=" + std::to_string(cells_x), "domain.y.cells=" + std::to_string(cells_y)});
    BodyRun run(c, MPI_COMM_WORLD);
    run.run_to(c.end_time);

    const double angle = c.bodies[0].angle, W = std::cos(angle), nu = c.viscosity;
    const Vec2 t(std::cos(angle), std::sin(angle)), n(-std::sin(angle), std::cos(angle));
    const double f = Vec2(c.body_force[0], c.body_force[1]).dot(t), u_max = f * W * W / (8 * nu);
    const Body& body = run.carrier.bodies()[0];
    const Grid& g = run.solver.grid();
    const double h = g.x_axis().width(0);
    const auto markers = body.outline().markers(0.5 * h);
    std::vector<Vec2> points;
    for (const Marker& m : markers) points.push_back(m.position);
    const auto su = delta_stencils(g, DeltaKernel::roma3, Staggering::u_face, points);
    const auto sv = delta_stencils(g, DeltaKernel::roma3, Staggering::v_face, points);
    const auto Uat = interpolate_velocity(g, su, sv, run.solver.velocity());
    double net = 0.0, gross = 0.0, length = 0.0;
    for (std::size_t l = 0; l < markers.size(); ++l) {
        const double un = Uat[l].dot(markers[l].normal);
        net += un * markers[l].length;
        gross += std::abs(un) * markers[l].length;
        length += markers[l].length;
    }
    // Profile: distance of each cell centre from the nearest image of the plane, n in [0, W).
    Field2D uc(g), vc(g);
    cell_centred_velocity(g, run.solver.velocity(), uc, vc);
    double profile_error = 0.0;
    for (int j = 0; j < g.ny(); ++j)
        for (int i = 0; i < g.nx(); ++i) {
            const Vec2 x(g.lx().c(i), g.ly().c(j));
            const double d = std::fmod(std::fmod(x.dot(n), W) + W, W);
            if (d < 3 * h || d > W - 3 * h) continue;
            const double exact = f * d * (W - d) / (2 * nu);
            profile_error = std::max(profile_error, std::abs(Vec2(uc(i, j), vc(i, j)).dot(t) - exact));
        }
    MPI_Allreduce(MPI_IN_PLACE, &profile_error, 1, MPI_DOUBLE, MPI_MAX, g.comm());
    const PlaneFlow r{net / (u_max * length), gross / (u_max * length), profile_error / u_max};
    if (g.rank() == 0)
        std::printf(
            "inclined plane (30 deg), %dx%d: net flux %.2e u_max L, gross |u.n| flux %.2e u_max L, "
            "max slip after forcing %.2e u_max, profile error %.3f u_max\n",
            cells_x, cells_y, r.net_flux, r.gross_flux, run.last[0].max_slip / u_max, r.profile_error);
    return r;
}

}  // namespace

// Steady state (6 s = 4 viscous times W^2/nu) at W/h = 14 and 28:
//   - the net flux through the outline, |sum (u . n) ds|, and the flux of |u . n|, below 0.5 % of u_max L
//     (the forcing leaves a slip of ~1e-3 u_max at the markers after the projection);
//   - the along-plane velocity at least 3 cells from the plane converges to the exact profile at first order
//     (observed order >= 0.9): the diffuse interface thickens the plane by about one cell (the channel is
//     narrower by ~1.1 h; docs/validation.md), the first-order error of regularised-delta forcing.
TEST(MovingBodies, NoFlowThroughAnInclinedPlane) {
    const PlaneFlow coarse = inclined_channel(28, 16), fine = inclined_channel(56, 32);
    for (const PlaneFlow& r : {coarse, fine}) {
        EXPECT_LT(std::abs(r.net_flux), 0.005);
        EXPECT_LT(r.gross_flux, 0.005);
    }
    const double order = std::log2(coarse.profile_error / fine.profile_error);
    std::printf("inclined plane: profile error order %.2f\n", order);
    EXPECT_GE(order, 0.9);
    EXPECT_LT(fine.profile_error, 0.1);
}

namespace {

// Galilean pair (issue 15): the same body and flow seen from two frames: a body moving at constant U through
// fluid at rest (prescribed motion), and the body fixed in a uniform stream U. Both runs take the same fixed
// step, so their force samples fall at the same times, and the difference of the two series isolates what
// the moving body's crossing of the grid adds.
struct GalileanPair {
    double moving_mean, fixed_mean;        // force (a) along the motion, mean over the window (N per m of depth)
    double ripple;                         // rms of (moving - fixed) about its mean, over |fixed mean|
    double trend_ripple;                   // rms of the moving force about its linear trend (tools/force_quality.py)
    double slip;                           // moving body: rms marker slip over the window, over U
    double surface_moving, surface_fixed;  // force (b) means, for the record
};

GalileanPair galilean_pair(const CaseConfig& moving, const CaseConfig& fixed, Vec2 direction, double U, double t0,
                           double t1) {
    auto run = [&](const CaseConfig& c) {
        BodyRun r(c, MPI_COMM_WORLD);
        r.run_to(c.end_time, *c.fixed_dt);
        return r.history;
    };
    const std::vector<ForceSample> m = run(moving), f = run(fixed);
    std::vector<double> t, fm, ff, diff;
    double sm = 0.0, sf = 0.0, slip2 = 0.0;
    for (std::size_t k = 0; k < std::min(m.size(), f.size()); ++k) {
        if (m[k].t < t0 || m[k].t > t1) continue;
        t.push_back(m[k].t);
        fm.push_back(m[k].f.forcing.dot(direction));
        ff.push_back(f[k].f.forcing.dot(direction));
        diff.push_back(fm.back() - ff.back());
        sm += m[k].f.surface.total().dot(direction);
        sf += f[k].f.surface.total().dot(direction);
        slip2 += m[k].f.rms_slip * m[k].f.rms_slip;
    }
    const double n = static_cast<double>(t.size());
    auto mean = [&](const std::vector<double>& x) { return std::accumulate(x.begin(), x.end(), 0.0) / n; };
    auto rms_about = [&](const std::vector<double>& x, double a, double b) {  // about a + b (t - t0)
        double s = 0.0;
        for (std::size_t k = 0; k < x.size(); ++k) s += std::pow(x[k] - a - b * (t[k] - t0), 2);
        return std::sqrt(s / n);
    };
    // Linear trend of the moving force by least squares.
    const double tm = mean(t) - t0, xm = mean(fm);
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        sxy += (t[k] - t0 - tm) * (fm[k] - xm);
        sxx += (t[k] - t0 - tm) * (t[k] - t0 - tm);
    }
    const double slope = sxy / sxx;
    GalileanPair r{xm,
                   mean(ff),
                   rms_about(diff, mean(diff), 0.0) / std::abs(mean(ff)),
                   rms_about(fm, xm - slope * tm, slope) / std::abs(xm),
                   std::sqrt(slip2 / n) / U,
                   sm / n,
                   sf / n};
    if (root())
        std::printf(
            "Galilean pair, t = %g-%g s (%d steps): force (a) moving %.5g, fixed %.5g (moving / fixed %.4f); ripple "
            "rms of moving - fixed %.2f %%, of moving about its trend %.2f %%; rms slip %.2f %% of U; force (b) "
            "moving %.5g, fixed %.5g (%.4f)\n",
            t0, t1, static_cast<int>(n), r.moving_mean, r.fixed_mean, r.moving_mean / r.fixed_mean, 100 * r.ripple,
            100 * r.trend_ripple, 100 * r.slip, r.surface_moving, r.surface_fixed, r.surface_moving / r.surface_fixed);
    return r;
}

}  // namespace

// Square cylinder at Re = U d / nu = 100 (as examples/square_cylinder_re100), d = 1, U = 1, 20 cells across
// on a uniform grid (h = 0.05), dt = 0.02 (CFL 0.4), from an impulsive start to t = 12; compared over
// t = 6-12 (the wake is still symmetric: no shedding from the unperturbed start). Moving: the square crosses
// a 30 d x 10 d box of fluid at rest with slip walls, from x = 0 towards -x. Fixed: a 30 d x 10 d box with
// the uniform inflow U on the left, convective outflow on the right, slip sides; the square at the middle.
// The walls ahead of and behind the moving square are the fixed case's inflow and outflow seen from the
// body (normal velocity U, no shear), at 12-18 d over the window against 15 d; the test measures whatever
// these frame differences add along with the grid's.
//   - mean drag (a): moving / fixed within 1 % (the issue's target: a Galilean-invariant method gives the
//     same force in both frames; the fixed square's drag is the reference);
//   - ripple: rms of (moving - fixed) below 1 % of the mean drag (the issue's target for the force ripple;
//     the difference removes the common start-up transient and leaves the cell-crossing ripple at U/h).
TEST(MovingBodies, GalileanPairSquareRe100) {
    const std::string common = R"(
fluid: {density: 1.0, viscosity: 0.01}
numerics: {convection: central, dt: 0.02}
time: {end: 12.0}
)";
    const CaseConfig moving = parse_case_text(common + R"(
domain:
  x: {start: -24.0, end: 6.0, cells: 600}
  y: {start: -5.0, end: 5.0, cells: 200}
boundaries: {left: {type: slip}, right: {type: slip}, bottom: {type: slip}, top: {type: slip}}
bodies:
  square:
    shape: rectangle
    centre: [0.0, 0.0]
    size: [1.0, 1.0]
    motion: {type: constant_velocity, velocity: [-1.0, 0.0]}
)");
    const CaseConfig fixed = parse_case_text(common + R"(
domain:
  x: {start: -15.0, end: 15.0, cells: 600}
  y: {start: -5.0, end: 5.0, cells: 200}
initial: {velocity: [1.0, 0.0]}
boundaries:
  left: {type: inflow, velocity: [1.0, 0.0]}
  right: {type: outflow}
  bottom: {type: slip}
  top: {type: slip}
bodies:
  square: {shape: rectangle, centre: [0.0, 0.0], size: [1.0, 1.0]}
)");
    // The fluid passes both squares along +x: the drag points along +x in both frames.
    const GalileanPair r = galilean_pair(moving, fixed, Vec2(1.0, 0.0), 1.0, 6.0, 12.0);
    EXPECT_NEAR(r.moving_mean / r.fixed_mean, 1.0, 0.01);
    EXPECT_LT(r.ripple, 0.01);
}

// The study's block (examples/free_fall_block: 0.3 m square, water, k-epsilon with wall functions, van Leer,
// 20 cells across) at its terminal speed U = 2.32 m/s (the free fall's mean speed over t = 2-4 s is
// 2.31-2.32 m/s, docs/validation.md, Cell-crossing ripple), from an impulsive start to t = 2 s, compared over t = 1-2 s
// (7-15 sides of travel), dt = 1.5 ms (the free fall's step at that speed; the adaptive step does not see a prescribed
// body's speed in fluid at rest). Moving: the example's box (3 m x 11.5 m, slip sides, walls at the ends), the block
// falling from y = 0. Fixed: the same grid across, 11.5 m along the stream (inflow U 4.5 m below the block,
// convective outflow 7 m above), the block fixed at y = 0. Ambient turbulence as in the example: in the
// moving frame it decays as the block travels, in the fixed one the inflow keeps it.
// Targets as for the square: mean drag (a) moving / fixed within 1 %, ripple of (moving - fixed) rms < 1 %.
// Known failure (tests.cmake): the ripple passes (0.91 %), the means differ by 5.1 %: the block held in the stream
// leaks through the slip the projection leaves and its drag follows that slip; with 8 forcing and projection passes
// per step (numerics.ibm.projection_passes) the means agree (1.0065) and the ripple fails (1.79 %)
// (docs/validation.md, "The fixed block's drag follows its slip").
namespace {

// The study block of `c` made to fall at U through still water, and the same block held (motion fixed) in the stream
// U entering through the bottom; the caller sets what else the held case changes.
std::pair<CaseConfig, CaseConfig> moving_and_held(CaseConfig c, double U) {
    BodyConfig& block = c.bodies.at(0);
    block.motion = MotionConfig{};
    block.motion.type = MotionType::constant_velocity;
    block.motion.velocity = {0.0, -U};
    block.density = 0.0;
    CaseConfig fixed = c;
    fixed.bodies.at(0).motion = MotionConfig{};
    fixed.initial_velocity = {0.0, U};
    fixed.boundary[static_cast<int>(Side::bottom)] = {.type = BoundaryType::inflow, .velocity = {0.0, U}};
    return {c, fixed};
}

}  // namespace

TEST(MovingBodies, GalileanPairStudyBlockAtTerminalSpeed) {
    const double U = 2.32;
    auto [moving, fixed] =
        moving_and_held(load_case(kExamples + "free_fall_block/case.yaml", {"time.end=2.0", "numerics.dt=0.0015"}), U);
    fixed.y.start = -4.5;
    fixed.y.end = 7.0;
    fixed.boundary[static_cast<int>(Side::top)] = {.type = BoundaryType::outflow};
    const GalileanPair r = galilean_pair(moving, fixed, Vec2(0.0, 1.0), U, 1.0, 2.0);
    EXPECT_NEAR(r.moving_mean / r.fixed_mean, 1.0, 0.01);
    EXPECT_LT(r.ripple, 0.01);
}

// The same pair on the sharp interface (the sharp-corners issue: within 1 % on mean drag with no extra projection
// passes, the moving block's ripple under 1 % rms of its mean). Both in the window of
// examples/free_fall_block/window.yaml (150 x 350 cells, 3 m x 5.25 m, the block 7.5 sides above the bottom):
// moving, the block at -U through water at rest, the grid translating with it (`follow: y`: inflow at rest ahead,
// outflow behind, run/following_frame.hpp); fixed, the grid at rest, the block held in the stream U entering
// through the bottom. The pair checks the translating grid's frame velocity in every term (convection, the
// boundaries, the wall functions, the cut pressure problem): the discrete problems are the same up to it. On a grid
// at rest the same moving block reads less drag wherever its faces cross the cells obliquely (docs/validation.md,
// "Sharp interface", ninth step); face-on, as here, the fixed-domain pair was within 2 %.
TEST(MovingBodies, GalileanPairStudyBlockSharpInAWindow) {
    const double U = 2.32;
    const std::vector<std::string> sharp = {"time.end=2.0", "numerics.dt=0.0015", "numerics.ibm.interface=sharp",
                                            "numerics.ibm.sharp_faces=ghost"};
    auto [moving, fixed] = moving_and_held(load_case(kExamples + "free_fall_block/window.yaml", sharp), U);
    fixed.bodies.at(0).follow = {false, false};
    const GalileanPair r = galilean_pair(moving, fixed, Vec2(0.0, 1.0), U, 1.0, 2.0);
    EXPECT_NEAR(r.moving_mean / r.fixed_mean, 1.0, 0.01);
    EXPECT_LT(r.ripple, 0.01);
    EXPECT_LT(r.trend_ripple, 0.01);
}

// Cut momentum's measure (a) on a body crossing the grid (the sharp-corners issue, item 2), in the pair that is exact:
// a 6 x 6 box periodic both ways, the body moving at U = 1 through fluid at rest, and the same body held with the
// fluid starting at U everywhere. With no walls the box's momentum is free in both frames and the two problems are the
// same Galilean transform of each other; what differs is the body crossing the cells. Re = U d / nu = 100, d = 1 at 20
// cells, central convection (a limiter's dissipation follows the velocity relative to the grid: with van Leer the
// diffuse carrier's pair differs by 1-2 %), dt = 6.25 ms, compared over t = 0.75-2 (the start's transient past, 25
// cells of travel). The measure is the momentum the fluid gains (SharpForcing::held_momentum); the set of faces whose
// centres are inside, taken at the step's end, read the moving circle 15 % under the held one and the square 1 %
// (docs/validation.md, "Sharp interface", fifteenth step). Target as for the other pairs: moving / fixed within 1 %.
// The force's ripple as the body crosses the cells (rms of moving - fixed about its mean, about 7 % of the drag) is
// printed, not held to the 1 % target: it is what is left of item 2.
namespace {

void expect_periodic_galilean_pair(const std::string& shape) {
    const std::string common = R"(
domain:
  x: {start: -3.0, end: 3.0, cells: 120}
  y: {start: -3.0, end: 3.0, cells: 120}
fluid: {density: 1.0, viscosity: 0.01}
boundaries: {left: {type: periodic}, right: {type: periodic}, bottom: {type: periodic}, top: {type: periodic}}
numerics:
  convection: central
  dt: 0.00625
  ibm: {interface: sharp, sharp_faces: ghost, cut_momentum: true}
time: {end: 2.0}
)";
    const CaseConfig moving = parse_case_text(common + "bodies:\n  block:\n    " + shape +
                                              "\n    motion: {type: constant_velocity, velocity: [0.0, -1.0]}\n");
    const CaseConfig fixed =
        parse_case_text(common + "initial: {velocity: [0.0, 1.0]}\nbodies:\n  block:\n    " + shape + "\n");
    // The fluid passes both bodies along +y: the drag points along +y in both frames.
    const GalileanPair r = galilean_pair(moving, fixed, Vec2(0.0, 1.0), 1.0, 0.75, 2.0);
    EXPECT_NEAR(r.moving_mean / r.fixed_mean, 1.0, 0.01);
}

}  // namespace

TEST(MovingBodies, GalileanPairSharpCutMomentumCircle) {
    expect_periodic_galilean_pair("shape: circle\n    centre: [0.0, 0.0]\n    diameter: 1.0");
}

TEST(MovingBodies, GalileanPairSharpCutMomentumSquare) {
    expect_periodic_galilean_pair("shape: rectangle\n    centre: [0.0, 0.0]\n    size: [1.0, 1.0]");
}
