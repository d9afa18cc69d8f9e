// k-epsilon with wall functions against DNS (VALIDATION.md): the fully developed turbulent channel of
// examples/turbulent_channel, Re_tau 550 (del Alamo & Jimenez 2003) and 950 (Hoyas & Jimenez 2006).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "body_fitted.hpp"
#include "body_run.hpp"
#include "wall_function.hpp"

using namespace chute;
using namespace chute::validation;

namespace {

struct ChannelResult {
    double bulk_plus, friction;  // U_b / u_tau, C_f = tau_w / (rho U_b^2 / 2) = 2 / U_b+^2
};

// u_tau = delta = 1, so U_b+ is the bulk velocity. Steady to 1e-10 relative change of U_b per unit time:
// the driving force fixes tau_w = 1 at the steady state, so U_b+ is what the model decides.
ChannelResult channel(double re_tau, int cells = 20) {
    const CaseConfig c =
        load_case(kExamples + "turbulent_channel/case.yaml",
                  {"fluid.viscosity=" + std::to_string(1.0 / re_tau), "domain.y.cells=" + std::to_string(cells)});
    BodyRun run(c, MPI_COMM_WORLD);
    const Grid& g = run.solver.grid();
    auto bulk = [&] {
        double s[2] = {0.0, 0.0};
        for (int j = 0; j < g.ny(); ++j)
            for (int i = 0; i < g.nx(); ++i)
                s[0] += run.solver.velocity().u(i, j) * g.lx().w(i) * g.ly().w(j), s[1] += g.lx().w(i) * g.ly().w(j);
        MPI_Allreduce(MPI_IN_PLACE, s, 2, MPI_DOUBLE, MPI_SUM, g.comm());
        return s[0] / s[1];
    };
    double previous = bulk(), t_check = 1.0;
    for (;;) {
        run.step();
        if (run.solver.time() >= t_check) {
            const double now = bulk();
            if (std::abs(now - previous) < 1e-10 * now || run.solver.time() > 400.0) break;
            previous = now;
            t_check += 1.0;
        }
    }
    const double ub = bulk();
    return {ub, 2.0 / (ub * ub)};
}

}  // namespace

// Two criteria (docs/validation-targets.md, revised).
// Verification: Chute solves the model it claims to. tools/ke_channel_1d.py, an independent 1D finite-volume
// solve of the same model, constants and wall functions with the same 10 cells per half channel (first cell
// at y+ 27.5 / 47.5), gives U_b+ 19.0965 (Re_tau 550) and 20.4201 (950); held to 0.5 %.
// Validation: standard k-epsilon with standard wall functions against the DNS (del Alamo & Jimenez 2003,
// Hoyas & Jimenez 2006): U_b+ 18.40 (550), 19.83 (950) within 6 %, the model's known error (its constants imply
// a log-law kappa of 0.433 against the wall function's 0.41; grid-converged it reads +5.1 / +4.3 %).
TEST(Turbulence, ChannelBulkVelocity) {
    const ChannelResult r550 = channel(550.0), r950 = channel(950.0);
    if (root())
        std::printf(
            "turbulent channel, 20 cells: Re_tau 550: U_b+ %.4f (1D solve 19.0965, DNS 18.40), C_f %.4e "
            "(5.91e-3); Re_tau 950: U_b+ %.4f (1D solve 20.4201, DNS 19.83), C_f %.4e (5.09e-3)\n",
            r550.bulk_plus, r550.friction, r950.bulk_plus, r950.friction);
    EXPECT_NEAR(r550.bulk_plus, 19.0965, 0.005 * 19.0965);
    EXPECT_NEAR(r950.bulk_plus, 20.4201, 0.005 * 20.4201);
    EXPECT_NEAR(r550.bulk_plus, 18.40, 0.06 * 18.40);
    EXPECT_NEAR(r950.bulk_plus, 19.83, 0.06 * 19.83);
}

// Validation of the friction (revised band): C_f = 2 / U_b+^2 doubles the relative error of U_b+, so the
// model's +5 % in U_b+ is about -9 % in C_f (grid-converged -9.4 / -8.1 %, tools/ke_channel_1d.py); the DNS
// C_f 5.91e-3 (550) and 5.09e-3 (950) within 10 %. Tighter needs another model, not tuning (docs/validation.md).
TEST(Turbulence, ChannelFrictionCoefficient) {
    const ChannelResult r550 = channel(550.0), r950 = channel(950.0);
    if (root()) std::printf("turbulent channel: C_f %.4e (Re_tau 550), %.4e (950)\n", r550.friction, r950.friction);
    EXPECT_NEAR(r550.friction, 5.91e-3, 0.10 * 5.91e-3);
    EXPECT_NEAR(r950.friction, 5.09e-3, 0.10 * 5.09e-3);
}

