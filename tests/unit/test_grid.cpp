// Grid geometry: ghost lines beyond the boundaries, periodic images, patch decomposition, and grid lines
// that move during a run (the body-fitted band will move them every step).
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>

#include "case_config.hpp"
#include "diagnostics.hpp"
#include "flow_solver.hpp"

using namespace chute;

TEST(Axis, GhostLinesMirrorAtWallsAndWrapWhenPeriodic) {
    const auto lines = geometric_lines(0.0, 1.0, 10, 1.1);
    const Axis wall(lines, false), periodic(lines, true);
    // Mirror: the ghost cell is the image of its interior partner, so the wall is midway between centres.
    EXPECT_DOUBLE_EQ(wall.line(-1), -lines[1]);
    EXPECT_DOUBLE_EQ(wall.centre(-1), -wall.centre(0));
    EXPECT_DOUBLE_EQ(wall.width(10), wall.width(9));
    EXPECT_DOUBLE_EQ(wall.line(12), 2.0 - lines[8]);
    // Periodic: the images are shifted by the length.
    EXPECT_DOUBLE_EQ(periodic.line(-1), lines[9] - 1.0);
    EXPECT_DOUBLE_EQ(periodic.line(11), lines[1] + 1.0);
    EXPECT_DOUBLE_EQ(periodic.width(-1), periodic.width(9));
}

TEST(Axis, GeneratorsHitTheEndsAndStretchAsAsked) {
    const auto t = tanh_lines(-1.0, 2.0, 16, 2.0);
    EXPECT_DOUBLE_EQ(t.front(), -1.0);
    EXPECT_DOUBLE_EQ(t.back(), 2.0);
    EXPECT_LT(t[1] - t[0], t[9] - t[8]);  // clustered at the ends
    const auto g = geometric_lines(0.0, 1.0, 8, 1.2);
    EXPECT_NEAR((g[2] - g[1]) / (g[1] - g[0]), 1.2, 1e-12);
    EXPECT_THROW(Axis({0.0, 1.0, 0.5}, false), std::invalid_argument);
}

// The study's body-fitted mesh (sec. 3.3): 30 cells across the 0.3 m block, 5 mm at its faces, growing away from
// them (here by 10 % per cell up to 5 cm, then uniform). The window's ends are lines; its cells are symmetric and
// grow by one ratio towards its middle; the outer cells start from the face's width and keep to the cap.
TEST(Axis, ClusteredTowardsABodysFaces) {
    const auto x = clustered_lines(-1.5, 4.5, -0.15, 0.15, 30, 1.1, 0.005, 0.05);
    EXPECT_DOUBLE_EQ(x.front(), -1.5);
    EXPECT_DOUBLE_EQ(x.back(), 4.5);
    const auto lo = std::find(x.begin(), x.end(), -0.15), hi = std::find(x.begin(), x.end(), 0.15);
    ASSERT_NE(lo, x.end());
    ASSERT_NE(hi, x.end());
    ASSERT_EQ(hi - lo, 30);
    const std::size_t a = lo - x.begin(), b = hi - x.begin();
    EXPECT_NEAR(x[a + 1] - x[a], 0.005, 1e-12);
    EXPECT_NEAR(x[b] - x[b - 1], 0.005, 1e-12);
    const double r = (x[a + 2] - x[a + 1]) / (x[a + 1] - x[a]);
    EXPECT_GT(r, 1.0);
    for (std::size_t k = 0; k < 15; ++k) {
        EXPECT_NEAR(x[a + k + 1] - x[a + k], x[b - k] - x[b - k - 1], 1e-12);  // symmetric
        if (k > 0 && k < 14) {
            EXPECT_NEAR((x[a + k + 1] - x[a + k]) / (x[a + k] - x[a + k - 1]), r, 1e-9);
        }
    }
    // Outside: the first cell beside each face about 5.5 mm (5 mm x 1.1, scaled by at most a few % to fit), growth
    // at most 1.1 per cell, never wider than the cap (to the scaling).
    EXPECT_NEAR((x[a] - x[a - 1]) / 0.0055, 1.0, 0.05);
    EXPECT_NEAR((x[b + 1] - x[b]) / 0.0055, 1.0, 0.05);
    double widest = 0.0;
    for (std::size_t k = 1; k < x.size(); ++k) {
        const double w = x[k] - x[k - 1];
        widest = std::max(widest, w);
        if (k > 1) {
            EXPECT_LT(w / (x[k - 1] - x[k - 2]), 1.1 * 1.05) << k;
            EXPECT_GT(w / (x[k - 1] - x[k - 2]), 1.0 / (1.1 * 1.05)) << k;
        }
    }
    EXPECT_LT(widest, 0.05 * 1.05);
    EXPECT_NEAR(clustered_cell_count(-1.5, 4.5, -0.15, 0.15, 30, 1.1, 0.005, 0.05), x.size() - 1.0, 2.0);
    EXPECT_THROW(clustered_lines(-1.0, 1.0, -0.15, 0.15, 30, 1.1, 0.01), std::invalid_argument);  // 30 x 1 cm
}

TEST(Grid, PatchesCoverTheDomainOnce) {
    const Grid g(Axis(uniform_lines(0, 1, 37), false), Axis(uniform_lines(0, 1, 21), false), MPI_COMM_WORLD);
    long long cells = 1LL * g.nx() * g.ny();
    MPI_Allreduce(MPI_IN_PLACE, &cells, 1, MPI_LONG_LONG, MPI_SUM, g.comm());
    EXPECT_EQ(cells, 37LL * 21);
    EXPECT_DOUBLE_EQ(g.lx().f(0), g.x_axis().line(g.lx().offset));
}

// After the lines move (same counts), geometry and the Poisson matrix follow: the next projection is
// again divergence-free to the solver tolerance on the new grid.
TEST(Grid, MovingLinesKeepTheProjectionExact) {
    CaseConfig c;
    c.x = AxisConfig{0.0, 1.0, 32, "uniform", 2.0, 1.05, {}};
    c.y = c.x;
    for (auto& b : c.boundary) b.type = BoundaryType::wall;
    c.boundary[3].velocity = {1.0, 0.0};
    c.viscosity = 1e-2;
    c.poisson_tolerance = 1e-10;
    FlowSolver s(c, MPI_COMM_WORLD);
    for (int k = 0; k < 20; ++k) s.advance();
    s.set_grid_lines(tanh_lines(0.0, 1.0, 32, 1.0), geometric_lines(0.0, 1.0, 32, 1.03));
    EXPECT_LT(s.grid().x_axis().width(0), 1.0 / 32);                                      // the lines moved
    EXPECT_DOUBLE_EQ(s.grid().lx().w(0), s.grid().x_axis().width(s.grid().lx().offset));  // geometry rebuilt
    for (int k = 0; k < 5; ++k) s.advance();
    // max |div u| against the velocity-gradient scale U / h_min ~ 1 / 0.02.
    EXPECT_LT(max_divergence(s.grid(), s.velocity()) * 0.02, 1e-8);
}
