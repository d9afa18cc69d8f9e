// Lid-driven cavity against Ghia, Ghia & Shin (1982), J. Comput. Phys. 48:387, Tables I and II
// (tests/data/ghia1982_*.dat): unit square, lid u = 1, Re = 1/nu; central convection, uniform grid.
// Measured: the maximum deviation from Ghia's centreline values, over all 2 x 17 points, in units of the
// lid speed. Ghia's own values come from a 129^2 (Re 100) / 129^2 (Re 1000) second-order solution, so a
// second-order solver on 128^2 should agree to about 0.02 U (issue 2, from the spread of published
// 128^2 results); at 64^2 the h^2 error is four times larger near the lid, hence the wider band there.
#include <gtest/gtest.h>

#include <cstdio>

#include "gather.hpp"
#include "steady_state.hpp"

using namespace chute;
using namespace chute::validation;

namespace {

CaseConfig cavity_case(int n, double re) {
    CaseConfig c;
    c.x = AxisConfig{0.0, 1.0, n, "uniform", 2.0, 1.05, {}};
    c.y = c.x;
    for (auto& b : c.boundary) b.type = BoundaryType::wall;
    c.boundary[static_cast<int>(Side::top)].velocity = {1.0, 0.0};
    c.viscosity = 1.0 / re;
    c.convection = ConvectionScheme::central;
    c.cfl = 0.5;
    c.poisson_tolerance = 1e-8;
    return c;
}

struct CavityResult {
    double max_dev_u = 0, max_dev_v = 0, psi_min = 0, x_psi_min = 0, y_psi_min = 0, steady_rate = 0;
};

CavityResult run_cavity(int n, double re, int column, double t_max,
                        ConvectionScheme scheme = ConvectionScheme::central) {
    CaseConfig config = cavity_case(n, re);
    config.convection = scheme;
    // AB2 stability: the TVD schemes oscillate at the lid corner above CFL 0.4 (van Leer) and 0.3 (Koren).
    if (scheme != ConvectionScheme::central) config.cfl = 0.3;
    FlowSolver s(config, MPI_COMM_WORLD);
    CavityResult r;
    r.steady_rate = run_to_steady_state(s, 1e-4, 1.0, t_max);
    const Grid& g = s.grid();
    const auto u = gather_global(g, s.velocity().u, 1, 0);  // (n) rows of (n+1) faces
    const auto v = gather_global(g, s.velocity().v, 0, 1);  // (n+1) rows of (n) faces
    if (g.rank() == 0) {
        const auto& X = g.x_axis();
        const auto& Y = g.y_axis();
        // u on the line x = 0.5 (a face line for even n) at the cell centres y_j, walls added.
        std::vector<double> ys = {0.0}, us = {0.0};
        for (int j = 0; j < n; ++j) ys.push_back(Y.centre(j)), us.push_back(u[(n / 2) + j * (n + 1)]);
        ys.push_back(1.0), us.push_back(1.0);
        std::vector<double> xs = {0.0}, vs = {0.0};
        for (int i = 0; i < n; ++i) xs.push_back(X.centre(i)), vs.push_back(v[i + (n / 2) * n]);
        xs.push_back(1.0), vs.push_back(0.0);
        const std::string dir = CHUTE_SOURCE_DIR "/tests/data/";
        for (const auto& row : read_table(dir + "ghia1982_u_vertical_centreline.dat"))
            r.max_dev_u = std::max(r.max_dev_u, std::abs(interpolate(ys, us, row[0]) - row[column]));
        for (const auto& row : read_table(dir + "ghia1982_v_horizontal_centreline.dat"))
            r.max_dev_v = std::max(r.max_dev_v, std::abs(interpolate(xs, vs, row[0]) - row[column]));
        // Stream function at the grid corners: psi = integral of u dy from the bottom wall.
        for (int i = 0; i <= n; ++i) {
            double psi = 0.0;
            for (int j = 0; j < n; ++j) {
                psi += u[i + j * (n + 1)] * Y.width(j);
                if (psi < r.psi_min) r.psi_min = psi, r.x_psi_min = X.line(i), r.y_psi_min = Y.line(j + 1);
            }
        }
        std::printf(
            "cavity Re %g, %d^2, %s: max |u - Ghia| = %.4f, max |v - Ghia| = %.4f, psi_min = %.6f at "
            "(%.4f, %.4f), steady rate %.1e at t = %.1f\n",
            re, n,
            scheme == ConvectionScheme::central    ? "central"
            : scheme == ConvectionScheme::van_leer ? "van Leer"
                                                   : "Koren",
            r.max_dev_u, r.max_dev_v, r.psi_min, r.x_psi_min, r.y_psi_min, r.steady_rate, s.time());
    }
    MPI_Bcast(&r, sizeof r / sizeof(double), MPI_DOUBLE, 0, MPI_COMM_WORLD);
    return r;
}

// Ghia's psi_min: -0.103423 at (0.6172, 0.7344) for Re 100, -0.117929 at (0.5313, 0.5625) for Re 1000
// (VALIDATION.md). Ours is the minimum over grid corners, O(h) from the true centre, so it is compared
// within a relative band: 2 % at 64^2 and for Re 1000 at 128^2, 1 % for Re 100 at 128^2.
constexpr double kGhiaPsiRe100 = -0.103423, kGhiaPsiRe1000 = -0.117929;
// Botella & Peyret (1998), Computers & Fluids 27:421, spectral solution of the Re 1000 cavity (N = 160):
// psi_min = -0.1189366 at (0.5308, 0.5652). More accurate than Ghia's 129^2 values.
constexpr double kBotellaPeyretPsiRe1000 = -0.1189366;

void expect_agreement(const CavityResult& r, double max_deviation, double psi_ref, double psi_band) {
    EXPECT_LT(r.steady_rate, 1e-4);  // steady: max |du/dt| below 1e-4 U^2/L
    EXPECT_LT(r.max_dev_u, max_deviation);
    EXPECT_LT(r.max_dev_v, max_deviation);
    EXPECT_NEAR(r.psi_min, psi_ref, psi_band * std::abs(psi_ref));
}

}  // namespace

