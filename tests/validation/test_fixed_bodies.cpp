// Fixed immersed bodies against published benchmarks (docs/validation-targets.md, docs/validation.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "body_run.hpp"
#include "shedding.hpp"

using namespace chute;
using namespace chute::validation;

namespace {

struct Coefficients {
    double cd_forcing, cl_forcing, cd_surface, cl_surface, cd_pressure, cd_viscous, delta_p, slip;
};

// Schäfer & Turek (1996), DFG benchmark 2D-1: the example case with D/h = cells_per_d: uniform in y, and in
// x uniform over [0.05, 0.6] (from 1.5 D upstream to 3.5 D behind the cylinder, past the 0.85 D
// recirculation) growing by 3 % per cell to the inlet and outlet. Run to t = 8 s, coefficients averaged over
// the last 0.5 s. The start-up leaves a slowly decaying oscillation in C_L (period ~2 s): at t = 3 s C_L still
// reads 0.0150 against 0.0117 at t = 8-12 s, while C_D has settled to 2e-4 (docs/validation.md).
CaseConfig dfg_case(const std::string& example, int cells_per_d, std::vector<std::string> settings = {}) {
    settings.push_back("domain.x={start: 0.0, end: 2.2, spacing: clustered, core: [0.05, 0.6], core_cells: " +
                       std::to_string(55 * cells_per_d / 10) + ", ratio: 1.03}");
    settings.push_back("domain.y.cells=" + std::to_string(41 * cells_per_d / 10));
    return load_case(kExamples + example, settings);
}

// The sharp interface (ibm/sharp_forcing.hpp) with its surface-stress probes at 1.5-3.5 cells: its pressure field is
// sharp and extended into the covered cells, so the probes may come nearer than the diffuse interface's reach.
const std::vector<std::string> kSharp{"numerics.ibm.interface=sharp", "numerics.ibm.stress_probes=[1.5, 2.5, 3.5]"};

Coefficients dfg_2d1(int cells_per_d, double t_end, const std::vector<std::string>& settings = {}) {
    const CaseConfig c = dfg_case("schaefer_turek_2d1/case.yaml", cells_per_d, settings);
    BodyRun run(c, MPI_COMM_WORLD);
    run.run_to(t_end);
    const double q = 0.5 * 1.0 * 0.2 * 0.2 * 0.1;  // 0.5 rho U_mean^2 D (depth 1)
    const double t0 = t_end - 0.5, t1 = t_end;
    Coefficients r;
    r.cd_forcing = run.mean(t0, t1, [](const BodyForces& f) { return f.forcing.x(); }) / q;
    r.cl_forcing = run.mean(t0, t1, [](const BodyForces& f) { return f.forcing.y(); }) / q;
    r.cd_surface =
        run.mean(t0, t1, [](const BodyForces& f) { return f.surface.pressure.x() + f.surface.viscous.x(); }) / q;
    r.cl_surface =
        run.mean(t0, t1, [](const BodyForces& f) { return f.surface.pressure.y() + f.surface.viscous.y(); }) / q;
    r.cd_pressure = run.mean(t0, t1, [](const BodyForces& f) { return f.surface.pressure.x(); }) / q;
    r.cd_viscous = run.mean(t0, t1, [](const BodyForces& f) { return f.surface.viscous.x(); }) / q;
    r.slip = run.last[0].max_slip / 0.3;
    // Delta p = p(0.15, 0.2) - p(0.25, 0.2): the wall pressure at the front and back of the cylinder,
    // extrapolated to the surface from the fluid side (inside the kernel's reach the field is smeared).
    const SurfaceStress& s = run.ibm->surface_stress(0);
    auto wall_p = [&](const Vec2& at) {
        std::size_t best = 0;
        for (std::size_t l = 0; l < s.points().size(); ++l)
            if ((s.points()[l] - at).norm() < (s.points()[best] - at).norm()) best = l;
        return s.wall_pressure()[best];
    };
    r.delta_p = wall_p({0.15, 0.2}) - wall_p({0.25, 0.2});
    if (run.solver.grid().rank() == 0)
        std::printf(
            "DFG 2D-1 (%s), D/h = %d: C_D forcing %.4f surface %.4f (pressure %.4f, viscous %.4f); C_L forcing "
            "%.5f surface %.5f; Delta p %.5f; max slip / U_max %.2e\n",
            settings.empty() ? "diffuse" : "sharp", cells_per_d, r.cd_forcing, r.cd_surface, r.cd_pressure,
            r.cd_viscous, r.cl_forcing, r.cl_surface, r.delta_p, r.slip);
    return r;
}

}  // namespace