// The answer does not depend on where the first cell centre sits inside the log layer (y+ 55, 27.5, 18).
TEST(Turbulence, ChannelIndependentOfTheFirstCell) {
    const double u10 = channel(550.0, 10).bulk_plus, u20 = channel(550.0, 20).bulk_plus,
                 u30 = channel(550.0, 30).bulk_plus;
    if (root())
        std::printf("turbulent channel Re_tau 550: U_b+ %.4f (10 cells), %.4f (20), %.4f (30)\n", u10, u20, u30);
    EXPECT_NEAR(u10, u20, 0.01 * u20);
    EXPECT_NEAR(u30, u20, 0.01 * u20);
}

// Square cylinder at Re 22,000 with the body immersed (examples/square_cylinder_re22000: Lyn et al. 1995,
// ERCOFTAC UFR2-02; bands of VALIDATION.md): mean C_D in 1.6-2.2, and, since the model sheds here, St in
// 0.12-0.145. Statistics over t = 50-150 D/U (about 14 periods) after the start-up.
// The same case carried body-fitted (`--set bodies.square.carrier=body_fitted`: the square's sides lie on the
// grid's lines) is SquareCylinderRe22000BodyFitted, with the same bands; measured 2026-11-24: C_D 2.041, C_L
// rms 0.72, St 0.144 against the immersed 1.78, 0.235, 0.140 (the slow test: 2.044, 0.736, 0.1443 in 120 s on
// 2 ranks; docs/validation.md, "Square cylinder, Re 22,000, carried body-fitted").
namespace {

struct SheddingStatistics {
    double cd = 0.0, cd_surface = 0.0, cl_rms = 0.0, st = NAN;
};

// The run's statistics over t = 50-150 D/U.
SheddingStatistics square_cylinder_re22000(const std::vector<std::string>& set) {
    const CaseConfig c = load_case(kExamples + "square_cylinder_re22000/case.yaml", set);
    BodyRun run(c, MPI_COMM_WORLD);
    run.run_to(c.end_time);
    std::vector<double> t, cl;
    double cd = 0.0, cds = 0.0;
    for (const auto& h : run.history)
        if (h.t >= 50.0) {
            t.push_back(h.t);
            cl.push_back(2.0 * h.f.forcing.y());
            cd += 2.0 * h.f.forcing.x();
            cds += 2.0 * h.f.surface.total().x();
        }
    cd /= t.size();
    cds /= t.size();
    double mean_cl = 0.0, rms = 0.0;
    for (double v : cl) mean_cl += v / cl.size();
    for (double v : cl) rms += (v - mean_cl) * (v - mean_cl) / cl.size();
    std::vector<double> up;
    for (std::size_t k = 1; k < t.size(); ++k)
        if (cl[k - 1] < mean_cl && cl[k] >= mean_cl)
            up.push_back(t[k - 1] + (t[k] - t[k - 1]) * (mean_cl - cl[k - 1]) / (cl[k] - cl[k - 1]));
    const double st = up.size() >= 2 ? (up.size() - 1) / (up.back() - up.front()) : NAN;
    if (root())
        std::printf(
            "square cylinder Re 22000, k-epsilon: mean C_D %.4f (forcing), %.4f (surface); C_L rms %.4f; "
            "St %.4f over %zu periods\n",
            cd, cds, std::sqrt(rms), st, up.size() ? up.size() - 1 : 0);
    return {cd, cds, std::sqrt(rms), st};
}

void expect_in_bands(const SheddingStatistics& s) {
    EXPECT_GE(s.cd, 1.6);
    EXPECT_LE(s.cd, 2.2);
    EXPECT_GE(s.st, 0.12);
    EXPECT_LE(s.st, 0.145);
}

}  // namespace

TEST(Turbulence, SquareCylinderRe22000) { expect_in_bands(square_cylinder_re22000({})); }

TEST(Turbulence, SquareCylinderRe22000BodyFitted) {
    expect_in_bands(square_cylinder_re22000({"bodies.square.carrier=body_fitted"}));
}

// The sharp immersed carrier with ghost faces against the body-fitted one on the same grid (the sharp-corners
// issue's criterion: mean C_D within 3 %, St within 2 %, C_L rms within 10 %). The square's sides lie on grid lines,
// so the two discretise the same wall: the ghost faces mirror the first fluid faces, the cells inside leave the
// pressure problem, and the wall law acts through the corners on the sides (ibm/sharp_forcing.hpp,
// turbulence/k_epsilon.cpp); what differs is the k-epsilon wall-function cells at the corners and the inside's
// pressure. Measured 2026-11-27 over t = 15-60: C_D 2.070 / 2.045, C_L rms 0.805 / 0.746, St 0.1446 / 0.1441.
TEST(Turbulence, SquareCylinderRe22000SharpMatchesBodyFitted) {
    const SheddingStatistics sharp =
        square_cylinder_re22000({"numerics.ibm.interface=sharp", "numerics.ibm.sharp_faces=ghost"});
    const SheddingStatistics fitted = square_cylinder_re22000({"bodies.square.carrier=body_fitted"});
    expect_in_bands(sharp);
    EXPECT_NEAR(sharp.cd, fitted.cd, 0.03 * fitted.cd);
    EXPECT_NEAR(sharp.st, fitted.st, 0.02 * fitted.st);
    EXPECT_NEAR(sharp.cl_rms, fitted.cl_rms, 0.10 * fitted.cl_rms);
}

