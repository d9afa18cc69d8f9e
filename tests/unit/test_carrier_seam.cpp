// The carrier seam (body/carrier.hpp): a second way of carrying bodies, defined in this file only, runs
// through run_simulation, free-body dynamics, contact, k-epsilon and the outputs with nothing changed in
// run/, rigidbody/, contact/ or turbulence/ beyond registering it (run/carriers.hpp).
//
// The test carrier is a staircase volume forcing: every velocity face whose point lies inside a body takes the
// body's velocity before the projection; no Lagrangian markers, no delta kernels, no surface stress. Its
// hydrodynamic wrench is the momentum it imposed plus the change of the momentum inside the body (the same
// balance as Uhlmann 2005 eq. 23, on faces instead of markers).
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>

#include "carriers.hpp"
#include "case_file.hpp"
#include "csv_column.hpp"
#include "simulation.hpp"

using namespace chute;
namespace fs = std::filesystem;

namespace {

class StaircaseCarrier final : public Carrier {
public:
    StaircaseCarrier(const Grid& grid, const CaseConfig& c, std::vector<Body>& bodies)
        : grid_(grid),
          rho_(c.density),
          depth_(c.depth),
          bodies_(bodies),
          fluid_(grid, 1.0),
          rate_(bodies.size(), Vec2::Zero()),
          start_(bodies.size(), Vec2::Zero()),
          wrench_(bodies.size()) {}

    const std::vector<Body>& bodies() const override { return bodies_; }
    double cell_size(std::size_t) const override { return std::min(grid_.x_axis().width(0), grid_.y_axis().width(0)); }
    void begin_step(const Velocity& start) override {
        for (std::size_t b = 0; b < bodies_.size(); ++b) {
            start_[b] = momentum_inside(start, b);
            rate_[b] = Vec2::Zero();
        }
    }
    void place(double t) override {
        for (Body& b : bodies_) b.move_to(t);
    }
    void impose(Velocity& star, double dt) override {
        ++imposed;
        for (std::size_t b = 0; b < bodies_.size(); ++b) {
            Vec2 sum = Vec2::Zero();
            each_face_inside(b, [&](bool is_u, int i, int j, const Vec2& X, double volume) {
                const Vec2 U = bodies_[b].velocity_at(X);
                double& u = is_u ? star.u(i, j) : star.v(i, j);
                sum[is_u ? 0 : 1] += ((is_u ? U.x() : U.y()) - u) * volume;
                u = is_u ? U.x() : U.y();
            });
            MPI_Allreduce(MPI_IN_PLACE, sum.data(), 2, MPI_DOUBLE, MPI_SUM, grid_.comm());
            rate_[b] += sum / dt;  // summed over the passes of a strongly coupled step
        }
    }
    Wrench hydrodynamic_wrench(std::size_t b, const Velocity& vel, double dt) override {
        wrench_[b].force = rho_ * depth_ * (-rate_[b] + (momentum_inside(vel, b) - start_[b]) / dt);
        return wrench_[b];
    }
    std::vector<BodyForces> measure(const Velocity&, const Field2D&, const WallTurbulence*) override {
        std::vector<BodyForces> out(bodies_.size());
        for (std::size_t b = 0; b < bodies_.size(); ++b)
            out[b].forcing = bodies_[b].free() ? wrench_[b].force : Vec2(-rho_ * depth_ * rate_[b]);
        return out;
    }
    void locate_walls() override {
        const auto& X = grid_.lx();
        const auto& Y = grid_.ly();
        for (int j = -kGhost; j < grid_.ny() + kGhost; ++j)
            for (int i = -kGhost; i < grid_.nx() + kGhost; ++i) {
                const Vec2 x(X.c(i), Y.c(j));
                fluid_(i, j) =
                    std::none_of(bodies_.begin(), bodies_.end(), [&](const Body& b) { return b.contains(x); });
            }
    }
    const Field2D& fluid_cells() const override { return fluid_; }
    std::vector<WallSample> sample_walls(const Velocity&, const Field2D&) const override { return {}; }

    static inline int imposed = 0;

private:
    template <class Visit>
    void each_face_inside(std::size_t b, Visit&& visit) const {
        const auto& X = grid_.lx();
        const auto& Y = grid_.ly();
        for (int j = 0; j < grid_.ny(); ++j)
            for (int i = 0; i < grid_.nx(); ++i) {
                const Vec2 pu(X.f(i), Y.c(j)), pv(X.c(i), Y.f(j));
                if (bodies_[b].contains(pu)) visit(true, i, j, pu, X.dc(i) * Y.w(j));
                if (bodies_[b].contains(pv)) visit(false, i, j, pv, X.w(i) * Y.dc(j));
            }
    }
    Vec2 momentum_inside(const Velocity& vel, std::size_t b) const {
        Vec2 sum = Vec2::Zero();
        each_face_inside(b, [&](bool is_u, int i, int j, const Vec2&, double volume) {
            sum[is_u ? 0 : 1] += (is_u ? vel.u(i, j) : vel.v(i, j)) * volume;
        });
        MPI_Allreduce(MPI_IN_PLACE, sum.data(), 2, MPI_DOUBLE, MPI_SUM, grid_.comm());
        return sum;
    }