// D/h = 40 (~60k cells, ~20 s on 2 ranks). Published (Schäfer & Turek 1996; VALIDATION.md): C_D 5.57-5.59
// (reference 5.5795), C_L 0.0104-0.0110, Delta p 0.1175. What each measure is held to, and why:
//   - C_D from the forcing: inside the published band.
//   - Delta p, wall pressures fitted from the fluid side: 2 % (measured 0.09 % high, 0.11763).
//   - C_D from the surface stress: 4 % (measured 2.2 % low: 5.4591 = pressure 3.6097 + viscous 1.8494, probes
//     2.5-4.5 cells with the wall's pressure gradient). The pressure part no longer depends on where it is
//     sampled (3.608-3.616 over probe sets from 2 to 5 cells); the deficit is the viscous part, which follows
//     the outer flow's first-order convergence (1.71, 1.85 at D/h 20, 40; docs/validation.md).
//   - C_L is 0.2 % of C_D (the cylinder sits 0.005 m below the channel's middle). It converges at first order
//     towards the band from above: 0.0127 at D/h = 20, 0.0117 at 40 (docs/validation.md has D/h = 80; the
//     surface-stress C_L is 0.01098 at D/h = 40, in the band). Held
//     to 0.0015 of the reference (measured 0.0010 above it), i.e. an asymmetry error below 0.03 % of C_D.
TEST(FixedBodies, SchaeferTurek2D1) {
    const Coefficients r = dfg_2d1(40, 8.0);
    EXPECT_GE(r.cd_forcing, 5.57);
    EXPECT_LE(r.cd_forcing, 5.59);
    EXPECT_NEAR(r.delta_p, 0.11752, 0.02 * 0.11752);
    EXPECT_NEAR(r.cd_surface, 5.5795, 0.04 * 5.5795);
    EXPECT_NEAR(r.cl_forcing, 0.010619, 0.0015);
    EXPECT_LT(r.slip, 0.01);
}

// Grid convergence (slow): D/h = 20, 40, 80; the numbers go to docs/validation.md.
TEST(FixedBodies, SchaeferTurek2D1Convergence) {
    const Coefficients a = dfg_2d1(20, 8.0), b = dfg_2d1(40, 8.0), c = dfg_2d1(80, 8.0);
    const double order = std::log2(std::abs(a.cd_forcing - b.cd_forcing) / std::abs(b.cd_forcing - c.cd_forcing));
    std::printf("DFG 2D-1 C_D (forcing) observed order %.2f\n", order);
    EXPECT_GE(c.cd_forcing, 5.57);
    EXPECT_LE(c.cd_forcing, 5.59);
    // The surface-stress drag converges towards the reference (its error at least halves from 40 to 80).
    EXPECT_LT(std::abs(c.cd_surface - 5.5795), 0.5 * std::abs(b.cd_surface - 5.5795));
}

// The sharp interface on the same benchmark, D/h = 20 and 40 (about 30 s on 2 ranks); laminar, so the faces beside
// the surface take the quadratic profile (ibm/sharp_forcing.hpp). Published as above. Measured (2026-11-27, means
// over t = 3.5-4; docs/validation.md, "Sharp interface"): (a) 5.5888 and 5.5826, errors 0.17 % and 0.056 % of the
// reference (5.5808 at D/h = 80): inside the band at D/h = 40 without the retraction that tunes the diffuse
// interface, and held there; its error must at least halve from 20 to 40 (first order; measured a third).
// (b) with probes at 1.5-3.5 cells: 5.5216 at D/h = 40, 1.0 % low (the diffuse interface: 2.2 %), its pressure part
// converged (3.629, 3.630 at 40, 80), its viscous part converging at order 1.7: held to 1.5 %. Delta p and C_L as
// the diffuse test. The slip the projection leaves on the forced faces: 0.5 % of U_max at D/h = 40, held to 1 %.
TEST(FixedBodies, SchaeferTurek2D1Sharp) {
    const Coefficients coarse = dfg_2d1(20, 8.0, kSharp), r = dfg_2d1(40, 8.0, kSharp);
    const double reference = 5.5795;
    EXPECT_GE(r.cd_forcing, 5.57);
    EXPECT_LE(r.cd_forcing, 5.59);
    EXPECT_LT(std::abs(r.cd_forcing - reference), 0.5 * std::abs(coarse.cd_forcing - reference));
    EXPECT_NEAR(r.delta_p, 0.11752, 0.02 * 0.11752);
    EXPECT_NEAR(r.cd_surface, reference, 0.015 * reference);
    EXPECT_NEAR(r.cl_forcing, 0.010619, 0.0015);
    EXPECT_LT(r.slip, 0.01);
}