// The same with cut momentum (numerics.ibm.cut_momentum): the wall stencils put the wall law's shear at the sides
// from the faces beside them, where the ghost faces' mirror took it through the eddy viscosity of the corners. Measured
// 2026-11-28 over t = 50-150: C_D (a) 2.0441, (b) 2.0444, C_L rms 0.738, St 0.1446 against the body-fitted 2.0442,
// 0.736, 0.1443 (ghost faces without it: 2.0687, 0.777, 0.1448). Held to the issue's bands (3 %, 10 %, 2 %) and, as
// cut momentum meets them with room, to 1 % on C_D. Slow: 5 minutes on 2 ranks (300 s, 2026-11-28).
TEST(Turbulence, SquareCylinderRe22000CutMomentumMatchesBodyFitted) {
    const SheddingStatistics sharp = square_cylinder_re22000(
        {"numerics.ibm.interface=sharp", "numerics.ibm.sharp_faces=ghost", "numerics.ibm.cut_momentum=true"});
    const SheddingStatistics fitted = square_cylinder_re22000({"bodies.square.carrier=body_fitted"});
    expect_in_bands(sharp);
    EXPECT_NEAR(sharp.cd, fitted.cd, 0.01 * fitted.cd);
    EXPECT_NEAR(sharp.st, fitted.st, 0.02 * fitted.st);
    EXPECT_NEAR(sharp.cl_rms, fitted.cl_rms, 0.10 * fitted.cl_rms);
}

// The same domain without the square: the inflow's k and nu_t only decay (no spurious turbulence from
// the stretched grid, the outflow or the slip sides).
TEST(Turbulence, SquareCylinderDomainWithoutBodyMakesNoTurbulence) {
    const CaseConfig c = load_case(kExamples + "square_cylinder_re22000/case.yaml",
                                   {"bodies={}", "initial.perturbation=0.0", "time.end=20.0"});
    BodyRun run(c, MPI_COMM_WORLD);
    run.run_to(c.end_time);
    const KEpsilon& m = *run.turbulence;
    const double nu_t_in = KEpsilonConstants::c_mu * m.inflow_k() * m.inflow_k() / m.inflow_epsilon();
    double mx[2] = {0.0, 0.0};
    for (int j = 0; j < run.solver.grid().ny(); ++j)
        for (int i = 0; i < run.solver.grid().nx(); ++i)
            mx[0] = std::max(mx[0], m.k()(i, j)), mx[1] = std::max(mx[1], m.eddy_viscosity()(i, j));
    MPI_Allreduce(MPI_IN_PLACE, mx, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    if (root())
        std::printf("empty Lyn domain at t = 20: max k / k_in %.6f, max nu_t / nu_t,in %.6f\n", mx[0] / m.inflow_k(),
                    mx[1] / nu_t_in);
    EXPECT_LE(mx[0], m.inflow_k() * (1.0 + 1e-9));
    EXPECT_LE(mx[1], nu_t_in * (1.0 + 1e-9));
}

// The study's block held in a 2.24 m/s stream with k-epsilon (Re 6.7e5; the grid of examples/free_fall_block/
// window.yaml, 20 cells across, h = 0.015 m) on the sharp interface with cut momentum reads the body-fitted drag
// whatever the place of its front and back in their cells: 0, 1/4, 1/2, 3/4 and 0.99 of a cell off the lines along the
// stream, drag (a) over t = 1.5-2.5 s within 2 % of the body-fitted block's on its lines (the offsets criterion of
// issue "Sharp corners"), and 0.99 within 1 % of 0 (a side reaching a line: the same place one cell on). Measured
// (2026-11-28, docs/validation.md "Sharp interface", fourteenth step): body-fitted 1321.8 N/m; cut momentum +0.15 /
// -1.54 / -1.17 / -0.38 / +0.29 %; before the shut faces carried the body's velocity in the convection, 0.75 and 0.99
// read -2.8 and -5.1 %, and ghost faces without cut momentum +0.3 / +1.4 / +5.1 (shedding) / -9.8 %. Slow: about
// 4 minutes on 2 ranks.
TEST(Turbulence, SharpCutMomentumHeldBlockIndependentOfItsPlace) {
    auto drag = [](double oy, const std::string& carrier) {
        const double h = 0.015;
        const std::string text = R"(domain:
  x: {start: -1.5, end: 1.5, spacing: clustered, core: [-0.75, 0.75], core_cells: 100, ratio: 1.05}
  y: {start: -2.25, end: 3.0, cells: 350}
fluid: {density: 1000.0, viscosity: 1.0e-6}
initial: {velocity: [0.0, 2.24]}
boundaries:
  left: {type: slip}
  right: {type: slip}
  bottom: {type: inflow, velocity: [0.0, 2.24]}
  top: {type: outflow}
bodies:
  block: {shape: rectangle, size: [0.3, 0.3], carrier: )" +
                                 carrier + R"(}
turbulence: {model: k_epsilon, velocity_scale: 2.0, intensity: 0.01, length_scale: 0.01}
numerics: {convection: van_leer, cfl: 0.4, dt: 0.0015, ibm: {interface: sharp, sharp_faces: ghost, cut_momentum: true}}
time: {end: 2.5}
)";
        const CaseConfig c = parse_case_text(text, {"bodies.block.centre=[0.0, " + std::to_string(oy * h) + "]"});
        BodyRun run(c, MPI_COMM_WORLD);
        run.run_to(2.5);
        const double d = run.mean(1.5, 2.5, [](const BodyForces& f) { return f.forcing.y(); });
        if (root()) std::printf("held block %s, %.2f cells off a line: drag %.1f N/m\n", carrier.c_str(), oy, d);
        return d;
    };
    const double fitted = drag(0.0, "body_fitted");
    double on_line = 0.0;
    for (const double oy : {0.0, 0.25, 0.5, 0.75, 0.99}) {
        const double d = drag(oy, "immersed");
        EXPECT_NEAR(d, fitted, 0.02 * fitted) << oy;
        if (oy == 0.0) on_line = d;
        if (oy == 0.99) {
            EXPECT_NEAR(d, on_line, 0.01 * on_line);
        }
    }
}

