// A grid that follows an immersed body (bodies.<body>.follow, run/following_frame.hpp): the same flow as on the
// fixed grid, without the body crossing cells. Reference: the fixed grid itself, on a flow that is the same
// problem in both frames (a y-periodic channel has no boundary along the motion).
#include <gtest/gtest.h>

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "case_file.hpp"
#include "chute_process.hpp"
#include "hdf5_file.hpp"
#include "immersed_boundary.hpp"
#include "model.hpp"
#include "simulation.hpp"
#include "step.hpp"

using namespace chute;

namespace {

// A square of side 1 moving down at 1 m/s (Re 40: a steady wake) through a channel 4 wide with slip sides, periodic
// along y (12 long), 16 cells across the square.
std::string moving_square(const std::string& follow) {
    return R"(
name: moving_square
domain:
  x: {start: -2.0, end: 2.0, cells: 64}
  y: {start: -6.0, end: 6.0, cells: 192}
fluid: {density: 1000.0, viscosity: 2.5e-2}
boundaries: {left: {type: slip}, right: {type: slip}, bottom: {type: periodic}, top: {type: periodic}}
bodies:
  square:
    shape: rectangle
    centre: [0.0, 0.0]
    size: [1.0, 1.0]
    follow: )" +
           follow + R"(
    motion: {type: constant_velocity, velocity: [0.0, -1.0]}
numerics: {dt: 0.01, convection: van_leer}
time: {end: 2.0}
output: {plots: false}
)";
}

struct Drag {
    std::vector<double> forcing;  // force (a) along y, every step (N per metre of span)
    double grid_travel = 0.0;     // how far the grid's lines moved (m)
};

Drag run(const std::string& follow, const std::vector<std::string>& overrides = {}, double dt = 0.01) {
    Model model(parse_case_text(moving_square(follow), overrides), MPI_COMM_WORLD);
    const double start = model.flow().grid().y_axis().start();
    Drag d;
    for (int n = 0; n < 200; ++n) {
        take_step(model, dt);
        d.forcing.push_back(measure_forces(model).at(0).forcing.y());
    }
    d.grid_travel = model.flow().grid().y_axis().start() - start;
    return d;
}