// The sharp interface's grid convergence (slow): D/h = 20, 40, 80; the numbers go to docs/validation.md. The issue
// (sharp corners) asks the surface-stress drag (b) to converge at order 1.5 or better; measured at t = 4 (means over
// 3.5-4): 5.4320, 5.5216, 5.5543, order 1.45 from the differences: a known failure, kept as the record. (a) is held
// inside the band at D/h = 80 and to order 1.5 (measured 1.78).
TEST(FixedBodies, SchaeferTurek2D1SharpConvergence) {
    const Coefficients a = dfg_2d1(20, 8.0, kSharp), b = dfg_2d1(40, 8.0, kSharp), c = dfg_2d1(80, 8.0, kSharp);
    const double order_a = std::log2(std::abs(a.cd_forcing - b.cd_forcing) / std::abs(b.cd_forcing - c.cd_forcing));
    const double order_b = std::log2(std::abs(a.cd_surface - b.cd_surface) / std::abs(b.cd_surface - c.cd_surface));
    if (root()) std::printf("DFG 2D-1 sharp: observed order of C_D (a) %.2f, (b) %.2f\n", order_a, order_b);
    EXPECT_GE(c.cd_forcing, 5.57);
    EXPECT_LE(c.cd_forcing, 5.59);
    EXPECT_GE(order_a, 1.5);
    EXPECT_GE(order_b, 1.5);
}

namespace {

// Schäfer & Turek (1996), DFG benchmark 2D-2 (examples/schaefer_turek_2d2): the 2D-1 grid at D/h = cells_per_d;
// from rest to t = 8 s, statistics of force (a) over t = 6-8 s (6 periods; periodic from t = 5 s).
Shedding dfg_2d2(int cells_per_d, const std::vector<std::string>& settings = {}) {
    BodyRun run(dfg_case("schaefer_turek_2d2/case.yaml", cells_per_d, settings), MPI_COMM_WORLD);
    run.run_to(8.0);
    const double q = 0.5 * 1.0 * 1.0 * 1.0 * 0.1;  // 0.5 rho U_mean^2 D (depth 1)
    const Shedding s = shedding(run, 6.0, q, 0.1 / 1.0);
    if (run.solver.grid().rank() == 0)
        std::printf("DFG 2D-2, D/h = %d: C_D max %.4f, C_L max %.4f, min %.4f (amplitude %.4f), St %.4f\n", cells_per_d,
                    s.cd_max, s.cl_max, s.cl_min, s.cl_amplitude, s.strouhal);
    return s;
}

// Inside the bands of Schäfer & Turek (1996), Table 4: C_D max 3.22-3.24, C_L max 0.99-1.01, St 0.295-0.305, each
// widened by `slack` (a fraction of its edges).
void expect_in_dfg_2d2_bands(const Shedding& s, double slack = 0.0) {
    EXPECT_GE(s.strouhal, (1.0 - slack) * 0.295);
    EXPECT_LE(s.strouhal, (1.0 + slack) * 0.305);
    EXPECT_GE(s.cd_max, (1.0 - slack) * 3.22);
    EXPECT_LE(s.cd_max, (1.0 + slack) * 3.24);
    EXPECT_GE(s.cl_max, (1.0 - slack) * 0.99);
    EXPECT_LE(s.cl_max, (1.0 + slack) * 1.01);
}

}  // namespace

// Unsteady lift on a curved body (the forces issue, item 5). Published (Schäfer & Turek 1996, Table 4): C_D max
// 3.22-3.24, C_L max 0.99-1.01, St 0.295-0.305. D/h = 20 and 40 (~12 min on 2 ranks). Known failure, kept as
// the record (docs/validation.md, DFG 2D-2): at D/h = 40 the lift reads 0.934 (max) / 0.951 (amplitude), 6 %
// low, and C_D max 3.2045; from D/h = 20 (0.825) the lift moves towards the band at about first order.
TEST(FixedBodies, SchaeferTurek2D2) {
    const Shedding coarse = dfg_2d2(20), fine = dfg_2d2(40);
    expect_in_dfg_2d2_bands(fine);
    // Converging: the fine grid's lift is closer to the reference than the coarse one's.
    EXPECT_LT(std::abs(fine.cl_max - 1.0), std::abs(coarse.cl_max - 1.0));
}