// The study's block in still water with k-epsilon (examples/free_fall_block, to t = 4 s, 20 cells across):
// it must reach a terminal speed and hold it, inside the experiment's 2.2 +/- 0.2 m/s (Turmel & Locat 2008,
// sec. 4.1: 0.3 m cube in a tank). "Holds": the fall speed over t = 1.5-4 s stays within 2 % of its mean
// (the shed vortices' ripple is about +/-0.5 %). Slow: about 1 minute on 2 ranks.
TEST(Turbulence, StudyBlockFallsAtTheExperimentsSpeed) {
    const CaseConfig c = load_case(kExamples + "free_fall_block/case.yaml");
    BodyRun run(c, MPI_COMM_WORLD);
    std::vector<std::pair<double, double>> fall;  // (t, downward speed)
    while (run.solver.time() < c.end_time - 1e-12) {
        run.step();
        fall.emplace_back(run.solver.time(), -run.carrier.bodies()[0].state().velocity.y());
    }
    double sum = 0.0, lo = 1e30, hi = -1e30;
    int n = 0;
    for (auto [t, v] : fall)
        if (t >= 1.5) sum += v, lo = std::min(lo, v), hi = std::max(hi, v), ++n;
    const double terminal = sum / n;
    double t95 = 0.0;
    for (auto [t, v] : fall)
        if (v >= 0.95 * terminal) {
            t95 = t;
            break;
        }
    if (root())
        std::printf(
            "block in water, k-epsilon: terminal speed %.4f m/s (t = 1.5-4 s: %.4f-%.4f), t95 %.3f s; "
            "experiment 2.2 +/- 0.2, Beranger 2.10, study 1.7\n",
            terminal, lo, hi, t95);
    EXPECT_NEAR(terminal, 2.2, 0.2);
    EXPECT_LT(hi - lo, 0.04 * terminal);
    EXPECT_LT(t95, 1.5);
}

namespace {
// The example's fall measured as StudyBlockFallsAtTheExperimentsSpeed measures it: mean downward speed over
// t = 1.5-4 s and the first time at 95 % of it.
std::pair<double, double> terminal_and_t95(const std::string& example) {
    const CaseConfig c = load_case(kExamples + example);
    BodyRun run(c, MPI_COMM_WORLD);
    std::vector<std::pair<double, double>> fall;
    while (run.solver.time() < c.end_time - 1e-12) {
        run.step();
        fall.emplace_back(run.solver.time(), -run.carrier.bodies()[0].state().velocity.y());
    }
    double sum = 0.0;
    int n = 0;
    for (auto [t, v] : fall)
        if (t >= 1.5) sum += v, ++n;
    const double terminal = sum / n;
    for (auto [t, v] : fall)
        if (v >= 0.95 * terminal) return {terminal, t};
    return {terminal, 0.0};
}
}  // namespace