std::string refusal(const std::vector<std::string>& overrides) {
    try {
        Model m(parse_case_text(moving_square("y"), overrides), MPI_COMM_WORLD);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// The square moving through the periodic channel on the fixed grid and on a grid following it by whole cells: the
// same problem (translation invariant along y), and the following grid computes it with the same discrete
// equations, its cells relabelled at each move (the rows wrap around the periodic axis). So the drag agrees to
// round-off (the direct pressure solve's transforms of the relabelled rows round differently), where a grid
// translating with the body kept one place of it against the cells and differed by 0.7 % (the first version of the
// frame, 2026-11-25). Bound 1e-9 of the mean at every step: measured 1.8e-15, on 1 and 2 ranks (2026-11-25).
TEST(FollowingFrame, MovingSquareIsTheFixedGridRelabelled) {
    const Drag fixed = run("none"), following = run("y");
    ASSERT_EQ(fixed.forcing.size(), following.forcing.size());
    double mean = 0.0, largest = 0.0;
    for (double f : fixed.forcing) mean += f / static_cast<double>(fixed.forcing.size());
    for (std::size_t n = 0; n < fixed.forcing.size(); ++n)
        largest = std::max(largest, std::abs(following.forcing[n] - fixed.forcing[n]));
    std::printf(
        "moving square: mean drag %.4f N/m, largest difference following - fixed %.2e of it; grid moved %.4f m\n", mean,
        largest / std::abs(mean), following.grid_travel);
    EXPECT_LT(largest, 1e-9 * std::abs(mean));
    // 200 steps of 0.01 s at 1 m/s: 2 m, 32 cells; the grid within a cell of the square's travel.
    EXPECT_NEAR(following.grid_travel, -2.0, 12.0 / 192.0 + 1e-12);
    EXPECT_EQ(fixed.grid_travel, 0.0);
    // On 2 ranks the automatic decomposition splits y, the followed axis (the rows a move takes across a patch's
    // edge come from the neighbour, across the periodic ends from the other patch); the other split, along x, too.
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (size != 2) return;
    const Drag split = run("y", {"parallel.ranks=[2, 1]"});
    double split_largest = 0.0;
    for (std::size_t n = 0; n < fixed.forcing.size(); ++n)
        split_largest = std::max(split_largest, std::abs(split.forcing[n] - fixed.forcing[n]));
    std::printf("moving square, patches split along x: largest difference %.2e of the mean\n",
                split_largest / std::abs(mean));
    EXPECT_LT(split_largest, 1e-9 * std::abs(mean));
}

// The same along both axes: the square moving diagonally through a doubly periodic box, the grid following it in x
// and y (16 moves in x, 31 in y over the 200 steps).
TEST(FollowingFrame, DiagonalMotionIsTheFixedGridRelabelled) {
    const std::vector<std::string> diagonal = {"boundaries.left={type: periodic}", "boundaries.right={type: periodic}",
                                               "bodies.square.motion={type: constant_velocity, velocity: [0.5, -1.0]}"};
    const Drag fixed = run("none", diagonal), following = run("xy", diagonal);
    double mean = 0.0, largest = 0.0;
    for (double f : fixed.forcing) mean += f / static_cast<double>(fixed.forcing.size());
    for (std::size_t n = 0; n < fixed.forcing.size(); ++n)
        largest = std::max(largest, std::abs(following.forcing[n] - fixed.forcing[n]));
    std::printf("diagonal square: mean drag along y %.4f N/m, largest difference %.2e of it; grid moved %.4f m in y\n",
                mean, largest / std::abs(mean), following.grid_travel);
    EXPECT_LT(largest, 1e-9 * std::abs(mean));
    EXPECT_NEAR(following.grid_travel, -2.0, 12.0 / 192.0 + 1e-12);
}

// On the sharp interface the grid translates with the body (run/following_frame.hpp): the square moving along a
// diagonal through a doubly periodic box is then the held square in the opposite stream, the same problem seen from
// a frame moving at the body's velocity, and the translating grid computes it with the same cells around the body.
// They differ only in the start (the held stream is projected round the square at t = 0, the moving square meets
// still water in its first step), so the drag is compared after it: measured 2026-11-28 largest 1.6e-10 of the mean
// over steps 50-200 (the start's difference gone, the rest round-off); bound 1e-7. Steps of 5 ms: the held square in
// the doubly periodic box diverges at 10 ms (t = 0.45 s; docs/limitations.md). On the grid at rest the sharp square
// moving oblique to the lines reads a drag that depends on how it crosses the cells (printed beside it; the study's
// block at Re 6e5 read 34 % less than held, docs/validation.md, "Sharp interface", ninth step).
TEST(FollowingFrame, SharpSquareOnTheTranslatingGridIsTheHeldSquare) {
    const std::vector<std::string> sharp = {"numerics.ibm.interface=sharp", "numerics.ibm.sharp_faces=ghost",
                                            "boundaries.left={type: periodic}", "boundaries.right={type: periodic}"};
    auto with = [&](std::vector<std::string> more) {
        more.insert(more.begin(), sharp.begin(), sharp.end());
        return more;
    };
    const double dt = 0.005;
    const Drag held = run("none", with({"bodies.square.motion={type: fixed}", "initial={velocity: [-0.5, 1.0]}"}), dt);
    const Drag moving = run("xy", with({"bodies.square.motion={type: constant_velocity, velocity: [0.5, -1.0]}"}), dt);
    const Drag crossing =
        run("none", with({"bodies.square.motion={type: constant_velocity, velocity: [0.5, -1.0]}"}), dt);
    double mean = 0.0, largest = 0.0, crossing_mean = 0.0;
    const std::size_t first = 50, n = held.forcing.size() - first;
    for (std::size_t k = first; k < held.forcing.size(); ++k) {
        mean += held.forcing[k] / static_cast<double>(n);
        crossing_mean += crossing.forcing[k] / static_cast<double>(n);
        largest = std::max(largest, std::abs(moving.forcing[k] - held.forcing[k]));
    }
    std::printf(
        "sharp diagonal square: held drag along y %.4f N/m, translating grid largest difference %.2e of it; on the "
        "grid at rest %.4f (%+.2f %%); grid moved %.4f m in y\n",
        mean, largest / std::abs(mean), crossing_mean, 100.0 * (crossing_mean / mean - 1.0), moving.grid_travel);
    EXPECT_LT(largest, 1e-7 * std::abs(mean));
    // The grid at rest reads less (measured -5.5 % at this Re of 40; the sharp boundary layer smeared as it crosses).
    EXPECT_LT(crossing_mean / mean, 0.99);
    // 200 steps of 5 ms at 1 m/s: the grid went with the square, to round-off.
    EXPECT_NEAR(moving.grid_travel, -1.0, 1e-9);
}

TEST(FollowingFrame, RefusesWhatItCannotFollowNamingTheKey) {
    const std::string walls = refusal({"boundaries.bottom={type: wall}", "boundaries.top={type: outflow}"});
    EXPECT_NE(walls.find("boundaries.bottom.type"), std::string::npos) << walls;
    EXPECT_NE(walls.find("across the motion"), std::string::npos) << walls;
    EXPECT_EQ(refusal({"boundaries.bottom={type: inflow, velocity: [0.0, 0.0]}", "boundaries.top={type: outflow}"}),
              "");
    const std::string two =
        refusal({"bodies.other={shape: circle, centre: [1.0, 3.0], diameter: 0.2, follow: y, "
                 "motion: {type: constant_velocity, velocity: [0.0, -0.1]}}"});
    EXPECT_NE(two.find("one body at most"), std::string::npos) << two;
    // A fixed body in the window moves against the grid: it is placed again after each move (Grid::lines_version).
    EXPECT_EQ(refusal({"bodies.post={shape: circle, centre: [1.0, 3.0], diameter: 0.2}"}), "");
    const std::string stretched =
        refusal({"domain.y={start: -6.0, end: 6.0, spacing: clustered, core: [-1.0, 1.0], core_cells: 40, "
                 "ratio: 1.05}"});
    EXPECT_NE(stretched.find("domain.y"), std::string::npos) << stretched;
    EXPECT_NE(stretched.find("equal"), std::string::npos) << stretched;
    try {
        (void)parse_case_text(moving_square("y"), {"bodies.square.motion={type: fixed}"});
        ADD_FAILURE() << "a fixed body to follow was accepted";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("bodies.square.follow"), std::string::npos) << e.what();
    }
}

namespace {

// A light square falling free (laminar, 32 x 64 cells, the step chosen by the CFL number), the grid following it.
const char* kFallingSquare = R"(
name: following_fall
domain:
  x: {start: -1.0, end: 1.0, cells: 32}
  y: {start: -1.5, end: 2.5, cells: 64}
fluid: {density: 1000.0, viscosity: 1.0e-2}
boundaries:
  left: {type: slip}
  right: {type: slip}
  bottom: {type: inflow, velocity: [0.0, 0.0]}
  top: {type: outflow}
bodies:
  square:
    shape: rectangle
    centre: [0.0, 0.0]
    size: [0.5, 0.5]
    density: 1500.0
    follow: y
    motion: {type: free, lock_x: true, lock_rotation: true}
numerics: {convection: van_leer, cfl: 0.4}
time: {end: 1.5}
output: {checkpoint_interval: 0.5, plots: false}
)";

}  // namespace