// The same on the sharp interface with ghost faces (the carrier that k-epsilon needs, cut pressure problem; the
// sharp-corners issue): at D/h = 40 C_D max, C_L max and St inside the bands, at D/h = 20 within 2 % of them (of the
// band's nearer edge). Known failure, kept as the record (docs/validation.md, "Sharp interface", eighth and tenth
// steps): D/h 40 C_L max 0.9812 (amplitude 0.999), D/h 20 C_D max 3.3134 (+2.3 %). Forcing faces, the laminar
// default, read 0.9166 and 3.0732 (2026-11-28). About 5 minutes on 2 ranks.
TEST(FixedBodies, SchaeferTurek2D2Sharp) {
    std::vector<std::string> ghost = kSharp;
    ghost.push_back("numerics.ibm.sharp_faces=ghost");
    const Shedding coarse = dfg_2d2(20, ghost), fine = dfg_2d2(40, ghost);
    expect_in_dfg_2d2_bands(fine);
    expect_in_dfg_2d2_bands(coarse, 0.02);
}

namespace {

// The square of side 0.3 held in a laminar stream along its diagonal, (-0.92, 0.92) m/s (Re = |U| d / nu = 300), from
// an impulsive start: inflow on the right and bottom, outflow on the left and top. `domain`: its x and y keys;
// `block`: the body's keys beyond shape and size; `faces`: numerics.ibm.sharp_faces.
std::string square_in_diagonal_stream(const std::string& domain, const std::string& block, const std::string& faces,
                                      double end) {
    return "domain:\n" + domain + R"(fluid: {density: 1000.0, viscosity: 1.3e-3}
initial: {velocity: [-0.92, 0.92]}
boundaries:
  left: {type: outflow, kind: convective}
  right: {type: inflow, velocity: [-0.92, 0.92]}
  bottom: {type: inflow, velocity: [-0.92, 0.92]}
  top: {type: outflow, kind: convective}
bodies:
  block: {shape: rectangle, size: [0.3, 0.3])" +
           block + "}\nnumerics: {convection: van_leer, cfl: 0.4, ibm: {interface: sharp, sharp_faces: " + faces +
           "}}\ntime: {end: " + std::to_string(end) + "}\n";
}

// Its drag along the stream, (-1, 1) / sqrt 2, and its force across it, (1, 1) / sqrt 2: means of the forcing (a) over
// t0-t1.
std::pair<double, double> diagonal_stream_forces(const BodyRun& run, double t0, double t1) {
    const Vec2 along = Vec2(-1.0, 1.0) / std::sqrt(2.0), across = Vec2(1.0, 1.0) / std::sqrt(2.0);
    return {run.mean(t0, t1, [&](const BodyForces& f) { return f.forcing.dot(along); }),
            run.mean(t0, t1, [&](const BodyForces& f) { return f.forcing.dot(across); })};
}

}  // namespace

// A sharp square's drag should not depend on where it lies within its cells. The square of side 0.3 (20 cells
// across, h = 0.015) held in a laminar stream along its diagonal, (-0.92, 0.92) m/s, Re = |U| d / nu = 300, on a
// 267 x 233 uniform grid (inflow on the right and bottom, outflow on the left and top), from an impulsive start;
// drag along the stream and lateral force from the forcing (a), means over t = 0.35-0.45 s (1.5-2 sides of
// travel). Aligned (sides on grid lines) it reads the body-fitted band's drag on the same grid within 1 % (842 against
// 837 N/m, 2026-11-28). Moved by fractions of a cell along x and y, it should read the aligned drag within 2 % and no
// lateral force beyond 1 % of it (the flow is symmetric about the diagonal). Measured (2026-11-28): (0.25, 0.75)
// cells -8.6 %, (0.5, 0.5) -2.0 %, (0.75, 0.25) +0.4 %, (0, 0.5) +4.3 % with a lateral force of 2 %: known failure,
// kept as the record of the sharp-corners issue (docs/validation.md, "Sharp interface", tenth step). With k-epsilon
// the same offsets spread from -7 % to +1 %, and a block held in a stream face-on reads +1.1 / -1.8 / -10 % a quarter
// / a half / three quarters of a cell off (fifth step). 16 s on 2 ranks.
TEST(FixedBodies, SharpSquareDragIndependentOfItsPlaceInTheCell) {
    auto forces = [](double ox, double oy, const std::string& carrier) {
        const double h = 0.015;
        const std::string text = square_in_diagonal_stream(
            "  x: {start: -2.01, end: 1.995, cells: 267}\n"
            "  y: {start: -1.0, end: 2.495, cells: 233}\n",
            ", carrier: " + carrier, "ghost", 0.45);
        const CaseConfig c = parse_case_text(
            text, {"bodies.block.centre=[" + std::to_string(ox * h) + ", " + std::to_string(0.8 + oy * h) + "]"});
        BodyRun run(c, MPI_COMM_WORLD);
        run.run_to(0.45);
        const auto [drag, lateral] = diagonal_stream_forces(run, 0.35, 0.45);
        if (root())
            std::printf("square %s, offset (%.2f, %.2f) cells: drag %.1f N/m, lateral %.1f N/m\n", carrier.c_str(), ox,
                        oy, drag, lateral);
        return std::pair{drag, lateral};
    };
    const double fitted = forces(0.0, 0.0, "body_fitted").first;
    const double aligned = forces(0.0, 0.0, "immersed").first;
    EXPECT_NEAR(aligned, fitted, 0.01 * fitted);
    for (const auto& [ox, oy] :
         {std::pair{0.25, 0.75}, std::pair{0.5, 0.5}, std::pair{0.75, 0.25}, std::pair{0.0, 0.5}}) {
        const auto [drag, lateral] = forces(ox, oy, "immersed");
        EXPECT_NEAR(drag, aligned, 0.02 * aligned) << "offset (" << ox << ", " << oy << ")";
        EXPECT_LT(std::abs(lateral), 0.01 * aligned) << "offset (" << ox << ", " << oy << ")";
    }
}