// The fall in a window that follows the block (examples/free_fall_block/window.yaml: 150 x 350 cells moving by whole
// cells with it, cfl 0.4 as the example) against the fixed domain (the example, 150 x 767): done-when of the speed
// issue, terminal speed and t95 within 0.5 %. Measured 2026-11-25: fixed / window 2.2934 / 2.2924 m/s (-0.04 %),
// t95 0.883 / 0.882 s (-0.18 %); over the last 0.1 s 2.2848 / 2.2849 m/s, t95 0.875 / 0.875 s (the chute tool); the
// speed at every quarter second within 0.001 m/s. (A grid translating with the
// block, the frame's first version, kept the block at one place against the cells: +2.9 % at cfl 0.4, because the
// immersed drag of the sharp-cornered block depends on that place; docs/validation.md, "A window that moves by
// whole cells".) Slow: about a minute on 2 ranks.
TEST(Turbulence, StudyBlockFallsAlikeInAWindowThatFollowsIt) {
    const auto [fixed_terminal, fixed_t95] = terminal_and_t95("free_fall_block/case.yaml");
    const auto [window_terminal, window_t95] = terminal_and_t95("free_fall_block/window.yaml");
    if (root())
        std::printf(
            "block in water, fixed domain / following window: terminal speed %.4f / %.4f m/s (%+.3f %%), t95 "
            "%.3f / %.3f s (%+.3f %%)\n",
            fixed_terminal, window_terminal, 100 * (window_terminal / fixed_terminal - 1), fixed_t95, window_t95,
            100 * (window_t95 / fixed_t95 - 1));
    EXPECT_NEAR(window_terminal / fixed_terminal, 1.0, 5e-3);
    EXPECT_NEAR(window_t95 / fixed_t95, 1.0, 5e-3);
}

// The same fall carried body-fitted (examples/free_fall_block/body_fitted.yaml: the grid falls with the block,
// coupled strongly without relaxation). Done-when of the body-fitted issue: terminal speed and t95 converged, two
// resolutions within 1 % (both measured as the immersed test does: mean speed over t = 1.5-4 s, first time at
// 95 % of it), inside the experiment's 2.2 +/- 0.2 m/s and holding its speed. The resolutions are 30 and 40 cells
// across: the example's 20 cells are within 0.5 % of 40 in the terminal speed but 2.5 % in t95 (docs/validation.md,
// "The study's block carried body-fitted": t95 moves five times more than the terminal speed it is taken from).
// The domain is the one this test was written for, water entering 5 block sizes ahead (the example now has 15, which
// the block feels: 2.1 % faster): a convergence in h on a fixed domain. With 15 sizes ahead 30 and 40 cells give
// 2.2378 and 2.2335 m/s (+0.19 %) and t95 0.830 and 0.820 s (+1.2 %, 610 s on 2 ranks; docs/validation.md).
// Slow: about 3 minutes on 2 ranks (172 s on 2026-11-24).
TEST(Turbulence, StudyBlockFallsBodyFittedConverged) {
    struct Fall {
        double terminal, t95, lo, hi;
    };
    auto fall = [](int core_cells) {
        const std::string n = std::to_string(core_cells);
        const CaseConfig c = load_case(kExamples + "free_fall_block/body_fitted.yaml",
                                       {"domain.x.core_cells=" + n, "domain.y.core_cells=" + n, "domain.y.start=-1.5"});
        BodyRun run(c, MPI_COMM_WORLD);
        std::vector<std::pair<double, double>> v;  // (t, downward speed)
        while (run.solver.time() < c.end_time - 1e-12) {
            run.step();
            v.emplace_back(run.solver.time(), -run.carrier.bodies()[0].state().velocity.y());
        }
        Fall f{0.0, 0.0, 1e30, -1e30};
        int count = 0;
        for (auto [t, s] : v)
            if (t >= 1.5) f.terminal += s, f.lo = std::min(f.lo, s), f.hi = std::max(f.hi, s), ++count;
        f.terminal /= count;
        for (auto [t, s] : v)
            if (s >= 0.95 * f.terminal) {
                f.t95 = t;
                break;
            }
        if (root())
            std::printf(
                "body-fitted block, %d cells across: terminal speed %.4f m/s (t = 1.5-4 s: %.4f-%.4f), t95 %.3f s\n",
                core_cells / 5, f.terminal, f.lo, f.hi, f.t95);
        return f;
    };
    const Fall coarse = fall(150), fine = fall(200);
    if (root())
        std::printf(
            "30 against 40 cells across: terminal speed %+.2f %%, t95 %+.2f %%; experiment 2.2 +/- 0.2, "
            "Beranger 2.10, study 1.7\n",
            100.0 * (coarse.terminal / fine.terminal - 1.0), 100.0 * (coarse.t95 / fine.t95 - 1.0));
    EXPECT_NEAR(coarse.terminal, fine.terminal, 0.01 * fine.terminal);
    EXPECT_NEAR(coarse.t95, fine.t95, 0.01 * fine.t95);
    EXPECT_NEAR(fine.terminal, 2.2, 0.2);
    EXPECT_LT(fine.hi - fine.lo, 0.04 * fine.terminal);
}

