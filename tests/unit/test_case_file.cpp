// Case files (core/case_file.cpp).
//
// Checks: a full valid case reads back exactly the values written; keys left out take the defaults of
// CaseConfig (so the schema's documented defaults and the struct's agree); --set overrides change, add
// and reject keys; each class of mistake is a CaseError whose message names the full key path, the
// reason and, for a file, the line; docs/case-file.md lists every schema key, carries the current
// generated key table, and its full example parses. Values are exact (no tolerance): they are read from
// text, not computed.
#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "case_file.hpp"

namespace chute {
namespace {

const std::string kFullCase = R"(name: channel
domain:
  x: {start: -1.0, end: 3.0, cells: 80, spacing: uniform}
  y: {start: 0.0, end: 1.0, cells: 40, spacing: tanh, beta: 1.5}
  depth: 0.5
fluid:
  density: 998.0
  viscosity: 1.0e-3
  body_force: [0.0, -9.81]
initial:
  type: uniform
  velocity: [0.5, 0.0]
boundaries:
  left:   {type: inflow, profile: parabolic, peak: 1.5}
  right:  {type: outflow, kind: zero_stress}
  bottom: {type: wall}
  top:    {type: wall, velocity: [0.25, 0]}
numerics:
  convection: koren
  cfl: 0.4
  diffusion_number: 0.25
  dt: 1.0e-3
  max_dt: 0.01
  poisson: {tolerance: 1.0e-10, max_iterations: 50}
  divergence_limit: 1.0e-4
time:
  end: 2.5
  max_steps: 1000
parallel:
  ranks: [2, 1]
output:
  fields_interval: 0.1
  checkpoint_interval: 0.5
  checkpoints_kept: 3
  timeseries_every: 5
  progress_interval: 0
  probes: [[0.5, 0.5], [2.0, 0.25]]
  plots: false
)";

// Only the required keys. Line numbers below refer to this text.
const std::string kMinimal = R"(domain:
  x: {start: 0, end: 1, cells: 8}
  y: {start: 0, end: 1, cells: 8}
fluid:
  viscosity: 0.01
boundaries:
  left: {type: wall}
  right: {type: wall}
  bottom: {type: wall}
  top: {type: wall, velocity: [1, 0]}
time:
  end: 1.0
)";