// A square held in a stream along its diagonal, on a grid symmetric about that diagonal (its sides on grid lines, the
// domain reaching 1.05 m from its centre on every side), feels no force across the stream: the discrete problem is
// mirror-symmetric, so the lateral force is round-off, for both kinds of sharp face. (With forcing faces the faces
// lying on its sides were classified inside or outside by the round-off of their distance, differently on each
// side: on this grid -20.6 N/m across against 3982 N/m of drag over the first 0.05 s, 5 % of the drag on the held
// square's bed; ibm/sharp_forcing.hpp.) 0.05 s, about a second.
TEST(FixedBodies, SharpSquareOnALineFeelsNoForceAcrossASymmetricStream) {
    for (const std::string faces : {"forcing", "ghost"}) {
        const std::string text = square_in_diagonal_stream(
            "  x: {start: -1.05, end: 1.05, cells: 140}\n"
            "  y: {start: -0.25, end: 1.85, cells: 140}\n",
            ", centre: [0.0, 0.8]", faces, 0.05);
        BodyRun run(parse_case_text(text), MPI_COMM_WORLD);
        run.run_to(0.05);
        const auto [drag, lateral] = diagonal_stream_forces(run, 0.0, 0.05);
        if (root())
            std::printf("square on the lines, %s faces: drag %.4f N/m, across %.3e N/m\n", faces.c_str(), drag,
                        lateral);
        EXPECT_GT(drag, 0.0) << faces;
        EXPECT_LT(std::abs(lateral), 1e-9 * drag) << faces << " faces";
    }
}

// A sharp body's force should follow its place continuously: moving it by a fiftieth of a cell must not change the
// force by more than the physics does. The bed (docs/validation.md, "Sharp interface", eleventh step): a steady laminar
// flow blocked by a 0.8 x 1.2 m rectangle, its front face across the stream, in a 3 x 2 m box (inflow 1 m/s on the
// right, outflow top and bottom, a wall on the left; Re = 40 on the 0.4 m gaps), h = 0.05 (24 cells across the front,
// 8 across each gap), to t = 10 s (steady: the force's spread over t = 8-10 s is under 0.01 %). Reference: the
// body-fitted band on a 4 times finer grid (240 x 160), whose lines reach the front and back faces at every place used
// here, reads 473.6 + 27.6 o N/m (o: the front face's offset from a grid line of the coarse grid, in coarse cells;
// 473.6 / 480.3 / 487.2 / 494.1 / 501.2 at o = 0 / 0.25 / 0.5 / 0.75 / 1, 2026-11-28). A move of 0.02 cells changes
// it by 0.03 %. The test asks, for each kind of sharp face, that the force changes by under 1 % as the front face
// crosses the place where the faces' classification switches (ghost faces: the tangential faces' centres, o = 0.5;
// forcing faces: the normal faces, o = 0), and that each reads the reference within 5 % (the aligned face reads +4.1 %:
// the coarse grid's own error, as the body-fitted band on it, +2.7 %). Measured (2026-11-28): ghost faces 436.7 at
// o = 0.49 and 560.6 at 0.51 (-10 % and +15 %); forcing faces 449.6 at o = -0.01 and 527.4 at 0.01 (-5 % and +11 %;
// 449.6 before 2026-11-28 noon), the same on 1 and 2 ranks. Known failure, kept as the record of the sharp-corners
// issue. 5 s on 2 ranks.
namespace {

// The blocked channel of the next two tests: its drag (force (a), mean over t = 8-10 s) with the front face o cells off
// a grid line, on ghost or forcing faces, with cut momentum or not.
double blocked_channel_drag(double o, const std::string& faces, bool cut_momentum) {
    const std::string text = R"(
domain:
  x: {start: -1.0, end: 2.0, cells: 60}
  y: {start: -1.0, end: 1.0, cells: 40}
fluid: {density: 1000.0, viscosity: 0.01}
boundaries:
  left: {type: wall}
  right: {type: inflow, velocity: [-1.0, 0.0]}
  bottom: {type: outflow}
  top: {type: outflow}
bodies:
  block: {shape: rectangle, size: [0.8, 1.2], motion: {type: fixed}}
numerics: {convection: van_leer, cfl: 0.4, ibm: {interface: sharp, sharp_faces: )" +
                             faces + (cut_momentum ? ", cut_momentum: true" : "") + R"(}}
time: {end: 10.0}
)";
    const CaseConfig c = parse_case_text(text, {"bodies.block.centre=[" + std::to_string(0.1 + 0.05 * o) + ", 0]"});
    BodyRun run(c, MPI_COMM_WORLD);
    run.run_to(10.0);
    const double drag = -run.mean(8.0, 10.0, [](const BodyForces& f) { return f.forcing.x(); });
    if (root())
        std::printf("blocked channel, %s faces%s, front %.2f cells off a line: %.1f N/m\n", faces.c_str(),
                    cut_momentum ? " with cut momentum" : "", o, drag);
    return drag;
}

// Its reference: the body-fitted band on a 4 times finer grid (below).
double blocked_channel_reference(double o) { return 473.6 + 27.6 * o; }

}  // namespace

