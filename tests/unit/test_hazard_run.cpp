// The hazard analysis as a run (hazard/monte_carlo, hazard_statistics, hazard_case): the same seed gives the
// same trajectories on 1 and 2 ranks (compared under unit_np2), statistics that converge as N grows, and case
// files whose mistakes are named by key.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "calibration.hpp"
#include "calibration_range.hpp"
#include "case_reader.hpp"
#include "hazard_case.hpp"
#include "hazard_statistics.hpp"
#include "monte_carlo.hpp"

namespace chute {
namespace {

const std::filesystem::path kExample = std::filesystem::path(CHUTE_SOURCE_DIR) / "examples/fjord_wall";

HazardCase example(long trajectories, unsigned long long seed, double water_level) {
    HazardCase c = load_hazard_case(kExample / "case.yaml",
                                    {"trajectories=" + std::to_string(trajectories), "seed=" + std::to_string(seed),
                                     "water.level=" + std::to_string(water_level), "output.stations=50"});
    return c;
}

int world_rank() {
    int r = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
}

// The fjord example's trajectories, water and dry, are identical bit for bit on all ranks of MPI_COMM_WORLD and
// on one (MPI_COMM_SELF), and no block passes under the ground (the integrator throws if one does).
TEST(HazardRun, SameSeedSameTrajectoriesOnAnyNumberOfRanks) {
    for (double level : {0.0, -1000.0}) {
        const HazardCase c = example(600, 11, level);
        const HazardResults world = run_hazard(c, MPI_COMM_WORLD);
        if (world_rank() != 0) continue;
        const HazardResults self = run_hazard(c, MPI_COMM_SELF);
        ASSERT_EQ(world.outcomes.size(), 600u);
        ASSERT_EQ(self.outcomes.size(), 600u);
        for (std::size_t i = 0; i < 600; ++i) {
            EXPECT_EQ(world.outcomes[i].stop, self.outcomes[i].stop) << i;
            EXPECT_EQ(world.outcomes[i].time, self.outcomes[i].time) << i;
            EXPECT_EQ(world.outcomes[i].impacts, self.outcomes[i].impacts) << i;
            EXPECT_EQ(world.outcomes[i].end, TrajectoryEnd::rest) << i;
        }
        for (std::size_t j = 0; j < world.kinetic_energy.size(); ++j) {
            const double a = world.kinetic_energy[j], b = self.kinetic_energy[j];
            EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << j;
        }
        EXPECT_EQ(world.paths.size(), self.paths.size());
    }
}

// Another seed gives other trajectories; a seed is reproducible.
TEST(HazardRun, SeedsAreReproducibleAndDistinct) {
    if (world_rank() != 0) GTEST_SKIP() << "one rank is enough";
    const HazardResults a = run_hazard(example(50, 1, -1000.0), MPI_COMM_SELF);
    const HazardResults b = run_hazard(example(50, 1, -1000.0), MPI_COMM_SELF);
    const HazardResults c = run_hazard(example(50, 2, -1000.0), MPI_COMM_SELF);
    int same = 0;
    for (std::size_t i = 0; i < 50; ++i) {
        EXPECT_EQ(a.outcomes[i].stop, b.outcomes[i].stop);
        same += a.outcomes[i].stop == c.outcomes[i].stop ? 1 : 0;
    }
    EXPECT_EQ(same, 0);
}

// Percentiles converge as N grows: the spread of the dry example's 90th percentile of the stopping x over four
// seeds shrinks about as 1/sqrt(N) (N = 250 -> 4000: 4 times narrower expected; at least 2 times required, as
// four seeds estimate a spread to about +-40 %).
TEST(HazardRun, StoppingPercentilesConverge) {
    if (world_rank() != 0) GTEST_SKIP() << "one rank is enough";
    const auto spread = [](long n) {
        double lo = 1e300, hi = -1e300;
        for (unsigned long long seed = 1; seed <= 4; ++seed) {
            const HazardCase c = example(n, seed, -1000.0);
            const double p90 = summarize(c, run_hazard(c, MPI_COMM_SELF)).stop_p90;
            lo = std::min(lo, p90), hi = std::max(hi, p90);
        }
        return hi - lo;
    };
    const double coarse = spread(250), fine = spread(4000);
    std::printf("p90 stopping x spread over 4 seeds: N = 250: %.3f m, N = 4000: %.3f m\n", coarse, fine);
    EXPECT_LT(fine, coarse / 2.0);
}

TEST(HazardRun, PercentileIsNumpysDefault) {
    EXPECT_DOUBLE_EQ(percentile({1.0, 2.0, 3.0, 4.0}, 0.5), 2.5);
    EXPECT_DOUBLE_EQ(percentile({4.0, 1.0, 3.0, 2.0}, 0.9), 3.7);
    EXPECT_DOUBLE_EQ(percentile({1.0, NAN, 3.0}, 1.0), 3.0);
    EXPECT_TRUE(std::isnan(percentile({}, 0.5)));
}

// Mistakes in a hazard case: each is a CaseError naming the key.
std::string error_of(const std::string& yaml) {
    try {
        (void)hazard_case_from_text(yaml, kExample);
    } catch (const CaseError& e) {
        return e.what();
    }
    return "no error";
}

const std::string kGood =
    "profile: {points: [[0, 10], [10, 0], [30, 0]]}\n"
    "materials: {rock: {}}\n"
    "block: {size: {value: 0.3}}\n"
    "release: {x: {value: 1.0}}\n";

TEST(HazardRun, CaseMistakesNameTheKey) {
    EXPECT_EQ(error_of(kGood), "no error");
    const auto expect = [](const std::string& yaml, const std::string& key, const std::string& words) {
        const std::string e = error_of(yaml);
        EXPECT_NE(e.find(key), std::string::npos) << e;
        EXPECT_NE(e.find(words), std::string::npos) << e;
    };
    expect(kGood + "trajectorys: 10\n", "trajectorys", "unknown key");
    expect(
        "profile: {points: [[0, 10], [10, 0], [5, -1]]}\nmaterials: {rock: {}}\nblock: {size: {value: 0.3}}\n"
        "release: {x: {value: 1.0}}\n",
        "profile.points", "folds the profile back");
    expect(
        "profile: {points: [[0, 10], [10, 0]], file: profile.csv}\nmaterials: {rock: {}}\n"
        "block: {size: {value: 0.3}}\nrelease: {x: {value: 1.0}}\n",
        "profile", "either profile.points or profile.file");
    expect(
        "profile: {file: missing.csv}\nmaterials: {rock: {}}\nblock: {size: {value: 0.3}}\n"
        "release: {x: {value: 1.0}}\n",
        "profile.file", "missing.csv");
    expect(
        "profile: {file: profile.csv}\nmaterials: {rock: {}}\nblock: {size: {value: 0.3}}\n"
        "release: {x: {value: 1.0}}\n",
        "profile.file (row 22)", "unknown material 'talus'");
    expect(kGood + "block: {size: {value: 0.3}, density: {value: 900}}\n", "block", "given twice");
    expect(
        "profile: {points: [[0, 10], [10, 0], [30, 0]]}\nmaterials: {rock: {}}\nwater: {level: 5}\n"
        "block: {size: {value: 0.3}, density: {value: 900}}\nrelease: {x: {value: 1.0}}\n",
        "block.density", "floats");
    expect(
        "profile: {points: [[0, 10], [10, 0], [30, 0]]}\nmaterials: {rock: {}}\n"
        "block: {size: {distribution: normal, mean: 0.3, sd: 0.1}}\nrelease: {x: {value: 1.0}}\n",
        "block.size.min", "truncate it");
    expect(
        "profile: {points: [[0, 10], [10, 0], [30, 0]]}\nmaterials: {rock: {}}\n"
        "block: {size: {distribution: uniform, min: 0.5, max: 0.2}}\nrelease: {x: {value: 1.0}}\n",
        "block.size.max", "must be above");
    expect(
        "profile: {points: [[0, 10], [10, 0], [30, 0]]}\nmaterials: {rock: {}}\n"
        "block: {size: {distribution: normal, mean: 0.3, sd: -0.1, min: 0.1}}\nrelease: {x: {value: 1.0}}\n",
        "block.size.sd", "must be");
    expect(
        "profile: {points: [[0, 10], [10, 0], [30, 0]]}\nmaterials: {rock: {}}\n"
        "block: {size: {distribution: gamma, mean: 0.3}}\nrelease: {x: {value: 1.0}}\n",
        "block.size.distribution", "gamma");
    expect(
        "profile: {points: [[0, 10], [10, 0], [30, 0]]}\nmaterials: {rock: {}}\n"
        "block: {size: {distribution: uniform, min: 0.2}}\nrelease: {x: {value: 1.0}}\n",
        "block.size.max", "missing");
    expect(
        "profile: {points: [[0, 10], [10, 0], [30, 0]]}\n"
        "materials: {rock: {normal_restitution: {distribution: normal, mean: 0.8, sd: 0.2, min: 0.3}}}\n"
        "block: {size: {value: 0.3}}\nrelease: {x: {value: 1.0}}\n",
        "materials.rock.normal_restitution.max", "at most 1");
    expect(
        "profile: {points: [[0, 10], [10, 0], [30, 0]]}\nmaterials: {rock: {}}\n"
        "block: {size: {value: 0.3}}\nrelease: {x: {distribution: uniform, min: 1, max: 40}}\n",
        "release.x", "inside the profile");
    expect(kGood + "collectors: {pipe: {x: 50}}\n", "collectors.pipe.x", "inside the profile");
    expect("profile: {points: [[0, 10], [10, 0], [30, 0]]}\nmaterials: {rock: {}}\nrelease: {x: {value: 1.0}}\n",
           "block", "missing");
    expect(
        "profile: {points: [[0, 10], [10, 0], [30, 0]]}\nmaterials: {rock: {}, mud: {}}\n"
        "block: {size: {value: 0.3}}\nrelease: {x: {value: 1.0}}\n",
        "profile.material", "several materials");
    expect(kGood + "model: {calibration: nothing.yaml}\n", "model.calibration", "not found");
    // A calibration file's slope law: one value per travel, travels increasing.
    const auto file = std::filesystem::temp_directory_path() / "chute_bad_slope_calibration.yaml";
    const std::string head =
        "model: {drag_coefficient: 1.7, added_mass_coefficient: 1.4, kappa_n: 0.6, kappa_t: 1, beta: 35,\n"
        "        slope: {angle: 30, ";
    const std::string tail = "}}\nblock: {size: 0.3, density: 2500}\n";
    const std::string uses = kGood + "model: {calibration: " + file.string() + "}\n";
    for (const auto& [slope, key, says] : std::vector<std::tuple<std::string, std::string, std::string>>{
             {"impact_angle: [3, 20], kappa_n: [0.8, 0.9], travel: [3, 5], push: [0.1]", "model.slope.push",
              "one value per entry of model.slope.travel"},
             {"impact_angle: [3, 20], kappa_n: [0.8], travel: [3, 5], push: [0.1, 0.2]", "model.slope.kappa_n",
              "one value per entry of model.slope.impact_angle"},
             {"impact_angle: [3, 20], kappa_n: [0.8, 0.9], travel: [5, 3], push: [0.1, 0.2]", "model.slope.travel",
              "increase"},
             {"impact_angle: [20, 3], kappa_n: [0.8, 0.9], travel: [3, 5], push: [0.1, 0.2]",
              "model.slope.impact_angle", "increase"},
             {"impact_angle: [3, 20], kappa_n: [0.8, 0.9], travel: [3, 5], push: [0.1, 3]", "model.slope.push", ""},
             {"impact_angle: [3], kappa_n: [0.8], travel: [3]", "model.slope.push", "missing"}}) {
        std::ofstream(file) << head << slope << tail;
        const std::string e = error_of(uses);
        EXPECT_NE(e.find(key), std::string::npos) << slope << ": " << e;
        EXPECT_NE(e.find(says), std::string::npos) << slope << ": " << e;
    }
    // Its ground effect: both numbers, in their bounds.
    for (const auto& [ground, key, says] : std::vector<std::tuple<std::string, std::string, std::string>>{
             {"{strength: -1, decay: 0.3}", "model.ground_effect.strength", "got -1"},
             {"{strength: 2, decay: 0}", "model.ground_effect.decay", "got 0"},
             {"{strength: 2}", "model.ground_effect.decay", "missing"}}) {
        std::ofstream(file) << "model: {drag_coefficient: 1.7, added_mass_coefficient: 1.4, kappa_n: 0.6, kappa_t: 1, "
                               "beta: 35, ground_effect: "
                            << ground << "}\nblock: {size: 0.3, density: 2500}\n";
        const std::string e = error_of(uses);
        EXPECT_NE(e.find(key), std::string::npos) << ground << ": " << e;
        EXPECT_NE(e.find(says), std::string::npos) << ground << ": " << e;
    }
    std::filesystem::remove(file);
}

}  // namespace
}  // namespace chute