namespace {

void expect_restart_equals_straight_run(const std::vector<std::string>& overrides, const std::string& tag) {
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const auto dir = [&](const std::string& name) {
        const auto d = std::filesystem::temp_directory_path() /
                       ("chute_test_following_" + tag + name + "_np" + std::to_string(size));
        if (rank == 0) {
            std::filesystem::remove_all(d);
            std::filesystem::create_directories(d);
        }
        MPI_Barrier(MPI_COMM_WORLD);
        return d;
    };
    const CaseConfig config = parse_case_text(kFallingSquare, overrides);
    const auto straight_dir = dir("straight"), split_dir = dir("split");
    RunOptions options;
    options.quiet = true;
    options.out_dir = straight_dir;
    const RunSummary straight = run_simulation(config, options, MPI_COMM_WORLD);
    CaseConfig first_part = config;
    ASSERT_GE(straight.steps, 40);
    first_part.max_steps = straight.steps / 2;
    options.out_dir = split_dir;
    const RunSummary stopped = run_simulation(first_part, options, MPI_COMM_WORLD);
    options.restart = stopped.last_checkpoint;
    const RunSummary resumed = run_simulation(config, options, MPI_COMM_WORLD);
    ASSERT_EQ(stopped.steps, straight.steps / 2);
    EXPECT_EQ(stopped.steps + resumed.steps, straight.steps);
    EXPECT_EQ(resumed.time, straight.time);
    if (rank != 0) return;
    std::vector<std::string> names = {"u", "v", "p"};
    if (config.turbulence.model != TurbulenceModelType::laminar)
        names.insert(names.end(), {"k", "epsilon", "eddy_viscosity"});
    for (const std::string& name : names) {
        const auto x = Hdf5File::open_read(straight.last_checkpoint).read("/fields/" + name);
        const auto y = Hdf5File::open_read(resumed.last_checkpoint).read("/fields/" + name);
        ASSERT_EQ(x.size(), y.size());
        for (std::size_t k = 0; k < x.size(); ++k) ASSERT_EQ(x[k], y[k]) << name << "[" << k << "]";
    }
    EXPECT_EQ(chute_test::read_text(straight_dir / "timeseries.csv"),
              chute_test::read_text(split_dir / "timeseries.csv"));
}

}  // namespace