TEST(FixedBodies, SharpForceContinuousAsTheSurfaceCrossesFaces) {
    const auto force = [](double o, const std::string& faces) { return blocked_channel_drag(o, faces, false); };
    const auto reference = blocked_channel_reference;
    for (const auto& [faces, before, after] :
         {std::tuple{std::string("ghost"), 0.49, 0.51}, std::tuple{std::string("forcing"), -0.01, 0.01}}) {
        const double a = force(before, faces), b = force(after, faces);
        EXPECT_NEAR(b, a, 0.01 * reference(0.5 * (before + after))) << faces << " faces";
        EXPECT_NEAR(a, reference(before), 0.05 * reference(before)) << faces << " faces, o = " << before;
        EXPECT_NEAR(b, reference(after), 0.05 * reference(after)) << faces << " faces, o = " << after;
    }
}

// Plane Couette flow over an immersed bed at rest (a plane, ghost faces) under a wall moving at 1 m/s, 1 m above the
// domain's floor, periodic along x (0.4 m, 8 x 20 cells, h = 0.05, nu = 1): the steady profile is linear, u = U (y -
// y_b) / (1 - y_b), which the mirror ghost faces and the cut momentum's wall stencils (Shortley-Weller from the middle
// of a cut face's open part) both hold exactly, so the bed's drag (a) is rho nu U / (1 - y_b) per metre, with the bed
// at 0.1, 0.5 and 0.9 of a cell off a grid line (the cut faces' middles on either side of the surface). Steady to 1e-9
// by t = 3 s (the slowest mode decays as exp(-nu pi^2 t / (1 - y_b)^2)); measured (2026-11-28) to 2e-14 without cut
// momentum and 7e-11 with it: both held to 1e-8. It checks that the momentum the wall terms give the fluid is the
// force (a) reads.
TEST(FixedBodies, SharpCutMomentumHoldsCouetteFlowExactly) {
    for (const bool cut_momentum : {false, true})
        for (const double o : {0.1, 0.5, 0.9}) {
            const double bed = 0.2 + 0.05 * o;
            const std::string text = std::string(R"(
domain:
  x: {start: 0.0, end: 0.4, cells: 8}
  y: {start: 0.0, end: 1.0, cells: 20}
fluid: {density: 1.0, viscosity: 1.0}
boundaries:
  left: {type: periodic}
  right: {type: periodic}
  bottom: {type: wall}
  top: {type: wall, velocity: [1.0, 0.0]}
bodies:
  bed: {shape: plane, angle: 0}
numerics: {convection: van_leer, cfl: 0.4, ibm: {interface: sharp, sharp_faces: ghost, cut_momentum: )") +
                                     (cut_momentum ? "true" : "false") + R"(}}
time: {end: 3.0}
)";
            BodyRun run(parse_case_text(text, {"bodies.bed.point=[0.0, " + std::to_string(bed) + "]"}), MPI_COMM_WORLD);
            run.run_to(3.0);
            const double drag = run.mean(2.9, 3.0, [](const BodyForces& f) { return f.forcing.x(); });
            const double exact = 1.0 * 1.0 * 1.0 / (1.0 - bed) * 0.4;
            EXPECT_NEAR(drag, exact, 1e-8 * exact) << "bed " << o << " cells off a line, cut momentum " << cut_momentum;
        }
}

// Plane Poiseuille flow between two immersed planes (ghost faces with cut momentum: two bodies), driven by a body force
// g = 1 along x, periodic along x (0.4 m, 8 x 20 cells, h = 0.05, nu = 1): the bed (solid below) at y_1 and the lid
// (solid above) at y_2, both off the grid lines, as far apart as 12.4 cells or as close as 1.6 (every face of the gap
// then has both walls in its stencil). The steady profile u = g (y - y_1)(y_2 - y) / (2 nu) is a parabola, for which
// the Shortley-Weller stencils are exact, so the faces of the gap hold it at their points (a cut face's: the middle of
// its open part) but for the on-surface tolerance, which moves each wall by 1e-9 of a cell (1e-9 of the peak for a
// gap of 1.6 cells); and the whole body force on the fluid and on the bodies' own faces reaches the bodies: the two
// forces (a) add up to rho g times the domain's area. Each body's share is its wall's shear g (y_2 - y_1) / 2 plus the
// body force on its own area: exact with the wide gap; in the narrow one the two faces of the gap see each other at
// different distances (the Shortley-Weller fluxes between them are not conservative), and 0.7 % of the shares
// moves from one body to the other. Steady by t = 1 s (the slowest mode decays as exp(-nu pi^2 t / (y_2 - y_1)^2));
// measured (2026-11-28): the profile to 3.3e-10 / 2.0e-9 of its peak, the sum to 5e-12, the shares 0.198 / 0.202
// (exact) and 0.1808 / 0.2192 (0.182 / 0.218); held to 1e-8, 1e-8, 1e-8 and 1 %.
TEST(FixedBodies, SharpCutMomentumHoldsPoiseuilleFlowBetweenTwoBodies) {
    for (const auto& [y1, y2] : {std::pair{0.185, 0.805}, std::pair{0.415, 0.495}}) {
        const std::string text = R"(
domain:
  x: {start: 0.0, end: 0.4, cells: 8}
  y: {start: 0.0, end: 1.0, cells: 20}
fluid: {density: 1.0, viscosity: 1.0, body_force: [1.0, 0.0]}
boundaries:
  left: {type: periodic}
  right: {type: periodic}
  bottom: {type: wall}
  top: {type: wall}
bodies:
  bed: {shape: plane, angle: 0}
  lid: {shape: plane, angle: 180}
numerics: {convection: van_leer, cfl: 0.4, ibm: {interface: sharp, sharp_faces: ghost, cut_momentum: true}}
time: {end: 1.0}
)";
        BodyRun run(parse_case_text(text, {"bodies.bed.point=[0.0, " + std::to_string(y1) + "]",
                                           "bodies.lid.point=[0.0, " + std::to_string(y2) + "]"}),
                    MPI_COMM_WORLD);
        run.run_to(1.0);
        const Grid& g = run.solver.grid();
        const double peak = (y2 - y1) * (y2 - y1) / 8.0;
        double error = 0.0;
        for (int j = 0; j < g.ny(); ++j) {
            // A face's value stands for the middle of its open part (SharpForcing: its point).
            const double lo = std::max(g.ly().f(j), y1), hi = std::min(g.ly().f(j + 1), y2);
            if (hi <= lo) continue;
            const double y = 0.5 * (lo + hi);
            for (int i = 0; i < g.nx(); ++i)
                error = std::max(error, std::abs(run.solver.velocity().u(i, j) - 0.5 * (y - y1) * (y2 - y)));
        }
        MPI_Allreduce(MPI_IN_PLACE, &error, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
        const std::vector<BodyForces> forces = measure_forces(run.model);
        const double total = forces.at(0).forcing.x() + forces.at(1).forcing.x();
        if (root())
            std::printf(
                "Poiseuille between planes at %.3f and %.3f: profile error %.2e of its peak, forces %.12f + "
                "%.12f = %.12f (rho g A = 0.4)\n",
                y1, y2, error / peak, forces.at(0).forcing.x(), forces.at(1).forcing.x(), total);
        EXPECT_LT(error, 1e-8 * peak) << y1 << " " << y2;
        EXPECT_NEAR(total, 0.4, 1e-8 * 0.4) << y1 << " " << y2;
        const double shear = 0.5 * (y2 - y1) * 0.4, bed = shear + y1 * 0.4, lid = shear + (1.0 - y2) * 0.4;
        const double share = y2 - y1 > 0.5 ? 1e-8 : 0.01;
        EXPECT_NEAR(forces.at(0).forcing.x(), bed, share * bed) << y1 << " " << y2;
        EXPECT_NEAR(forces.at(1).forcing.x(), lid, share * lid) << y1 << " " << y2;
    }
}

// The same with cut momentum (numerics.ibm.cut_momentum; ghost faces): the faces along the front face keep their own
// momentum on both sides of o = 0.5, their open part's, with the wall where it lies in their viscous stencil. Measured
// (2026-11-28): 505.8 at o = 0.49 and 506.6 at 0.51 (+3.8 % and +3.9 % against the reference; the jump 0.16 %); over
// the cell o = 0 / 0.01 / 0.25 / 0.75 / 0.99: 512.4 / 505.4 / 501.8 / 517.3 / 528.0 (+8.2 % to +3.8 %, against -10 % to
// +15 % without). The test asks what the known failure above asks of the ghost faces: under 1 % across o = 0.5 and
// each within 5 % of the reference. 3 s on 2 ranks.
TEST(FixedBodies, SharpCutMomentumForceContinuousAsTheSurfaceCrossesFaces) {
    const double a = blocked_channel_drag(0.49, "ghost", true), b = blocked_channel_drag(0.51, "ghost", true);
    EXPECT_NEAR(b, a, 0.01 * blocked_channel_reference(0.5));
    EXPECT_NEAR(a, blocked_channel_reference(0.49), 0.05 * blocked_channel_reference(0.49));
    EXPECT_NEAR(b, blocked_channel_reference(0.51), 0.05 * blocked_channel_reference(0.51));
}

// A square held face-on in a laminar stream (side 0.3, 20 cells across, h = 0.015; -1.3 m/s, Re = 300, slip sides 3.5 m
// apart; impulsive start, drag (a) over t = 0.35-0.45 s, 1.5-2 sides of travel) with cut momentum reads the body-fitted
// drag of the aligned square whatever its front face's place in its cell: 0, 1/4, 1/2 and 3/4 of a cell off a line,
// within 2 % (the offsets criterion of issue "Sharp corners"). Measured (2026-11-28): body-fitted 338.1 N/m; cut
// momentum 342.6 / 334.9 / 334.5 / 335.5 (+1.3 / -0.9 / -1.1 / -0.8 %); ghost faces without it 332.4 / 306.6 / 336.0 /
// 334.7 (-1.7 / -9.3 / -0.6 / -1.0 %). Along the diagonal (sharp_square_offsets) cut momentum narrows the spread
// (+1.0 % to -6.6 %, from +4.7 % to -8.2 %) but does not meet it. 10 s on 2 ranks.
TEST(FixedBodies, SharpCutMomentumFaceOnSquareIndependentOfItsPlace) {
    auto drag = [](double ox, const std::string& carrier) {
        const double h = 0.015;
        const std::string text = R"(domain:
  x: {start: -2.01, end: 1.995, cells: 267}
  y: {start: -1.0, end: 2.495, cells: 233}
fluid: {density: 1000.0, viscosity: 1.3e-3}
initial: {velocity: [-1.3, 0.0]}
boundaries:
  left: {type: outflow, kind: convective}
  right: {type: inflow, velocity: [-1.3, 0.0]}
  bottom: {type: slip}
  top: {type: slip}
bodies:
  block: {shape: rectangle, size: [0.3, 0.3], carrier: )" +
                                 carrier +
                                 R"(}
numerics: {convection: van_leer, cfl: 0.4, ibm: {interface: sharp, sharp_faces: ghost, cut_momentum: true}}
time: {end: 0.45}
)";
        const CaseConfig c = parse_case_text(text, {"bodies.block.centre=[" + std::to_string(ox * h) + ", 0.8]"});
        BodyRun run(c, MPI_COMM_WORLD);
        run.run_to(0.45);
        const double d = -run.mean(0.35, 0.45, [](const BodyForces& f) { return f.forcing.x(); });
        if (root()) std::printf("face-on square %s, %.2f cells off a line: drag %.1f N/m\n", carrier.c_str(), ox, d);
        return d;
    };
    const double fitted = drag(0.0, "body_fitted");
    for (const double ox : {0.0, 0.25, 0.5, 0.75}) EXPECT_NEAR(drag(ox, "immersed"), fitted, 0.02 * fitted) << ox;
}