// kMinimal with one piece of text replaced.
std::string minimal_with(const std::string& from, const std::string& to) {
    std::string text = kMinimal;
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "test text not found: " << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

// The message of the CaseError that parsing throws ("" and a failure if it throws none).
std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
    try {
        parse_case_text(text, overrides);
    } catch (const CaseError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no CaseError for:\n" << text;
    return "";
}

// Every part must appear in the message.
void expect_message(const std::string& message, std::initializer_list<std::string> parts) {
    for (const std::string& part : parts)
        EXPECT_NE(message.find(part), std::string::npos) << "message: " << message << "\nlacks: " << part;
}

std::filesystem::path temp_case(const std::string& stem, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() /
                      (stem + "_" + std::to_string(::getpid()) + ".yaml");  // one file per process (MPI)
    std::ofstream(path) << text;
    return path;
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const std::filesystem::path kDoc = std::filesystem::path(CHUTE_SOURCE_DIR) / "docs" / "case-file.md";

TEST(CaseFile, FullCaseReadsBack) {
    const CaseConfig c = parse_case_text(kFullCase);
    EXPECT_EQ(c.name, "channel");
    EXPECT_EQ(c.x.start, -1.0);
    EXPECT_EQ(c.x.end, 3.0);
    EXPECT_EQ(c.x.cells, 80);
    EXPECT_EQ(c.x.spacing, "uniform");
    EXPECT_EQ(c.y.cells, 40);
    EXPECT_EQ(c.y.spacing, "tanh");
    EXPECT_EQ(c.y.beta, 1.5);
    EXPECT_EQ(c.depth, 0.5);
    EXPECT_EQ(c.density, 998.0);
    EXPECT_EQ(c.viscosity, 1.0e-3);
    EXPECT_EQ(c.body_force, (std::array<double, 2>{0.0, -9.81}));
    EXPECT_EQ(c.initial, InitialCondition::uniform);
    EXPECT_EQ(c.initial_velocity, (std::array<double, 2>{0.5, 0.0}));

    const BoundaryConfig& left = c.boundary[0];
    EXPECT_EQ(left.type, BoundaryType::inflow);
    EXPECT_EQ(left.profile, InflowProfile::parabolic);
    EXPECT_EQ(left.peak, 1.5);
    EXPECT_EQ(c.boundary[1].type, BoundaryType::outflow);
    EXPECT_EQ(c.boundary[1].outflow, OutflowKind::zero_stress);
    EXPECT_EQ(c.boundary[2].type, BoundaryType::wall);
    EXPECT_EQ(c.boundary[2].velocity, (std::array<double, 2>{0.0, 0.0}));
    EXPECT_EQ(c.boundary[3].type, BoundaryType::wall);
    EXPECT_EQ(c.boundary[3].velocity, (std::array<double, 2>{0.25, 0.0}));

    EXPECT_EQ(c.convection, ConvectionScheme::koren);
    EXPECT_EQ(c.cfl, 0.4);
    EXPECT_EQ(c.diffusion_number, 0.25);
    ASSERT_TRUE(c.fixed_dt.has_value());
    EXPECT_EQ(*c.fixed_dt, 1.0e-3);
    EXPECT_EQ(c.max_dt, 0.01);
    EXPECT_EQ(c.poisson_tolerance, 1.0e-10);
    EXPECT_EQ(c.poisson_max_iterations, 50);
    EXPECT_EQ(c.divergence_limit, 1.0e-4);
    EXPECT_EQ(c.end_time, 2.5);
    EXPECT_EQ(c.max_steps, 1000);
    EXPECT_EQ(c.ranks, (std::array<int, 2>{2, 1}));
    EXPECT_EQ(c.field_interval, 0.1);
    EXPECT_EQ(c.checkpoint_interval, 0.5);
    EXPECT_EQ(c.checkpoints_kept, 3);
    EXPECT_EQ(c.timeseries_every, 5);
    EXPECT_EQ(c.progress_interval, 0.0);
    ASSERT_EQ(c.probes.size(), 2u);
    EXPECT_EQ(c.probes[1], (std::array<double, 2>{2.0, 0.25}));
    EXPECT_FALSE(c.plots);
}

// What the schema gives a key left out must be what CaseConfig says it is.
TEST(CaseFile, DefaultsAgreeWithCaseConfig) {
    const CaseConfig c = parse_case_text(kMinimal);
    const CaseConfig d;
    EXPECT_EQ(c.name, d.name);
    EXPECT_EQ(c.x.spacing, d.x.spacing);
    EXPECT_EQ(c.x.beta, d.x.beta);
    EXPECT_EQ(c.x.ratio, d.x.ratio);
    EXPECT_EQ(c.depth, d.depth);
    EXPECT_EQ(c.density, d.density);
    EXPECT_EQ(c.body_force, d.body_force);
    EXPECT_EQ(c.initial, d.initial);
    EXPECT_EQ(c.initial_velocity, d.initial_velocity);
    EXPECT_EQ(c.taylor_green_amplitude, d.taylor_green_amplitude);
    EXPECT_EQ(c.boundary[0].velocity, d.boundary[0].velocity);
    EXPECT_EQ(c.boundary[0].profile, d.boundary[0].profile);
    EXPECT_EQ(c.boundary[0].outflow, d.boundary[0].outflow);
    EXPECT_EQ(c.convection, d.convection);
    EXPECT_EQ(c.max_steps, d.max_steps);
    EXPECT_EQ(c.cfl, d.cfl);
    EXPECT_EQ(c.diffusion_number, d.diffusion_number);
    EXPECT_EQ(c.fixed_dt, d.fixed_dt);
    EXPECT_EQ(c.max_dt, d.max_dt);
    EXPECT_EQ(c.poisson_tolerance, d.poisson_tolerance);
    EXPECT_EQ(c.poisson_max_iterations, d.poisson_max_iterations);
    EXPECT_EQ(c.divergence_limit, d.divergence_limit);
    EXPECT_EQ(c.ranks, d.ranks);
    EXPECT_EQ(c.field_interval, d.field_interval);
    EXPECT_EQ(c.checkpoint_interval, d.checkpoint_interval);
    EXPECT_EQ(c.checkpoints_kept, d.checkpoints_kept);
    EXPECT_EQ(c.timeseries_every, d.timeseries_every);
    EXPECT_EQ(c.progress_interval, d.progress_interval);
    EXPECT_EQ(c.probes, d.probes);
    EXPECT_EQ(c.plots, d.plots);
}

TEST(CaseFile, ExplicitLinesGiveStartEndAndCells) {
    const CaseConfig c = parse_case_text(
        minimal_with("x: {start: 0, end: 1, cells: 8}", "x: {spacing: lines, lines: [0, 0.1, 0.3, 1]}"));
    EXPECT_EQ(c.x.spacing, "lines");
    EXPECT_EQ(c.x.lines, (std::vector<double>{0.0, 0.1, 0.3, 1.0}));
    EXPECT_EQ(c.x.start, 0.0);
    EXPECT_EQ(c.x.end, 1.0);
    EXPECT_EQ(c.x.cells, 3);
}

TEST(CaseFile, LoadReadsFileAndNamesRunAfterIt) {
    const auto path = temp_case("cavity", kMinimal);
    const CaseConfig c = load_case(path);
    EXPECT_EQ(c.name, path.stem().string());
    EXPECT_EQ(c.x.cells, 8);
    std::filesystem::remove(path);
}

TEST(CaseFile, SetOverridesKeyInFile) {
    const CaseConfig c = parse_case_text(kMinimal, {"domain.x.cells=64", "boundaries.top.velocity=[2, 0]"});
    EXPECT_EQ(c.x.cells, 64);
    EXPECT_EQ(c.y.cells, 8);  // siblings untouched
    EXPECT_EQ(c.x.end, 1.0);
    EXPECT_EQ(c.boundary[3].velocity, (std::array<double, 2>{2.0, 0.0}));
}

TEST(CaseFile, SetAddsKeyAbsentFromFile) {
    const CaseConfig c = parse_case_text(
        kMinimal, {"numerics.poisson.tolerance=1e-6", "numerics.dt=0.01", "output.probes=[[0.5, 0.5]]", "name=run2"});
    EXPECT_EQ(c.poisson_tolerance, 1e-6);
    ASSERT_TRUE(c.fixed_dt.has_value());
    EXPECT_EQ(*c.fixed_dt, 0.01);
    ASSERT_EQ(c.probes.size(), 1u);
    EXPECT_EQ(c.name, "run2");
}

TEST(CaseFile, SetReplacesWholeSection) {
    const CaseConfig c = parse_case_text(kMinimal, {"boundaries.top={type: slip}"});
    EXPECT_EQ(c.boundary[3].type, BoundaryType::slip);
}

TEST(CaseFile, SetUnknownKeyIsRejected) {
    expect_message(error_of(kMinimal, {"fluid.viscosty=1e-3"}),
                   {"--set fluid.viscosty=1e-3", "fluid.viscosty", "unknown key", "fluid.viscosity"});
    expect_message(error_of(kMinimal, {"domain.x.cells.n=3"}), {"domain.x.cells", "no sub-keys"});
    expect_message(error_of(kMinimal, {"domain.x.cells"}), {"key.path=value"});
}

TEST(CaseFile, SetValueIsValidated) {
    expect_message(error_of(kMinimal, {"fluid.density=-5"}),
                   {"--set fluid.density=-5", "fluid.density", "must be > 0, got -5"});
}

TEST(CaseFile, UnknownKeySuggestsNearest) {
    expect_message(error_of(minimal_with("viscosity:", "viscosty:")),
                   {"line 5", "fluid.viscosty", "unknown key", "did you mean 'fluid.viscosity'"});
    // A key in the wrong section points to where it belongs.
    expect_message(error_of(minimal_with("time:\n", "time:\n  cfl: 0.3\n")),
                   {"time.cfl", "unknown key", "numerics.cfl"});
    // Nothing near: the keys allowed there are listed.
    expect_message(error_of(minimal_with("time:\n", "time:\n  zzzzzz: 1\n")),
                   {"time.zzzzzz", "unknown key", "keys in time: end, max_steps"});
}

TEST(CaseFile, WrongType) {
    expect_message(error_of(minimal_with("viscosity: 0.01", "viscosity: abc")),
                   {"line 5", "fluid.viscosity", "expected a number, got 'abc'"});
    expect_message(error_of(minimal_with("cells: 8}\n  y", "cells: 8.5}\n  y")),
                   {"line 2", "domain.x.cells", "expected an integer, got '8.5'"});
    expect_message(error_of(minimal_with("velocity: [1, 0]", "velocity: [1, up]")),
                   {"boundaries.top.velocity[1]", "expected a number, got 'up'"});
    expect_message(error_of(minimal_with("fluid:\n", "fluid:\n  density: [1, 2]\n")),
                   {"fluid.density", "expected a number, got a list"});
    expect_message(error_of(minimal_with("fluid:\n  viscosity: 0.01", "fluid: 3")), {"fluid", "expected a mapping"});
}

TEST(CaseFile, NegativeDensity) {
    expect_message(error_of(minimal_with("fluid:\n", "fluid:\n  density: -3\n")),
                   {"line 5", "fluid.density", "must be > 0, got -3"});
}

TEST(CaseFile, CellsBelowTwo) {
    expect_message(error_of(minimal_with("cells: 8}\n  y", "cells: 0}\n  y")),
                   {"line 2", "domain.x.cells", "must be >= 2, got 0"});
}

TEST(CaseFile, RangeWithBothBoundsAndSpecialValue) {
    expect_message(error_of(kMinimal, {"numerics.cfl=1.5"}), {"numerics.cfl", "must be in (0, 1], got 1.5"});
    expect_message(error_of(kMinimal, {"time.max_steps=0"}), {"time.max_steps", "must be -1 or >= 1, got 0"});
    EXPECT_EQ(parse_case_text(kMinimal, {"time.max_steps=-1"}).max_steps, -1);
}

TEST(CaseFile, WrongListLength) {
    expect_message(error_of(minimal_with("velocity: [1, 0]", "velocity: [1, 0, 0]")),
                   {"line 10", "boundaries.top.velocity", "expected a list of 2 numbers, got 3 items"});
}

TEST(CaseFile, InvalidChoice) {
    expect_message(error_of(minimal_with("top: {type: wall", "top: {type: wal")),
                   {"line 10", "boundaries.top.type", "invalid choice 'wal'", "wall, slip, inflow, outflow, periodic",
                    "did you mean 'wall'"});
}

TEST(CaseFile, MissingRequiredKey) {
    expect_message(error_of(minimal_with("  viscosity: 0.01\n", "  density: 1.0\n")),
                   {"fluid.viscosity", "missing required key"});
    expect_message(error_of(minimal_with("  top: {type: wall, velocity: [1, 0]}\n", "")),
                   {"boundaries.top", "missing required key"});
    expect_message(error_of(minimal_with("time:\n  end: 1.0\n", "")), {"time", "missing required key"});
    expect_message(error_of(minimal_with("cells: 8}\n  y", "cells: 8, spacing: lines}\n  y")),
                   {"domain.x.start", "not used when spacing is 'lines'"});
    expect_message(error_of(minimal_with("x: {start: 0, end: 1, cells: 8}", "x: {spacing: lines}")),
                   {"domain.x.lines", "missing required key", "needed when spacing is 'lines'"});
}

TEST(CaseFile, KeyOnlyForAnotherChoice) {
    expect_message(error_of(kMinimal, {"initial.amplitude=2"}),
                   {"initial.amplitude", "not used when type is 'uniform'", "only with type: taylor_green"});
    expect_message(error_of(minimal_with("top: {type: wall, velocity: [1, 0]}", "top: {type: slip, velocity: [1, 0]}")),
                   {"line 10", "boundaries.top.velocity", "not used when type is 'slip'"});
    expect_message(error_of(minimal_with("right: {type: wall}", "right: {type: wall, kind: convective}")),
                   {"boundaries.right.kind", "only with type: outflow"});
}

TEST(CaseFile, UnpairedPeriodic) {
    expect_message(
        error_of(minimal_with("left: {type: wall}", "left: {type: periodic}")),
        {"line 7", "boundaries.left.type", "pairs", "boundaries.right.type must be periodic too, got 'wall'"});
    const CaseConfig c = parse_case_text(kMinimal, {"boundaries.left.type=periodic", "boundaries.right.type=periodic"});
    EXPECT_EQ(c.boundary[0].type, BoundaryType::periodic);
}

TEST(CaseFile, WallNormalVelocity) {
    expect_message(error_of(minimal_with("velocity: [1, 0]", "velocity: [1, 0.5]")),
                   {"line 10", "boundaries.top.velocity", "normal component velocity[1] must be 0", "got 0.5"});
    expect_message(error_of(minimal_with("left: {type: wall}", "left: {type: wall, velocity: [1, 0]}")),
                   {"boundaries.left.velocity", "normal component velocity[0] must be 0"});
}

TEST(CaseFile, InflowChecks) {
    const std::string inflow = minimal_with("left: {type: wall}", "left: {type: inflow, velocity: [1, 0]}");
    expect_message(error_of(inflow), {"boundaries.left.type", "needs an outflow"});
    EXPECT_NO_THROW(parse_case_text(inflow, {"boundaries.right={type: outflow}"}));
    expect_message(error_of(inflow, {"boundaries.right={type: outflow}", "boundaries.left.velocity=[-1, 0]"}),
                   {"boundaries.left.velocity", "must enter the domain", "velocity[0] must be >= 0"});
    expect_message(error_of(inflow, {"boundaries.right={type: outflow}", "boundaries.left.profile=parabolic"}),
                   {"boundaries.left.peak", "missing required key"});
}

TEST(CaseFile, ProbeOutsideDomain) {
    expect_message(error_of(kMinimal, {"output.probes=[[0.5, 0.5], [1.5, 0.5]]"}),
                   {"output.probes[1]", "[1.5, 0.5] lies outside the domain [0, 1] x [0, 1]"});
}

TEST(CaseFile, AxisChecks) {
    expect_message(error_of(minimal_with("x: {start: 0, end: 1", "x: {start: 2, end: 1")),
                   {"line 2", "domain.x.end", "must be greater than domain.x.start (2), got 1"});
    expect_message(
        error_of(minimal_with("x: {start: 0, end: 1, cells: 8}", "x: {spacing: lines, lines: [0, 0.5, 0.4, 1]}")),
        {"domain.x.lines[2]", "strictly increasing, got 0.4 after 0.5"});
    expect_message(error_of(minimal_with("x: {start: 0, end: 1, cells: 8}", "x: {spacing: lines, lines: [0, 1]}")),
                   {"domain.x.lines", "at least 3 lines"});
}

// Found by the case fuzz (test_case_fuzz.cpp): a grid of more cells than memory holds was accepted, and a
// clustered axis made its lines while being read (ratio 1 across a long domain, or a huge core_cells: the
// reader threw std::bad_alloc or the process was killed); the grid is now counted before anything is made.
TEST(CaseFile, GridBeyondTheCellLimitIsRejectedBeforeItIsMade) {
    expect_message(error_of(kMinimal, {"domain.x.cells=10000000", "domain.y.cells=64"}),
                   {"domain.x.cells", "10000000 x 64", "domain.y.cells", "at most 1e+08"});
    expect_message(error_of(kMinimal, {"domain.y.cells=2147483647"}), {"domain.y.cells", "8 x 2147483647"});
    const std::string clustered = "domain.x={start: 0, end: 1, spacing: clustered, core: [0.4, 0.6], ";
    expect_message(error_of(kMinimal, {clustered + "core_cells: 2147483647}"}),
                   {"domain.x.core_cells", "at most 1e+08"});
    expect_message(error_of(kMinimal, {"domain.x={start: 0, end: 1e300, spacing: clustered, core: [0.4, 0.6], "
                                       "core_cells: 10, ratio: 1}"}),
                   {"domain.x.core_cells", "growing by ratio 1"});
    EXPECT_EQ(parse_case_text(kMinimal, {clustered + "core_cells: 10, ratio: 1}"}).x.cells, 50);
    // A window clustered towards its ends: first cells that do not fit, a cap below them.
    expect_message(error_of(kMinimal, {clustered + "core_cells: 10, first: 0.05}"}),
                   {"domain.x.first", "cannot be clustered", "core_cells"});
    expect_message(error_of(kMinimal, {clustered + "core_cells: 10, first: 0.005, max: 0.001}"}),
                   {"domain.x.max", "at least"});
    EXPECT_GT(parse_case_text(kMinimal, {clustered + "core_cells: 10, first: 0.005, ratio: 1.1, max: 0.05}"}).x.cells,
              10);
}

// domain.refinement scales a grid as a convergence study does: f times the cells each way, and a stretched axis keeps
// its shape (ratio^(1/f): f refined cells grow as much as one did), so its lines are the coarse grid's lines with
// cells between them.
TEST(CaseFile, RefinementScalesTheGridAndKeepsItsShape) {
    const std::string clustered =
        "domain.x={start: -3, end: 3, spacing: clustered, core: [-0.5, 0.5], "
        "core_cells: 10, ratio: 1.21, max: 0.4}";
    const FlowConfig coarse = parse_case_text(kMinimal, {clustered, "domain.y={start: 0, end: 1, cells: 8}"});
    const FlowConfig fine =
        parse_case_text(kMinimal, {clustered, "domain.y={start: 0, end: 1, cells: 8}", "domain.refinement=2"});
    EXPECT_EQ(fine.y.cells, 16);
    EXPECT_EQ(fine.x.core_cells, 20);
    EXPECT_DOUBLE_EQ(fine.x.ratio, 1.1);
    EXPECT_DOUBLE_EQ(fine.x.max_width, 0.2);
    const std::vector<double> a = axis_lines(coarse.x), b = axis_lines(fine.x);
    EXPECT_NEAR(static_cast<double>(fine.x.cells), 2.0 * coarse.x.cells, 2.0);
    EXPECT_DOUBLE_EQ(b.front(), -3.0);
    EXPECT_DOUBLE_EQ(b.back(), 3.0);
    // The window's lines fall on every other fine line; outside, the fine cells are half as wide as the coarse
    // ones at the same place (to a cell's growth, 10 %).
    const auto window_start = [](const std::vector<double>& l) {
        return static_cast<std::size_t>(std::lower_bound(l.begin(), l.end(), -0.5 - 1e-12) - l.begin());
    };
    for (std::size_t k = 0; k <= 10; ++k)
        EXPECT_NEAR(b[window_start(b) + 2 * k], a[window_start(a) + k], 1e-12) << "window line " << k;
    for (std::size_t k = 1; k + 1 < a.size(); ++k) {
        const double x = 0.5 * (a[k - 1] + a[k]);
        const auto j = static_cast<std::size_t>(std::upper_bound(b.begin(), b.end(), x) - b.begin());
        EXPECT_NEAR(b[j] - b[j - 1], 0.5 * (a[k] - a[k - 1]), 0.1 * (a[k] - a[k - 1])) << "coarse cell " << k;
    }
    const FlowConfig half = parse_case_text(kMinimal, {"domain.x.cells=31", "domain.refinement=0.5"});
    EXPECT_EQ(half.x.cells, 16);  // rounded
    expect_message(error_of(kMinimal, {"domain.x={spacing: lines, lines: [0, 0.5, 1]}", "domain.refinement=2"}),
                   {"domain.refinement", "domain.x", "listed one by one"});
    expect_message(error_of(kMinimal, {"domain.refinement=0"}), {"domain.refinement"});
}

// Found by the case fuzz: lines that a strong stretching makes equal in double precision (tanh beta 1e300,
// geometric ratio 1e300) or a length that overflows were accepted, and the solver stopped with
// std::invalid_argument ("grid lines must increase strictly", exit code 1).
TEST(CaseFile, GridLinesThatDoNotIncreaseAreRejected) {
    expect_message(error_of(kMinimal, {"domain.x={start: 0, end: 1, cells: 100, spacing: tanh, beta: 1e300}"}),
                   {"domain.x.beta", "spacing 'tanh' with 100 cells do not increase strictly"});
    expect_message(error_of(kMinimal, {"domain.y={start: 0, end: 1, cells: 100, spacing: geometric, ratio: 1e300}"}),
                   {"domain.y.ratio", "do not increase strictly"});
    expect_message(error_of(minimal_with("x: {start: 0, end: 1", "x: {start: -1e308, end: 1e308")),
                   {"line 2", "domain.x.end", "beyond the largest number"});
}

// Found with the fuzz's extreme values: the name '..' was read, and the results went to results/.. (the
// working folder); a name with a NUL byte made a path cut short at it.
TEST(CaseFile, NameThatCannotNameAFolderIsRejected) {
    expect_message(error_of(kMinimal, {"name=.."}), {"--set name=..", "name: must not be '.' or '..'"});
    expect_message(error_of(kMinimal + "name: \"run\\0two\"\n"), {"line 13", "name: must not contain control"});
    EXPECT_EQ(parse_case_text(kMinimal, {"name=run.2"}).name, "run.2");
}

// Found by the case fuzz: a '---' line in a case starts a second YAML document, and the reader read the first
// only: the keys after it were dropped without a word (here output.plots: the run would have made its plots),
// or a section after it was reported missing though written in the file.
TEST(CaseFile, SecondYamlDocumentIsRejected) {
    expect_message(error_of(kMinimal + "---\noutput: {plots: false}\n"),
                   {"line 14", "a case is one YAML document, but a '---' line starts another one here"});
    // One document, opened by '---' and closed by '...', or followed by an empty one, is still one.
    EXPECT_EQ(parse_case_text("---\n" + kMinimal + "...\n").end_time, 1.0);
    EXPECT_EQ(parse_case_text(kMinimal + "---\n").end_time, 1.0);
}

TEST(CaseFile, DuplicateKey) {
    expect_message(error_of(minimal_with("time:\n  end: 1.0\n", "time:\n  end: 1.0\n  end: 2.0\n")),
                   {"line 13", "time.end", "given twice (first on line 12)"});
}

TEST(CaseFile, YamlSyntaxError) {
    expect_message(error_of(minimal_with("velocity: [1, 0]}", "velocity: [1, 0}")), {"line 10", "YAML syntax error"});
    const auto path = temp_case("broken", minimal_with("  viscosity: 0.01\n", "  viscosity: 0.01\n   density: 3\n"));
    try {
        load_case(path);
        ADD_FAILURE() << "no CaseError";
    } catch (const CaseError& e) {
        expect_message(e.what(), {path.string() + ", line 6", "YAML syntax error"});
    }
    std::filesystem::remove(path);
}

TEST(CaseFile, MissingFile) {
    try {
        load_case("/nonexistent/dir/cavity.yaml");
        ADD_FAILURE() << "no CaseError";
    } catch (const CaseError& e) {
        expect_message(e.what(), {"/nonexistent/dir/cavity.yaml", "not found"});
    }
}

TEST(CaseFile, ErrorsInFileNameFileAndLine) {
    const auto path = temp_case("bad_density", minimal_with("fluid:\n", "fluid:\n  density: -3\n"));
    try {
        load_case(path);
        ADD_FAILURE() << "no CaseError";
    } catch (const CaseError& e) {
        expect_message(e.what(), {path.string() + ", line 5: fluid.density: must be > 0, got -3"});
    }
    std::filesystem::remove(path);
}

TEST(CaseFile, DocListsEveryKey) {
    const std::string doc = read_text(kDoc);
    ASSERT_FALSE(doc.empty()) << "cannot read " << kDoc;
    for (const CaseKey& key : case_schema())
        EXPECT_NE(doc.find("`" + std::string(key.path) + "`"), std::string::npos)
            << kDoc << " does not list `" << key.path << "`";
}

// The key table in the documentation is exactly the one the schema generates.
TEST(CaseFile, DocTableIsCurrent) {
    const std::string doc = read_text(kDoc);
    const std::string begin = "<!-- BEGIN GENERATED KEY TABLE -->\n", end = "<!-- END GENERATED KEY TABLE -->";
    const std::size_t b = doc.find(begin), e = doc.find(end);
    ASSERT_NE(b, std::string::npos) << kDoc << " lacks " << begin;
    ASSERT_NE(e, std::string::npos) << kDoc << " lacks " << end;
    const std::string table = doc.substr(b + begin.size(), e - b - begin.size());
    if (table != schema_markdown()) {
        const auto updated = std::filesystem::current_path() / "case-file.md";
        std::ofstream(updated) << doc.substr(0, b + begin.size()) << schema_markdown() << doc.substr(e);
        ADD_FAILURE() << "the key table in " << kDoc << " differs from schema_markdown(); updated doc written to "
                      << updated << ": cp " << updated << " " << kDoc;
    }
}

TEST(CaseFile, DocExampleParses) {
    const std::string doc = read_text(kDoc);
    const std::string marker = "<!-- FULL EXAMPLE -->\n```yaml\n";
    const std::size_t b = doc.find(marker);
    ASSERT_NE(b, std::string::npos) << kDoc << " lacks the full example";
    const std::size_t start = b + marker.size(), stop = doc.find("```", start);
    const CaseConfig c = parse_case_text(doc.substr(start, stop - start));
    EXPECT_EQ(c.name, "cavity_re100");
}

// ---- immersed bodies ----

TEST(CaseFile, BodiesReadBackWithUnitsConverted) {
    const CaseConfig c = parse_case_text(kMinimal + R"(bodies:
  block:
    shape: rectangle
    centre: [0.5, 0.6]
    size: [0.2, 0.1]
    angle: 90
    motion: {type: oscillation, amplitude: [-0.1, 0], frequency: 2, phase: 90}
  bed:
    shape: plane
    point: [0.5, 0.1]
    angle: 30
)");
    ASSERT_EQ(c.bodies.size(), 2u);
    // Sections are read in name order.
    EXPECT_EQ(c.bodies[0].name, "bed");
    EXPECT_EQ(c.bodies[0].shape, BodyShape::plane);
    EXPECT_NEAR(c.bodies[0].angle, M_PI / 6, 1e-15);
    const BodyConfig& b = c.bodies[1];
    EXPECT_EQ(b.name, "block");
    EXPECT_EQ(b.shape, BodyShape::rectangle);
    EXPECT_NEAR(b.angle, M_PI / 2, 1e-15);
    EXPECT_EQ(b.motion.type, MotionType::oscillation);
    EXPECT_EQ(b.motion.amplitude[0], -0.1);
    EXPECT_NEAR(b.motion.phase, M_PI / 2, 1e-15);
    // Reference length defaults to the extent across x: the rotated rectangle is 0.2 high.
    EXPECT_NEAR(b.reference_length, 0.2, 1e-12);
    EXPECT_EQ(b.reference_velocity, 1.0);
    EXPECT_EQ(c.ibm.kernel, DeltaKernel::roma3_smoothed);
    EXPECT_EQ(c.ibm.forcing_iterations, 10);
    EXPECT_EQ(c.ibm.retraction, 0.43);
}

TEST(CaseFile, BodyErrorsNameTheKey) {
    const std::string circle = "bodies:\n  cyl:\n    shape: circle\n    centre: [0.5, 0.5]\n    diameter: 0.2\n";
    EXPECT_NO_THROW(parse_case_text(kMinimal + circle));
    // A body that reaches outside the domain.
    expect_message(error_of(kMinimal + circle, {"bodies.cyl.centre=[0.95, 0.5]"}),
                   {"bodies.cyl.centre", "outside the domain", "point [1.05, "});
    // A key of another shape.
    expect_message(error_of(kMinimal + circle + "    size: [1, 1]\n"),
                   {"bodies.cyl.size", "not used when shape is 'circle'"});
    // A typo inside a body.
    expect_message(error_of(kMinimal + circle + "    diametre: 0.2\n"),
                   {"bodies.cyl.diametre", "unknown key", "did you mean 'bodies.cyl.diameter'"});
    // A missing key.
    expect_message(error_of(kMinimal + "bodies:\n  cyl:\n    shape: circle\n    centre: [0.5, 0.5]\n"),
                   {"bodies.cyl.diameter", "missing required key"});
    // A plane cannot move; an oscillation needs its frequency.
    expect_message(error_of(kMinimal + "bodies:\n  bed: {shape: plane, point: [0.5, 0.1], motion: {type: "
                                       "constant_velocity}}\n"),
                   {"bodies.bed.motion.type", "planes and segments are fixed"});
    expect_message(error_of(kMinimal + circle + "    motion: {type: oscillation}\n"),
                   {"bodies.cyl.motion.frequency", "missing required key"});
    expect_message(error_of(kMinimal + circle, {"numerics.ibm.stress_probes=[2, 1]"}),
                   {"numerics.ibm.stress_probes", "second distance must be greater"});
}

// The surface-stress probes: 2.5, 3.5, 4.5 cells out by default (clear of the diffuse interface's smear), 1.5, 2.5, 3.5
// on the sharp interface (nothing to clear), and what the case gives either way.
TEST(CaseFile, StressProbesFollowTheInterfaceUnlessGiven) {
    const std::string circle = "bodies:\n  cyl: {shape: circle, centre: [0.5, 0.5], diameter: 0.25}\n";
    EXPECT_EQ(parse_case_text(kMinimal + circle).ibm.stress_probes, (std::vector<double>{2.5, 3.5, 4.5}));
    EXPECT_EQ(parse_case_text(kMinimal + circle, {"numerics.ibm.interface=sharp"}).ibm.stress_probes,
              (std::vector<double>{1.5, 2.5, 3.5}));
    EXPECT_EQ(parse_case_text(kMinimal + circle, {"numerics.ibm.interface=sharp", "numerics.ibm.stress_probes=[2, 3]"})
                  .ibm.stress_probes,
              (std::vector<double>{2.0, 3.0}));
}

TEST(CaseFile, FreeBodyKeysAndErrors) {
    const std::string block = "bodies:\n  block:\n    shape: rectangle\n    centre: [0.5, 0.5]\n    size: [0.2, 0.2]\n";
    const CaseConfig c = parse_case_text(kMinimal + block +
                                         "    density: 2500\n    motion: {type: free, lock_rotation: "
                                         "true, velocity: [0, -1]}\ncontact: {law: impulse, distance: 0.01}\n");
    EXPECT_EQ(c.bodies[0].motion.type, MotionType::free);
    EXPECT_EQ(c.bodies[0].density, 2500.0);
    EXPECT_EQ(c.bodies[0].motion.locked, (std::array<bool, 3>{false, false, true}));
    EXPECT_EQ(c.bodies[0].motion.velocity[1], -1.0);
    EXPECT_EQ(c.contact.law, ReboundLaw::impulse);
    EXPECT_EQ(c.contact.distance, 0.01);
    EXPECT_EQ(c.contact.normal_restitution, 0.8);  // Turmel & Locat's value is the default
    EXPECT_EQ(c.gravity[1], -9.81);
    expect_message(error_of(kMinimal + block + "    motion: {type: free}\n"),
                   {"bodies.block.density", "a free body needs its density"});
    expect_message(error_of(kMinimal + block + "    density: 2500\n"), {"bodies.block.density", "only free bodies"});
    expect_message(error_of(kMinimal + block + "    density: -1\n    motion: {type: free}\n"),
                   {"bodies.block.density"});
    expect_message(error_of(kMinimal + block + "    motion: {type: fixed, lock_x: true}\n"),
                   {"bodies.block.motion.lock_x"});
    expect_message(error_of(kMinimal + block, {"contact.normal_restitution=1.5"}), {"contact.normal_restitution"});
}

}  // namespace
}  // namespace chute