// The same fall with the study's mesh modifiers (examples/free_fall_block/body_fitted_layers.yaml: the lines of a
// zone around the block fall with it, the lines beyond stay, layers move from ahead of the block to behind it,
// band/layers.hpp) in the immersed case's fixed domain with its bed and lid, against the grid that falls whole
// (body_fitted.yaml, water at rest entering 15 block sizes ahead). Done-when of the body-fitted issue, part 2:
// terminal speed within 0.5 % (measured 2.2420 against 2.2427 m/s, 2026-11-24; 2.2393 with the example's far field
// made twice as coarse, 0.2 m and growth 1.15), t95 within 1 % (0.843 against 0.847 s). 20 cells across in both.
// Slow: about 1.5 minutes on 2 ranks.
TEST(Turbulence, StudyBlockFallsAlikeWithLayersAndATranslatingGrid) {
    auto fall = [](const std::string& example) {
        const CaseConfig c = load_case(kExamples + "free_fall_block/" + example, {});
        BodyRun run(c, MPI_COMM_WORLD);
        std::vector<std::pair<double, double>> v;  // (t, downward speed)
        while (run.solver.time() < c.end_time - 1e-12) {
            run.step();
            v.emplace_back(run.solver.time(), -run.carrier.bodies()[0].state().velocity.y());
        }
        double terminal = 0.0, t95 = 0.0;
        int count = 0;
        for (auto [t, s] : v)
            if (t >= 1.5) terminal += s, ++count;
        terminal /= count;
        for (auto [t, s] : v)
            if (s >= 0.95 * terminal) {
                t95 = t;
                break;
            }
        const auto* band = dynamic_cast<const BodyFitted*>(&run.carrier);
        if (root())
            std::printf("%s: terminal speed %.4f m/s (t = 1.5-4 s), t95 %.3f s, %d layer changes\n", example.c_str(),
                        terminal, t95, band ? band->layer_changes()[1] : 0);
        return std::pair{terminal, t95};
    };
    const auto [layers, layers_t95] = fall("body_fitted_layers.yaml");
    const auto [translate, translate_t95] = fall("body_fitted.yaml");
    if (root())
        std::printf("layers against the translating grid: terminal speed %+.2f %%, t95 %+.2f %%\n",
                    100.0 * (layers / translate - 1.0), 100.0 * (layers_t95 / translate_t95 - 1.0));
    EXPECT_NEAR(layers, translate, 0.005 * translate);
    EXPECT_NEAR(layers_t95, translate_t95, 0.01 * translate_t95);
}

// The study's free fall on the sharp carrier (ghost faces) against the body-fitted layers, the issue "Sharp corners"'s
// criterion for the unperturbed fall: terminal speed within 1 %. Both in the example's fixed domain, 20 cells across,
// to t = 4 s; the speed averaged over t = 3-4 s, once both are terminal (the sharp block overshoots to 2.27 m/s at
// t = 1.5-2.5 s and comes down, the body-fitted one still gains there; the sharp block's symmetric wake breaks by
// itself after t = 4 s). Measured 2026-11-27: 2.2525 against 2.2425 m/s (+0.45 %); since the exact coupling (seventh
// step) 2.2577 (+0.68 %, 2026-11-28); the diffuse carrier 2.2846
// (+1.9 %). docs/validation.md, "Sharp interface", sixth step. Slow: 3-5 minutes on 2 ranks.
TEST(Turbulence, StudyBlockFallsOnTheSharpCarrierAsBodyFitted) {
    auto terminal = [](const std::string& example, const std::vector<std::string>& settings) {
        BodyRun run(load_case(kExamples + "free_fall_block/" + example, settings), MPI_COMM_WORLD);
        double distance = 0.0, duration = 0.0;  // over t = 3-4 s
        while (run.solver.time() < 4.0 - 1e-12) {
            const double y0 = run.carrier.bodies()[0].state().centre.y();
            const double t0 = run.solver.time();
            run.step();
            if (t0 >= 3.0) {
                distance += y0 - run.carrier.bodies()[0].state().centre.y();
                duration += run.solver.time() - t0;
            }
        }
        const double speed = distance / duration;
        if (root()) std::printf("%s: mean speed over t = 3-4 s %.4f m/s\n", example.c_str(), speed);
        return speed;
    };
    const double sharp =
        terminal("case.yaml", {"time.end=4", "numerics.ibm.interface=sharp", "numerics.ibm.sharp_faces=ghost"});
    const double layers = terminal("body_fitted_layers.yaml", {"time.end=4"});
    if (root()) std::printf("sharp against body-fitted layers: %+.2f %%\n", 100.0 * (sharp / layers - 1.0));
    EXPECT_NEAR(sharp, layers, 0.01 * layers);
}