TEST(Cavity, Re100Grid64) { expect_agreement(run_cavity(64, 100.0, 1, 40.0), 0.02, kGhiaPsiRe100, 0.02); }

TEST(Cavity, Re100Grid128) { expect_agreement(run_cavity(128, 100.0, 1, 40.0), 0.01, kGhiaPsiRe100, 0.01); }

TEST(Cavity, Re1000Grid128) { expect_agreement(run_cavity(128, 1000.0, 3, 120.0), 0.02, kGhiaPsiRe1000, 0.02); }

// The bounded (TVD) schemes for high Reynolds numbers, on the Re 1000 cavity at 128^2, held to the same
// 0.02 U band as the central scheme: limited second-order upwinding adds numerical diffusion only where
// the limiter clips, which a 128^2 grid keeps small. (This test found a sign error in the van Leer face
// value for negative slopes, which put the profiles 0.08 U off and kept the run from a steady state.)
TEST(Cavity, Re1000Grid128VanLeer) {
    expect_agreement(run_cavity(128, 1000.0, 3, 120.0, ConvectionScheme::van_leer), 0.02, kGhiaPsiRe1000, 0.02);
}

TEST(Cavity, Re1000Grid128Koren) {
    expect_agreement(run_cavity(128, 1000.0, 3, 120.0, ConvectionScheme::koren), 0.02, kGhiaPsiRe1000, 0.02);
}

// Grid convergence of the Re 1000 cavity (label slow, ~1.5 min on 2 ranks). From 128^2 to 256^2 psi_min
// must move towards the spectral value of Botella & Peyret and lie within 1 % of it; against Ghia's
// centrelines the deviation does not shrink (v grows from 0.012 to 0.016 U): Ghia's own 129^2 error.
TEST(Cavity, Re1000Grid256) {
    const auto coarse = run_cavity(128, 1000.0, 3, 120.0), fine = run_cavity(256, 1000.0, 3, 120.0);
    expect_agreement(fine, 0.02, kBotellaPeyretPsiRe1000, 0.01);
    EXPECT_LT(std::abs(fine.psi_min - kBotellaPeyretPsiRe1000), std::abs(coarse.psi_min - kBotellaPeyretPsiRe1000));
}