namespace chute {
namespace {

// A free fall observed from the lumped model's closed form with C_D 1.8 and C_a 0.9, 6 s (its last 0.5 s at the
// terminal speed).
FreeFallObservation closed_form_fall(const BlockFluid& fluid, double size, double density) {
    LumpedModelConfig m;
    m.volume = size * size * size;
    m.mass = density * m.volume;
    m.frontal_area = size * size;
    m.fluid_density = fluid.fluid_density;
    m.drag_coefficient = 1.8;
    m.added_mass_coefficient = 0.9;
    const BerangerFreeFall closed = beranger_free_fall(m);
    FreeFallObservation fall;
    for (double t = 0.0; t <= 6.0; t += 0.002) fall.t.push_back(t), fall.speed.push_back(closed.speed(t));
    fall.terminal_speed = closed.terminal_speed;
    return fall;
}

// A bed bounce made by the model itself (the law `truth`, C_D 1.8, C_a 0.9) at `speed`, after `travel` block sizes.
BounceObservation bed_bounce(const BlockFluid& fluid, const WetRebound& truth, double speed, double travel = 0.0) {
    BounceObservation o;
    o.name = "bed";
    o.impact_velocity = Vec2(0.0, -speed);
    o.travel = travel;
    o.size = 0.3, o.density = 2500.0;
    o.rebound_height = lumped_bounce(o, fluid, 1.8, 0.9, truth).height;
    return o;
}

// The calibration's fits recover the constants of observations made by the lumped model itself: a free fall
// from the closed form with C_D 1.8 and C_a 0.9, bed bounces made with kappa_n 0.7 (hazard/calibration.hpp).
TEST(HazardCalibration, RecoversTheConstantsOfItsOwnModel) {
    const BlockFluid fluid;
    const double size = 0.3, density = 2500.0;
    const FreeFallObservation fall = closed_form_fall(fluid, size, density);
    WetRebound truth;
    truth.kappa_n = 0.7;
    std::vector<BounceObservation> bounces;
    for (double speed : {1.2, 1.7, 2.2}) bounces.push_back(bed_bounce(fluid, truth, speed));
    const Calibration c = calibrate(fall, size, density, bounces, fluid);
    EXPECT_NEAR(c.constants.drag_coefficient, 1.8, 1e-9);
    EXPECT_NEAR(c.constants.added_mass_coefficient, 0.9, 1e-4);
    EXPECT_NEAR(c.constants.wet_rebound.kappa_n, 0.7, 1e-4);
    EXPECT_EQ(c.constants.wet_rebound.kappa_t, 1.0);  // no slope fitted to
    for (const CalibrationPoint& p : c.points) {
        EXPECT_NEAR(p.kappa, 0.7, 1e-4);
        EXPECT_NEAR(p.lumped_height, p.cfd.rebound_height, 1e-4 * p.cfd.rebound_height);
    }
}

// The wake's growth (hazard/wet_rebound.hpp) is recovered from bed bounces the model made itself after falls of
// 2-12 block sizes at different speeds: kappa_n 0.62 once the wake is developed, 1.0 with no wake, over 3 sizes.
TEST(HazardCalibration, RecoversTheWakeGrowthOfItsOwnModel) {
    const BlockFluid fluid;
    const double size = 0.3, density = 2500.0;
    const FreeFallObservation fall = closed_form_fall(fluid, size, density);
    WetRebound truth;
    truth.kappa_n = 0.62, truth.kappa_n_start = 1.0, truth.wake_length = 3.0;
    std::vector<BounceObservation> bounces;
    for (const auto& [travel, speed] :
         std::vector<std::pair<double, double>>{{2, 1.5}, {4.5, 1.9}, {8, 2.0}, {12, 2.1}})
        bounces.push_back(bed_bounce(fluid, truth, speed, travel));
    const Calibration c = calibrate(fall, size, density, bounces, fluid);
    EXPECT_NEAR(c.constants.wet_rebound.kappa_n, 0.62, 1e-3);
    EXPECT_NEAR(c.constants.wet_rebound.kappa_n_start, 1.0, 1e-3);
    EXPECT_NEAR(c.constants.wet_rebound.wake_length, 3.0, 1e-2);
    for (const CalibrationPoint& p : c.points) {
        EXPECT_NEAR(p.law_kappa, truth.normal_kappa(p.cfd.travel), 1e-4);
        EXPECT_NEAR(p.lumped_height, p.cfd.rebound_height, 1e-3 * p.cfd.rebound_height);
    }
    // A calibration file keeps the law.
    const auto file = std::filesystem::temp_directory_path() / "chute_wake_calibration.yaml";
    write_calibration_file(file, c.constants);
    const CalibrationFile back = read_calibration_file(file);
    EXPECT_NEAR(back.wet_rebound.wake_length, c.constants.wet_rebound.wake_length, 1e-5);  // 6 digits
    EXPECT_NEAR(back.wet_rebound.kappa_n_start, c.constants.wet_rebound.kappa_n_start, 1e-5);
    std::filesystem::remove(file);
}

// A block dropped in water onto flat ground takes the wake's kappa_n for its fall (the travel since its flight
// began, in block sizes), and the next impact for the bounce's own travel.
TEST(HazardCalibration, ImpactTakesTheKappaOfItsTravel) {
    const SlopeProfile flat({Vec2(-50.0, 0.0), Vec2(50.0, 0.0)}, {0}, 100.0);  // all under water
    Material ground;
    ground.normal_restitution = Distribution::fixed(0.8);
    ground.tangential_restitution = Distribution::fixed(0.8);
    TrajectorySettings settings;
    settings.wet_rebound.kappa_n = 0.6, settings.wet_rebound.kappa_n_start = 1.1,
    settings.wet_rebound.wake_length = 4.0;
    settings.end_time = 3.0;
    const std::vector<Material> materials{ground};  // the integrator keeps a reference
    TrajectoryIntegrator integrator(flat, materials, WaterProperties{}, settings);
    HazardBlock block;
    block.size = 0.3, block.density = 2500.0;
    std::mt19937_64 rng(0);
    const TrajectoryResult r = integrator.run(block, Vec2(0.0, 1.2), Vec2::Zero(), {}, rng);
    ASSERT_GE(r.impacts.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        const Impact& e = r.impacts[i];
        const Vec2 from = i == 0 ? Vec2(0.0, 1.2) : r.impacts[0].position;
        EXPECT_NEAR(e.travel, (e.position - from).norm() / block.size, 1e-12);
        EXPECT_NEAR(e.normal_restitution,
                    0.8 * settings.wet_rebound.normal_kappa(e.travel) * std::exp(-35.0 / e.stokes), 1e-12);
    }
    EXPECT_NEAR(r.impacts[0].travel, 4.0, 1e-6);                                  // 1.2 m of fall
    EXPECT_GT(r.impacts[1].normal_restitution, r.impacts[0].normal_restitution);  // a short bounce: less wake
}

// The ground effect (hazard/ground_effect.hpp) and the bed's kappa_n are recovered from bed runs the model made
// itself: approaches from 2 block sizes up at 1.5-2.2 m/s braked by G = 2.5 exp(-c / 0.3 a), and the rebounds
// with kappa_n 0.7 flying through the same ground effect.
TEST(HazardCalibration, RecoversTheGroundEffectOfItsOwnModel) {
    const BlockFluid fluid;
    const double size = 0.3, density = 2500.0;
    const GroundEffect truth{2.5, 0.3};
    WetRebound law;
    law.kappa_n = 0.7;
    std::vector<BounceObservation> bounces;
    for (const double speed : {1.5, 1.9, 2.2}) {
        BounceObservation o;
        o.name = "bed_" + std::to_string(speed);
        o.size = size, o.density = density;
        for (int i = 0; i <= 12; ++i) o.approach_clearance.push_back(2.0 * size * (1.0 - i / 12.0));
        o.approach_velocity.assign(13, Vec2(0.0, -speed));
        const std::vector<double> approach = lumped_approach(o, fluid, 1.8, 0.9, truth);
        for (int i = 0; i <= 12; ++i) o.approach_velocity[i] = Vec2(0.0, -approach[i]);
        o.impact_velocity = o.approach_velocity.back();
        o.rebound_height = lumped_bounce(o, fluid, 1.8, 0.9, law, truth).height;
        o.release_offset = Vec2(0.0, 2.0 * size), o.release_velocity = Vec2(0.0, -speed);  // the approach's start
        bounces.push_back(o);
    }
    EXPECT_LT(bounces[2].impact_velocity.norm(), 0.9 * 2.2);  // the ground effect brakes by over 10 %
    const Calibration c = calibrate(closed_form_fall(fluid, size, density), size, density, bounces, fluid);
    EXPECT_NEAR(c.constants.ground_effect.strength, 2.5, 2e-3);
    EXPECT_NEAR(c.constants.ground_effect.decay, 0.3, 2e-4);
    EXPECT_NEAR(c.constants.wet_rebound.kappa_n, 0.7, 1e-4);
    for (const CalibrationPoint& p : c.points) {
        EXPECT_NEAR(p.approach_impact_speed, -p.cfd.impact_velocity.y(), 1e-4);
        EXPECT_GT(p.approach_impact_speed_plain, 1.05 * p.approach_impact_speed);
        // Flown from the release through its own impact, the bounce is the one made from the impact.
        EXPECT_NEAR(p.released_impact_speed, -p.cfd.impact_velocity.y(), 1e-4);
        EXPECT_NEAR(p.released.height, p.cfd.rebound_height, 1e-3 * p.cfd.rebound_height);
    }
    // A calibration file keeps it, a hazard run's flight uses it (ImpactSpeedOfTheGroundEffect).
    const auto file = std::filesystem::temp_directory_path() / "chute_ground_effect_calibration.yaml";
    write_calibration_file(file, c.constants);
    const CalibrationFile back = read_calibration_file(file);
    EXPECT_NEAR(back.ground_effect.strength, c.constants.ground_effect.strength, 1e-5 * 2.5);
    EXPECT_NEAR(back.ground_effect.decay, c.constants.ground_effect.decay, 1e-5 * 0.3);
    std::filesystem::remove(file);
}

// A block released at rest 0.6 m above flat ground under water meets it at the speed of the one-dimensional fall
// with the ground effect, m_e dv/dt = (m - m_f) g - 1/2 rho C_D A (1 + G(y)) v |v| (classical RK4 with a small step,
// written here), not at the free-stream one; in air the ground effect does nothing.
TEST(HazardCalibration, ImpactSpeedOfTheGroundEffect) {
    const SlopeProfile flat({Vec2(-50.0, 0.0), Vec2(50.0, 0.0)}, {0}, 100.0);  // all under water
    const SlopeProfile dry_flat({Vec2(-50.0, 0.0), Vec2(50.0, 0.0)}, {0}, -100.0);
    Material ground;
    ground.normal_restitution = Distribution::fixed(0.8);
    ground.tangential_restitution = Distribution::fixed(0.8);
    const std::vector<Material> materials{ground};
    TrajectorySettings settings;
    settings.drag_coefficient = 1.7, settings.added_mass_coefficient = 1.4;
    settings.ground_effect = {2.2, 0.29};
    settings.end_time = 1.0;
    settings.relative_tolerance = 1e-10, settings.absolute_tolerance = 1e-12;
    HazardBlock block;
    block.size = 0.3, block.density = 2500.0;
    const double a = block.size, volume = a * a * a, rho = 1000.0, g = 9.81;
    const double m = block.density * volume, me = m + 1.4 * rho * volume;
    const auto accel = [&](double y, double v, double ground_factor) {
        const double G = ground_factor * 2.2 * std::exp(-y / (0.29 * a));
        return ((m - rho * volume) * -g - 0.5 * rho * 1.7 * a * a * (1.0 + G) * v * std::abs(v)) / me;
    };
    const auto rk4_impact_speed = [&](double ground_factor) {
        double y = 0.6, v = 0.0;
        const double h = 1e-5;
        while (true) {
            const double k1y = v, k1v = accel(y, v, ground_factor);
            const double k2y = v + 0.5 * h * k1v, k2v = accel(y + 0.5 * h * k1y, v + 0.5 * h * k1v, ground_factor);
            const double k3y = v + 0.5 * h * k2v, k3v = accel(y + 0.5 * h * k2y, v + 0.5 * h * k2v, ground_factor);
            const double k4y = v + h * k3v, k4v = accel(y + h * k3y, v + h * k3v, ground_factor);
            const double y1 = y + h / 6.0 * (k1y + 2 * k2y + 2 * k3y + k4y);
            const double v1 = v + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
            if (y1 <= 0.0) return -(v + (v1 - v) * y / (y - y1));  // linear to the crossing
            y = y1, v = v1;
        }
    };
    std::mt19937_64 rng(0);
    TrajectoryIntegrator wet(flat, materials, WaterProperties{}, settings);
    const TrajectoryResult r = wet.run(block, Vec2(0.0, 0.6), Vec2::Zero(), {}, rng);
    ASSERT_FALSE(r.impacts.empty());
    const double with = rk4_impact_speed(1.0), without = rk4_impact_speed(0.0);
    EXPECT_NEAR(-r.impacts.front().velocity_before.y(), with, 1e-6 * with);
    EXPECT_LT(with, 0.95 * without);
    TrajectoryIntegrator dry(dry_flat, materials, WaterProperties{}, settings);
    const TrajectoryResult d = dry.run(block, Vec2(0.0, 0.6), Vec2::Zero(), {}, rng);
    ASSERT_FALSE(d.impacts.empty());
    EXPECT_NEAR(-d.impacts.front().velocity_before.y(), std::sqrt(2.0 * g * 0.6), 1e-7);
}

// A slope run made by the model itself (wet_rebound.hpp's slope law `truth`) at 30 degrees.
BounceObservation slope_bounce(const BlockFluid& fluid, const WetRebound& truth, double degrees, double travel,
                               Vec2 impact, bool fitted) {
    BounceObservation o;
    o.name = "slope_" + std::to_string(static_cast<int>(degrees)) + "_" + std::to_string(travel);
    o.fitted = fitted;
    o.slope_angle = degrees * std::numbers::pi / 180.0;
    o.impact_velocity = impact;
    o.travel = travel;
    o.size = 0.3, o.density = 2500.0;
    const LumpedBounce b = lumped_bounce(o, fluid, 1.8, 0.9, truth);
    o.rebound_height = b.height, o.runout = b.runout;
    return o;
}

// The slope's law (kappa_n against the impact's angle from the normal, the water's push along the slope against
// travel, on one slope angle) is recovered from 30 degree bounces the model made itself, the push both down (+) and
// up (-) the slope as in Chute's runs; a run between the fitted ones is reproduced; the law is interpolated in the
// angle from the bed's and held above the measured angle; a calibration file keeps it.
TEST(HazardCalibration, RecoversTheSlopeLawOfItsOwnModel) {
    const BlockFluid fluid;
    const double size = 0.3, density = 2500.0;
    WetRebound truth;
    truth.kappa_n = 0.7;
    // The fitted runs' impacts, 3, 12 and 24 degrees from the normal, after 3, 4.7 and 6 block sizes.
    const std::vector<Vec2> impacts{Vec2(0.09, -1.65), Vec2(0.35, -1.6), Vec2(0.63, -1.42)};
    const auto obliquity = [](Vec2 v) { return std::atan2(std::abs(v.x()), std::abs(v.y())); };
    truth.slope = {30.0 * std::numbers::pi / 180.0,
                   {obliquity(impacts[0]), obliquity(impacts[1]), obliquity(impacts[2])},
                   {0.82, 0.90, 1.03},
                   {3.0, 4.7, 6.0},
                   {0.03, -0.3, -0.95}};
    std::vector<BounceObservation> bounces;
    for (double speed : {1.5, 2.0}) bounces.push_back(bed_bounce(fluid, truth, speed));
    bounces.push_back(slope_bounce(fluid, truth, 30.0, 3.0, impacts[0], true));
    bounces.push_back(slope_bounce(fluid, truth, 30.0, 4.7, impacts[1], true));
    bounces.push_back(slope_bounce(fluid, truth, 30.0, 6.0, impacts[2], true));
    bounces.push_back(slope_bounce(fluid, truth, 30.0, 3.9, Vec2(0.2, -1.64), false));   // between: a check
    bounces.push_back(slope_bounce(fluid, truth, 45.0, 6.9, Vec2(1.47, -0.82), false));  // steeper: held at 30
    const Calibration c = calibrate(closed_form_fall(fluid, size, density), size, density, bounces, fluid);
    const SlopeRebound& law = c.constants.wet_rebound.slope;
    EXPECT_NEAR(law.angle, truth.slope.angle, 1e-12);
    ASSERT_EQ(law.travel.size(), 3u);
    ASSERT_EQ(law.impact_angle.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(law.impact_angle[i], truth.slope.impact_angle[i], 1e-12);
        EXPECT_NEAR(law.travel[i], truth.slope.travel[i], 1e-12);
        EXPECT_NEAR(law.kappa_n[i], truth.slope.kappa_n[i], 1e-4);
        EXPECT_NEAR(law.push[i], truth.slope.push[i], 1e-4);
    }
    EXPECT_EQ(c.constants.wet_rebound.kappa_t, 1.0);  // not fitted
    for (const CalibrationPoint& p : c.points) {
        EXPECT_NEAR(p.law_kappa, truth.normal_kappa(p.cfd.travel, p.cfd.slope_angle, p.cfd.impact_angle()), 1e-4)
            << p.cfd.name;
        EXPECT_NEAR(p.lumped_height, p.cfd.rebound_height, 1e-3 * p.cfd.rebound_height) << p.cfd.name;
        if (!p.cfd.on_bed()) {
            EXPECT_NEAR(p.lumped_runout, p.cfd.runout, 1e-3 * std::abs(p.cfd.runout)) << p.cfd.name;
        }
        // Each fitted slope run is also predicted by the law fitted to the others (a cross-validation).
        EXPECT_EQ(std::isfinite(p.left_out_height), p.cfd.fitted && !p.cfd.on_bed()) << p.cfd.name;
    }
    // Between the bed and the measured angle, linear in the angle; above it, the measured angle's.
    const WetRebound& fitted = c.constants.wet_rebound;
    const double half = 15.0 * std::numbers::pi / 180.0, steep = 60.0 * std::numbers::pi / 180.0;
    EXPECT_NEAR(fitted.normal_kappa(3.9, half, 0.1), 0.5 * (fitted.normal_kappa(3.9) + law.kappa_n_at(0.1)), 1e-12);
    EXPECT_EQ(fitted.normal_kappa(3.9, steep, 0.1), law.kappa_n_at(0.1));
    EXPECT_EQ(law.kappa_n_at(1.2), law.kappa_n.back());  // held beyond the measured impact angles
    EXPECT_NEAR(fitted.push(3.9, half), 0.5 * law.push_at(3.9), 1e-12);
    EXPECT_EQ(fitted.push(3.9, steep), law.push_at(3.9));
    EXPECT_EQ(fitted.push(3.9, 0.0), 0.0);
    EXPECT_EQ(law.push_at(1.0), law.push.front());  // held beyond the measured travels
    EXPECT_EQ(law.push_at(9.0), law.push.back());
    // Left out, the last run (6 sizes, 24 degrees) takes the held values of the middle one.
    const CalibrationPoint& last = c.points[4];
    WetRebound held = truth;
    held.slope = {truth.slope.angle,
                  {truth.slope.impact_angle[0], truth.slope.impact_angle[1]},
                  {0.82, 0.90},
                  {3.0, 4.7},
                  {0.03, -0.3}};
    const LumpedBounce expected = lumped_bounce(last.cfd, fluid, 1.8, 0.9, held);
    EXPECT_NEAR(last.left_out_height, expected.height, 1e-3 * expected.height);
    EXPECT_NEAR(last.left_out_runout, expected.runout, 1e-3 * std::abs(expected.runout));
    // A calibration file keeps it.
    const auto file = std::filesystem::temp_directory_path() / "chute_slope_calibration.yaml";
    write_calibration_file(file, c.constants);
    const SlopeRebound back = read_calibration_file(file).wet_rebound.slope;
    EXPECT_NEAR(back.angle, law.angle, 1e-6);
    ASSERT_EQ(back.push.size(), 3u);
    ASSERT_EQ(back.kappa_n.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(back.push[i], law.push[i], 1e-5);
        EXPECT_NEAR(back.kappa_n[i], law.kappa_n[i], 1e-5);
        EXPECT_NEAR(back.impact_angle[i], law.impact_angle[i], 1e-6);
    }
    std::filesystem::remove(file);
    // Slope runs on two angles cannot make one law.
    bounces.back().fitted = true;
    try {
        calibrate(closed_form_fall(fluid, size, density), size, density, bounces, fluid);
        ADD_FAILURE() << "two slope angles fitted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("different angles"), std::string::npos) << e.what();
    }
}

// A block dropped in water onto a 30 degree slope leaves its first impact with the slope law's rebound: the
// normal part Rn kappa_n^s(impact angle) exp(-beta/St), the tangential Rt kappa_t v_t plus push |v_n| down the slope,
// whichever way the slope descends (the mirrored slope gives the mirrored rebound).
TEST(HazardCalibration, ImpactOnASlopeTakesTheSlopeLaw) {
    Material ground;
    ground.normal_restitution = Distribution::fixed(0.8);
    ground.tangential_restitution = Distribution::fixed(0.8);
    const std::vector<Material> materials{ground};
    TrajectorySettings settings;
    settings.wet_rebound.kappa_n = 0.6;
    settings.wet_rebound.slope = {30.0 * std::numbers::pi / 180.0, {0.0, 0.6}, {0.9, 1.1}, {2.0, 6.0}, {-0.2, -0.6}};
    settings.end_time = 3.0;
    HazardBlock block;
    block.size = 0.3, block.density = 2500.0;
    const double t30 = std::tan(30.0 * std::numbers::pi / 180.0);
    std::vector<Impact> first;
    for (const double side : {1.0, -1.0}) {  // descending towards +x, then towards -x
        const SlopeProfile slope({Vec2(-50.0, side * 50.0 * t30), Vec2(50.0, -side * 50.0 * t30)}, {0}, 100.0);
        TrajectoryIntegrator integrator(slope, materials, WaterProperties{}, settings);
        std::mt19937_64 rng(0);
        const TrajectoryResult r = integrator.run(block, Vec2(0.0, 1.2), Vec2::Zero(), {}, rng);
        ASSERT_GE(r.impacts.size(), 1u);
        const Impact& e = r.impacts[0];
        const Vec2 n(side * 0.5, std::sqrt(3.0) / 2.0), down(side * std::sqrt(3.0) / 2.0, -0.5);
        const double vn = e.velocity_before.dot(n), vt = e.velocity_before.dot(down);
        const double kappa = settings.wet_rebound.slope.kappa_n_at(std::atan2(std::abs(vt), std::abs(vn)));
        EXPECT_GT(kappa, 0.9);  // an oblique impact: kappa_n from the angle's table
        EXPECT_NEAR(e.normal_restitution, 0.8 * kappa * std::exp(-35.0 / e.stokes), 1e-12);
        EXPECT_NEAR(e.push, settings.wet_rebound.slope.push_at(e.travel) * std::abs(vn), 1e-12);
        EXPECT_LT(e.push, 0.0);  // up the slope
        EXPECT_NEAR(e.velocity_after.dot(n), -e.normal_restitution * vn, 1e-12);
        EXPECT_NEAR(e.velocity_after.dot(down), 0.8 * vt + e.push, 1e-12);
        first.push_back(e);
    }
    EXPECT_NEAR(first[1].velocity_after.x(), -first[0].velocity_after.x(), 1e-9);
    EXPECT_NEAR(first[1].velocity_after.y(), first[0].velocity_after.y(), 1e-9);
}

// The shipped calibration (data/calibration/study_block.yaml) reads, and a hazard case takes its constants.
TEST(HazardCalibration, ShippedCalibrationIsUsedByTheExample) {
    const CalibrationFile f =
        read_calibration_file(std::filesystem::path(CHUTE_SOURCE_DIR) / "data/calibration/study_block.yaml");
    const HazardCase c = load_hazard_case(kExample / "case.yaml");
    EXPECT_EQ(c.settings.drag_coefficient, f.drag_coefficient);
    EXPECT_EQ(c.settings.added_mass_coefficient, f.added_mass_coefficient);
    EXPECT_EQ(c.settings.wet_rebound.kappa_n, f.wet_rebound.kappa_n);
    EXPECT_EQ(f.block_size, 0.3);
    EXPECT_TRUE(f.wet_rebound.slope.measured());
    EXPECT_EQ(c.settings.wet_rebound.slope.push, f.wet_rebound.slope.push);  // the slope law is used
    const HazardCase bed_law = load_hazard_case(kExample / "case.yaml", {"model.slope_law=false"});
    EXPECT_FALSE(bed_law.settings.wet_rebound.slope.measured());
    EXPECT_TRUE(f.ground_effect.active());  // and the ground effect
    EXPECT_EQ(c.settings.ground_effect.strength, f.ground_effect.strength);
    EXPECT_EQ(c.settings.ground_effect.decay, f.ground_effect.decay);
    EXPECT_FALSE(
        load_hazard_case(kExample / "case.yaml", {"model.ground_effect=false"}).settings.ground_effect.active());
    const HazardCase own = load_hazard_case(kExample / "case.yaml", {"model.drag_coefficient=2.0"});
    EXPECT_EQ(own.settings.drag_coefficient, 2.0);  // a key given in the case wins over the calibration
}

}  // namespace
}  // namespace chute

