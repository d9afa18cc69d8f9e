// Solid cells (core/grid/solid_cells.hpp): the hole a body-fitted body makes in the grid. Its sides must act
// exactly as the domain's walls do: same ghost values, no flux across them, the same discrete solution.
#include <gtest/gtest.h>

#include <mpi.h>

#include <cmath>

#include "diagnostics.hpp"
#include "flow_solver.hpp"
#include "solid_cells.hpp"

using namespace chute;

namespace {

double global_max(double local, const Grid& g) {
    MPI_Allreduce(MPI_IN_PLACE, &local, 1, MPI_DOUBLE, MPI_MAX, g.comm());
    return local;
}

// A channel, periodic in x, driven by a body force and a bottom that slides at `bed_speed`, started from a
// cross-stream sine: a flow with both components and both walls' conditions at work.
FlowConfig channel(double y_start, int y_cells, double bed_speed) {
    FlowConfig c;
    c.x = AxisConfig{0.0, 2.0, 24, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{y_start, 1.0, y_cells, "uniform", 2.0, 1.05, {}};
    c.boundary[static_cast<int>(Side::left)].type = BoundaryType::periodic;
    c.boundary[static_cast<int>(Side::right)].type = BoundaryType::periodic;
    c.boundary[static_cast<int>(Side::bottom)] = {.type = BoundaryType::wall, .velocity = {bed_speed, 0.0}};
    c.boundary[static_cast<int>(Side::top)].type = BoundaryType::wall;
    c.viscosity = 0.05;
    c.body_force = {0.8, 0.0};
    c.initial_perturbation = 0.2;
    c.convection = ConvectionScheme::van_leer;
    c.diffusion = DiffusionScheme::explicit_ab2;
    c.fixed_dt = 0.004;
    c.poisson_tolerance = 1e-13;
    return c;
}

}  // namespace

// The bed as a solid block across the whole (periodic) width, sliding at 0.3 m/s, against the same channel
// whose bottom wall slides: the fluid's velocity agrees to round-off after 150 steps. Checks the mirrors of
// both components, the wall speed in them, and the Poisson problem without the solid cells.
TEST(SolidCells, BedBlockIsTheDomainWall) {
    const double bed_speed = 0.3;
    FlowSolver wall(channel(0.0, 16, bed_speed), MPI_COMM_WORLD);
    FlowConfig holed = channel(-0.5, 24, 0.0);
    FlowSolver block(holed, MPI_COMM_WORLD);
    SolidCells solid(block.grid());
    solid.set({SolidBlock{.lower = {0, 0}, .upper = {24, 8}, .velocity = {bed_speed, 0.0}}});
    block.set_solid_cells(&solid);  // projects the start against the block
    wall.project_start();           // the same for the walled channel
    for (int k = 0; k < 150; ++k) {
        wall.advance();
        block.advance();
    }
    // Compare on the rows both grids own alike: with one rank each, and in general through global indices.
    const Grid& gw = wall.grid();
    const Grid& gb = block.grid();
    double diff = 0.0, scale = 0.0;
    for (int j = 0; j < gb.ny(); ++j)
        for (int i = 0; i < gb.nx(); ++i) {
            const int gj = j + gb.ly().offset - 8;  // row of the walled channel
            const int lj = gj - gw.ly().offset, li = i + gb.lx().offset - gw.lx().offset;
            if (gj < 0 || lj < 0 || lj >= gw.ny() || li < 0 || li >= gw.nx()) continue;
            diff = std::max(diff, std::abs(block.velocity().u(i, j) - wall.velocity().u(li, lj)));
            if (gj > 0) diff = std::max(diff, std::abs(block.velocity().v(i, j) - wall.velocity().v(li, lj)));
            scale = std::max(scale, std::abs(wall.velocity().u(li, lj)));
        }
    diff = global_max(diff, gb);
    scale = global_max(scale, gb);
    ASSERT_GT(scale, 0.1);
    EXPECT_LT(diff / scale, 1e-11);
}

// A block at rest in a lid-driven cavity: no flow through its sides (their normal velocity stays exactly 0),
// the fluid divergence-free, and the flow goes round it (the faces beside it move).
TEST(SolidCells, BlockInACavityTakesNoFlowThroughItsSides) {
    FlowConfig c;
    c.x = AxisConfig{0.0, 1.0, 32, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{0.0, 1.0, 32, "tanh", 1.5, 1.05, {}};
    for (auto& b : c.boundary) b.type = BoundaryType::wall;
    c.boundary[static_cast<int>(Side::top)].velocity = {1.0, 0.0};
    c.viscosity = 0.01;
    c.poisson_tolerance = 1e-12;
    c.diffusion = DiffusionScheme::explicit_ab2;
    FlowSolver s(c, MPI_COMM_WORLD);
    SolidCells solid(s.grid());
    const std::array<int, 2> lo{10, 12}, hi{22, 20};
    solid.set({SolidBlock{.lower = lo, .upper = hi}});
    s.set_solid_cells(&solid);
    for (int k = 0; k < 120; ++k) s.advance();

    const Grid& g = s.grid();
    const int ox = g.lx().offset, oy = g.ly().offset;
    double through = 0.0, beside = 0.0;
    for (int j = 0; j < g.ny(); ++j)
        for (int i = 0; i < g.nx(); ++i) {
            const int gi = i + ox, gj = j + oy;
            const bool rows = gj >= lo[1] && gj < hi[1], cols = gi >= lo[0] && gi < hi[0];
            if (rows && (gi == lo[0] || gi == hi[0])) through = std::max(through, std::abs(s.velocity().u(i, j)));
            if (cols && (gj == lo[1] || gj == hi[1])) through = std::max(through, std::abs(s.velocity().v(i, j)));
            if (cols && gj == hi[1]) beside = std::max(beside, std::abs(s.velocity().u(i, j)));  // above the top
        }
    through = global_max(through, g);
    beside = global_max(beside, g);
    EXPECT_EQ(through, 0.0);
    EXPECT_GT(beside, 1e-3);
    EXPECT_LT(max_divergence(g, s.velocity(), s.fluid_cells()), 1e-9);
    // Without the mask the mirrored faces inside the hole show (they are ghosts, not a flow).
    EXPECT_GT(max_divergence(g, s.velocity()), 1e-6);
}