    const Grid& grid_;
    double rho_, depth_;
    std::vector<Body>& bodies_;
    Field2D fluid_;
    std::vector<Vec2> rate_, start_;
    std::vector<Wrench> wrench_;
};

// A disc twice as dense as water released in a closed 1 m box, rotation locked, with k-epsilon on (the
// turbulence model asks the test carrier which cells are fluid), and a prescribed disc crossing at 0.1 m/s.
const char* kTwoDiscs = R"(
name: staircase
domain:
  x: {start: 0.0, end: 1.0, cells: 64}
  y: {start: 0.0, end: 1.0, cells: 64}
fluid: {density: 1000.0, viscosity: 1.0e-3}
boundaries: {left: {type: wall}, right: {type: wall}, bottom: {type: wall}, top: {type: wall}}
bodies:
  falling: {shape: circle, centre: [0.3, 0.6], diameter: 0.2, density: 2000.0,
            motion: {type: free, lock_rotation: true}}
  crossing: {shape: circle, centre: [0.75, 0.5], diameter: 0.1, motion: {type: constant_velocity, velocity: [-0.1, 0.0]}}
turbulence: {model: k_epsilon, velocity_scale: 0.5}
numerics: {max_dt: 0.002}
time: {end: 0.1}
output: {plots: false}
)";

// Last data row of a CSV file as numbers, and the number of data rows.
std::pair<std::vector<double>, int> last_row(const fs::path& file) {
    std::ifstream in(file);
    std::string line, last;
    int rows = -1;  // the header
    while (std::getline(in, line))
        if (!line.empty()) last = line, ++rows;
    std::vector<double> values;
    std::stringstream s(last);
    for (std::string cell; std::getline(s, cell, ',');) values.push_back(std::stod(cell));
    return {values, rows};
}

// The sum of a column of a CSV file with a header.
double column_sum(const fs::path& file, const std::string& name) {
    const std::vector<double> values = csv_column(file, name);
    return std::accumulate(values.begin(), values.end(), 0.0);
}

}  // namespace

TEST(CarrierSeam, UnknownCarrierNamesTheKnownOnes) {
    const CaseConfig c = parse_case_text(kTwoDiscs);
    RunOptions options;
    options.quiet = true;
    options.carrier = "body_fitted_someday";
    try {
        run_simulation(c, options, MPI_COMM_WORLD);
        ADD_FAILURE() << "no error";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("immersed"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("body_fitted_someday"), std::string::npos) << e.what();
    }
}

// The run goes through every stage with the test carrier: it imposes the bodies every step, the free disc
// falls under gravity, buoyancy and the carrier's wrench, the outputs are written. Physics check on the
// wrench: the disc's added mass must show. Buoyancy alone gives a = (1 - rho_f/rho_s) g = 4.905 m/s^2; any
// added-mass coefficient C_a >= 0.5 (a circle in open water has 1, more in a box) gives a <= 3.92, 80 % of it.
TEST(CarrierSeam, ATestCarrierRunsTheWholeLoop) {
    register_carrier("staircase", [](const Grid& g, const CaseConfig& c, std::vector<Body>& b) {
        return std::make_unique<StaircaseCarrier>(g, c, b);
    });
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const fs::path dir = fs::temp_directory_path() / ("chute_test_carrier_np" + std::to_string(size));
    if (rank == 0) fs::remove_all(dir);
    MPI_Barrier(MPI_COMM_WORLD);
    RunOptions options;
    options.quiet = true;
    options.carrier = "staircase";
    options.out_dir = dir;
    StaircaseCarrier::imposed = 0;
    const RunSummary s = run_simulation(parse_case_text(kTwoDiscs), options, MPI_COMM_WORLD);
    EXPECT_GT(s.steps, 10);
    // Every step imposes the bodies once per pass (the first step of a free body makes several, rigidbody/
    // free_bodies.hpp); the time series counts them.
    EXPECT_GT(StaircaseCarrier::imposed, s.steps);
    EXPECT_EQ(StaircaseCarrier::imposed, column_sum(dir / "timeseries.csv", "coupling_passes"));

    const auto [falling, rows] = last_row(dir / "body_falling.csv");
    EXPECT_EQ(rows, s.steps + 1);  // t = 0 and every step
    const double t = falling[0], x = falling[1], y = falling[2], u = falling[4], v = falling[5];
    const double a = -v / t, buoyancy_only = 0.5 * 9.81;
    if (rank == 0)
        std::printf(
            "staircase carrier: %ld steps, falling disc at t = %.3f s: y = %.4f m, v = %.4f m/s, mean "
            "acceleration %.3f m/s^2 (buoyancy alone %.3f)\n",
            s.steps, t, y, v, a, buoyancy_only);
    EXPECT_GT(a, 0.0);
    EXPECT_LT(a, 0.8 * buoyancy_only);
    EXPECT_LT(y, 0.6);
    EXPECT_NEAR(x, 0.3, 1e-3);  // straight down, up to the staircase's left-right asymmetry
    EXPECT_LT(std::abs(u), 0.05 * std::abs(v));

    const auto [crossing, crossing_rows] = last_row(dir / "body_crossing.csv");
    EXPECT_NEAR(crossing[1], 0.75 - 0.1 * t, 1e-12);  // placed by the carrier at every step
    EXPECT_EQ(crossing_rows, rows);
}