namespace chute {
namespace {

// docs/hazard-case-file.md's key table is the schema's (regenerate: chute keys --hazard).
TEST(HazardRun, DocTableIsCurrent) {
    const auto path = std::filesystem::path(CHUTE_SOURCE_DIR) / "docs/hazard-case-file.md";
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    const std::string doc = text.str();
    const std::string begin = "<!-- BEGIN GENERATED HAZARD KEY TABLE -->\n",
                      end = "<!-- END GENERATED HAZARD KEY TABLE -->";
    const std::size_t b = doc.find(begin), e = doc.find(end);
    ASSERT_NE(b, std::string::npos);
    ASSERT_NE(e, std::string::npos);
    EXPECT_EQ(doc.substr(b + begin.size(), e - b - begin.size()), hazard_keys_markdown())
        << "regenerate the table with: build/apps/chute keys --hazard";
}

}  // namespace
}  // namespace chute

namespace chute {
namespace {

// A profile of 500 segments (a wavy 42 degree slope, +-10 degrees, into the water): every block ends (at rest or
// past the end), none passes under the ground, some stop under the water and some pass a barrier.
TEST(HazardRun, HundredsOfSegments) {
    if (world_rank() != 0) GTEST_SKIP() << "one rank is enough";
    std::string points = "[";
    for (int i = 0; i <= 500; ++i) {
        const double x = 0.4 * i, z = 100.0 - 0.9 * x + 0.3 * std::sin(0.37 * i) + 0.05 * std::sin(1.9 * i);
        points += (i ? ", [" : "[") + std::to_string(x) + ", " + std::to_string(z) + "]";
    }
    points += "]";
    const HazardCase c = hazard_case_from_text(
        "trajectories: 300\nwater: {level: 20.0}\nprofile: {points: " + points +
            "}\nmaterials: {rock: {normal_restitution: {distribution: uniform, min: 0.2, max: 0.5}, "
            "friction_angle: {distribution: normal, mean: 36, sd: 4, min: 25, max: 45}, roughness: 3}}\n"
            "block: {size: {distribution: lognormal, mean: 0.5, sd: 0.2, min: 0.1, max: 2.0}, density: {value: 2700}}\n"
            "release: {x: {distribution: uniform, min: 0.5, max: 10}, height: {value: 1.0}}\n"
            "collectors: {barrier: {x: 60, height: 2.0}}\n",
        kExample);
    ASSERT_EQ(c.segment_materials.size(), 500u);
    const HazardResults r = run_hazard(c, MPI_COMM_SELF);
    int wet_stops = 0;
    for (const TrajectoryOutcome& o : r.outcomes) {
        EXPECT_TRUE(o.end == TrajectoryEnd::rest || o.end == TrajectoryEnd::past_end);
        EXPECT_GE(o.stop.y() - c.profile().height_at(o.stop.x()), -1e-6);
        wet_stops += o.stop.y() < 20.0 ? 1 : 0;
    }
    EXPECT_GT(wet_stops, 0);
    const HazardSummary s = summarize(c, r);
    EXPECT_EQ(s.trajectories, 300);
    EXPECT_LE(s.collectors[0].hits, s.collectors[0].passing);
    EXPECT_GT(s.collectors[0].passing, 0);
}

}  // namespace
}  // namespace chute