// A run with a following grid stopped and restarted from its checkpoint ends bit for bit where the straight run
// ends: the lines (where the window has moved to, and so where the body started on them) and the flow are in the
// checkpoint.
TEST(FollowingFrame, StopAndRestartEqualsStraightRun) { expect_restart_equals_straight_run({}, ""); }

// The same with k-epsilon. Two things a restart did not find again, both found on the study's window (2026-11-25):
// the cells beside the immersed surface take the wall's eddy viscosity from samples taken with k before the last
// update, which k after it does not give back (now in the checkpoint; the fixed-domain example was 2e-7 apart in
// its kinetic energy the step after a restart), and on 2 ranks the outflow's faces in a patch's corner halo, which
// the convective condition updates there and no exchange sets (now read from the checkpoint with the halo).
// The sharp interface's translating grid under a free body: its velocity changes within each step, the grid's
// velocity takes the drift back over the next (FollowingFrame::follow), and the lines' place is in the checkpoint.
TEST(FollowingFrame, StopAndRestartEqualsStraightRunOnTheTranslatingGrid) {
    expect_restart_equals_straight_run({"numerics.ibm.interface=sharp", "numerics.ibm.sharp_faces=ghost"}, "sharp_");
}

// On the translating grid the lines move by multiples of a power of two on whose multiples they lie, so that a rigid
// translation keeps every spacing bit for bit (run/following_frame.hpp). A free square whose sides lie on the lines
// then cuts the same faces every step, the cut pressure problem keeps its matrix, and the exact coupling's response
// to the body's unit motion is solved once and kept (ibm/immersed_boundary.cpp): the same answer a restart solves
// afresh (StopAndRestartEqualsStraightRunOnTheTranslatingGrid). Moved half a cell off the lines, the square's cut
// faces are found by bisection in bits that the round-off of its place decides, and the response is solved again in
// most steps.
TEST(FollowingFrame, FollowedBlockOnTheLinesKeepsItsResponse) {
    for (const double offset : {0.0, 0.5}) {
        SCOPED_TRACE(offset == 0.0 ? "sides on the lines" : "half a cell off");
        const double centre = offset * 2.0 / 32;
        CaseConfig config = parse_case_text(
            kFallingSquare, {"numerics.ibm.interface=sharp", "numerics.ibm.sharp_faces=ghost",
                             "bodies.square.centre=[" + std::to_string(centre) + ", " + std::to_string(centre) + "]"});
        Model model(config, MPI_COMM_WORLD);
        std::vector<double> widths;
        for (int k = 0; k < model.flow().grid().y_axis().cells(); ++k)
            widths.push_back(model.flow().grid().y_axis().width(k));
        const double start = model.flow().grid().y_axis().start();
        const int steps = 30;
        for (int n = 0; n < steps; ++n) take_step(model, model.stable_dt(), nullptr);
        const Grid& grid = model.flow().grid();
        EXPECT_LT(grid.y_axis().start(), start - 0.01);  // it fell, and the lines with it
        for (int k = 0; k < grid.y_axis().cells(); ++k)
            ASSERT_EQ(grid.y_axis().width(k), widths[static_cast<std::size_t>(k)]) << "cell " << k;
        const auto& immersed = dynamic_cast<const ImmersedBoundary&>(model.carrier());
        if (offset == 0.0)
            EXPECT_EQ(immersed.responses_solved(), 1u);
        else  // measured 29 of 30 steps
            EXPECT_GT(immersed.responses_solved(), static_cast<std::size_t>(steps / 2));
    }
}

TEST(FollowingFrame, StopAndRestartEqualsStraightRunWithKEpsilon) {
    expect_restart_equals_straight_run(
        {"turbulence={model: k_epsilon, velocity_scale: 1.0, intensity: 0.01, length_scale: 0.01}",
         "fluid.viscosity=1.0e-5"},
        "ke_");
}