// The same block shedding (the sharp-corners issue's second free-fall criterion): `initial.perturbation` 0.05 m/s
// breaks the mirror symmetry, x locked, both carriers on the body-fitted run's grid (clustered in x and y, 200 x 251
// cells), the grid translating with the block along y (the body-fitted grid by carrying the hole, the sharp one by
// `follow: y`), to t = 8 s; the wake takes until t = 4 s to settle, so the mean is over t = 4-8 s (14 shedding
// periods). Measured 2026-11-28: sharp 2.0682 m/s against 2.0768 (-0.41 %), lateral force rms 542 N against 527 N
// (+2.8 %); re-measured the same day (session 29): 2.0683 against 2.0768, 536 N against 521 N (+2.9 %). On a grid at
// rest along y the sharp block fell 2.1 % fast and shed 23 % more weakly (its faces crossing the cells smear the
// boundary layer: docs/validation.md, "Sharp interface", ninth step). Held to the issue's 1 %; the lateral force to 10
// % (the issue's C_L rms criterion for the Lyn square). Slow: about 5 minutes on 2 ranks.
TEST(Turbulence, StudyBlockShedsOnTheSharpCarrierAsBodyFitted) {
    struct Shedding {
        double speed, lateral_rms;
    };
    auto shedding = [](const std::vector<std::string>& carrier) {
        std::vector<std::string> set = {"time.end=8", "initial.type=uniform", "initial.velocity=[0.0, 0.0]",
                                        "initial.perturbation=0.05"};
        set.insert(set.end(), carrier.begin(), carrier.end());
        BodyRun run(load_case(kExamples + "free_fall_block/body_fitted.yaml", set), MPI_COMM_WORLD);
        double distance = 0.0, duration = 0.0, impulse = 0.0, square = 0.0;  // over t = 4-8 s
        while (run.solver.time() < 8.0 - 1e-12) {
            const double y0 = run.carrier.bodies()[0].state().centre.y();
            const double t0 = run.solver.time();
            const double lateral = run.step()[0].forcing.x();
            if (t0 < 4.0) continue;
            const double dt = run.solver.time() - t0;
            distance += y0 - run.carrier.bodies()[0].state().centre.y();
            duration += dt;
            impulse += lateral * dt;
            square += lateral * lateral * dt;
        }
        const double mean = impulse / duration;
        const Shedding s{distance / duration, std::sqrt(square / duration - mean * mean)};
        if (root())
            std::printf("mean speed over t = 4-8 s %.4f m/s, lateral force rms %.0f N\n", s.speed, s.lateral_rms);
        return s;
    };
    const Shedding sharp = shedding({"bodies.block.carrier=immersed", "bodies.block.follow=y",
                                     "numerics.ibm.interface=sharp", "numerics.ibm.sharp_faces=ghost"});
    const Shedding fitted = shedding({});
    if (root())
        std::printf("sharp against body-fitted: speed %+.2f %%, lateral force rms %+.1f %%\n",
                    100.0 * (sharp.speed / fitted.speed - 1.0), 100.0 * (sharp.lateral_rms / fitted.lateral_rms - 1.0));
    EXPECT_NEAR(sharp.speed, fitted.speed, 0.01 * fitted.speed);
    EXPECT_NEAR(sharp.lateral_rms, fitted.lateral_rms, 0.10 * fitted.lateral_rms);
}

// Runout after a bounce on a slope, water against air (Turmel & Locat 2008, sec. 4.3): "in water the block
// travels less than 2/3 of the distance it travels in air" before its next impact on the 45 degree slope,
// "less than half" on the 30 degree slope. examples/bounce_slope with k-epsilon, arrival at about 1.86 m/s;
// runout = horizontal distance between the first two impacts. The study's claim is checked with the study's
// treatment of the impact, contact.water_impulse `body` (the rebound law on the block alone, the water then
// takes its momentum back). With Chute's default, `obstacle` (the wet restitution near the dry one, as the
// sphere experiments and a resolved contact find), the block flies farther in water than in air: printed for
// the record, docs/validation.md "Impacts in water" says why. Slow: about 3 minutes on 2 ranks.
TEST(Turbulence, SlopeRunoutInWaterIsShorterThanInAir) {
    auto runout = [](double angle, bool air, const std::string& water_impulse) {
        std::vector<std::string> set = {"bodies.slope.angle=" + std::to_string(angle), "time.end=2.0",
                                        "contact.water_impulse=" + water_impulse};
        const double above = air ? (angle == 45 ? 0.617 : 0.528) : (angle == 45 ? 1.141 : 1.052);
        set.push_back("bodies.block.centre=[0.0, " + std::to_string(above) + "]");
        if (air) set.insert(set.end(), {"fluid.density=1.2", "fluid.viscosity=1.5e-5"});
        BodyRun run(load_case(kExamples + "bounce_slope/case.yaml", set), MPI_COMM_WORLD);
        std::vector<double> impacts_x;
        while (run.solver.time() < 2.0 - 1e-12 && impacts_x.size() < 2) {
            run.step();
            for (const ContactEvent& e : run.free.events()) impacts_x.push_back(e.centre.x());
        }
        return impacts_x.size() == 2 ? std::abs(impacts_x[1] - impacts_x[0]) : NAN;
    };
    for (double angle : {45.0, 30.0}) {
        const double air = runout(angle, true, "body");
        const double water = runout(angle, false, "body"), water_obstacle = runout(angle, false, "obstacle");
        const double limit = angle == 45.0 ? 2.0 / 3.0 : 0.5;
        if (root())
            std::printf(
                "slope %.0f deg, k-epsilon: runout %.4f m in water (water_impulse body), %.4f m in air, ratio %.3f "
                "(study: < %.3f); water_impulse obstacle: %.4f m, ratio %.3f\n",
                angle, water, air, water / air, limit, water_obstacle, water_obstacle / air);
        EXPECT_LT(water / air, limit);
    }
}