namespace chute {
namespace {

// A hazard case with the shipped calibration (its slope law measured at 30 degrees) warns about the wet ground
// steeper than that, and only about it: a 40 degree stretch under the water does, the same stretch above the water
// or at 25 degrees does not, nor does a case without the slope law.
TEST(HazardRun, WarnsWhereTheSlopeLawIsExtrapolated) {
    if (world_rank() != 0) GTEST_SKIP() << "one rank is enough";
    const std::filesystem::path calibration =
        std::filesystem::path(CHUTE_SOURCE_DIR) / "data/calibration/study_block.yaml";
    auto case_with = [&](double angle_deg, double water_level, const std::string& extra) {
        const double t = std::tan(angle_deg * std::numbers::pi / 180.0);
        const std::string points = "[[0, 100], [50, " + std::to_string(100.0 - 50.0 * t) + "], [100, " +
                                   std::to_string(100.0 - 50.0 * t) + "]]";
        return hazard_case_from_text(
            "trajectories: 10\nwater: {level: " + std::to_string(water_level) + "}\nprofile: {points: " + points +
                "}\nmaterials: {rock: {}}\nblock: {size: {value: 0.3}, density: {value: 2500}}\n" +
                "release: {x: {value: 1.0}, height: {value: 1.0}}\n" + "model: {calibration: " + calibration.string() +
                extra + "}\n",
            kExample);
    };
    const std::vector<std::string> steep = calibration_range_warnings(case_with(40.0, 200.0, ""));
    ASSERT_EQ(steep.size(), 1u);
    EXPECT_NE(steep[0].find("1 segment(s)"), std::string::npos) << steep[0];
    EXPECT_NE(steep[0].find("up to 40"), std::string::npos) << steep[0];
    EXPECT_NE(steep[0].find("model.slope_law"), std::string::npos) << steep[0];
    EXPECT_TRUE(calibration_range_warnings(case_with(40.0, -1000.0, "")).empty());  // all dry
    EXPECT_TRUE(calibration_range_warnings(case_with(25.0, 200.0, "")).empty());
    EXPECT_TRUE(calibration_range_warnings(case_with(40.0, 200.0, ", slope_law: false")).empty());
}

}  // namespace
}  // namespace chute