// The study's 45 degree slope as it ran it (a horizontal bed, gravity tilted by 45 degrees, the block translating),
// in both modes: examples/bounce_slope/tilted_gravity.yaml (immersed) against body_fitted_layers.yaml (four
// modifiers, the zone compressed against the bed at the impact). Runout = the horizontal distance (across gravity)
// between the first two impacts. Measured 2026-11-24: 0.9496 against 0.9457 m (-0.4 %), impact speeds 1.352 and
// 1.308 m/s. The body-fitted fall has 2-3 % more drag (the immersed square's sharp-corner separation, issue 15), so
// its block arrives 3.3 % slower; the runouts shall agree to within that, 3.5 %. (At 30 degrees they do not: the
// lateral force on the square at 25 degrees incidence differs, docs/validation.md "Slopes in both modes".)
// Slow: about 2 minutes on 2 ranks.
TEST(Turbulence, StudySlopeRunoutAgreesInBothModes) {
    auto runout = [](const std::string& example) {
        const CaseConfig c = load_case(kExamples + "bounce_slope/" + example, {});
        BodyRun run(c, MPI_COMM_WORLD);
        const Vec2 across = Vec2(c.gravity[1], -c.gravity[0]).normalized();  // the real slope's horizontal
        std::vector<ContactEvent> impacts;
        while (run.solver.time() < c.end_time - 1e-12 && impacts.size() < 2) {
            run.step();
            for (const ContactEvent& e : run.free.events()) impacts.push_back(e);
        }
        if (impacts.size() < 2) return std::pair<double, double>{NAN, NAN};
        if (root())
            std::printf("%s: impact at %.3f m/s, runout %.4f m\n", example.c_str(), impacts[0].velocity_before.norm(),
                        std::abs((impacts[1].centre - impacts[0].centre).dot(across)));
        return std::pair<double, double>{std::abs((impacts[1].centre - impacts[0].centre).dot(across)),
                                         impacts[0].velocity_before.norm()};
    };
    const auto [immersed, immersed_impact] = runout("tilted_gravity.yaml");
    const auto [layers, layers_impact] = runout("body_fitted_layers.yaml");
    if (root())
        std::printf("body-fitted against immersed: runout %+.2f %%, impact speed %+.2f %%\n",
                    100.0 * (layers / immersed - 1.0), 100.0 * (layers_impact / immersed_impact - 1.0));
    EXPECT_NEAR(layers, immersed, 0.035 * immersed);
    EXPECT_NEAR(layers_impact, immersed_impact, 0.05 * immersed_impact);
}

// The water squeezed out between the block's face and the bed (examples/bounce_bed/body_fitted_layers.yaml with
// contact at 5 mm, where the gap is the one cell that stretches): a cushion that slows the block from 1.86 m/s (its
// speed at the study's 0.1 m) to about 0.34 m/s before it touches (docs/validation.md, "The contact gap"; 0.339,
// 0.335, 0.335 m/s at 20, 30, 40 cells across, 2026-11-24). Converged: 20 and 30 cells agree to 2 %, and the cushion
// takes at least three quarters of the speed. Slow: about 3 minutes on 2 ranks.
TEST(Turbulence, StudyBlockOnTheBedIsCushionedByTheSqueezedWater) {
    auto impact_speed = [](const std::vector<std::string>& resolution) -> double {
        std::vector<std::string> set = {"contact.distance=0.005", "time.end=1.7"};
        set.insert(set.end(), resolution.begin(), resolution.end());
        const CaseConfig c = load_case(kExamples + "bounce_bed/body_fitted_layers.yaml", set);
        BodyRun run(c, MPI_COMM_WORLD);
        while (run.solver.time() < c.end_time - 1e-12)
            for (run.step(); const ContactEvent& e : run.free.events()) return e.velocity_before.norm();
        return NAN;
    };
    const double coarse = impact_speed({});
    const double fine =
        impact_speed({"domain.x.core_cells=150", "domain.y.core_cells=105", "domain.y.core=[2.1,3.15]"});
    if (root()) std::printf("impact at a 5 mm gap: %.4f m/s (20 cells across), %.4f m/s (30)\n", coarse, fine);
    EXPECT_NEAR(coarse, fine, 0.02 * fine);
    EXPECT_LT(fine, 0.25 * 1.86);
}
