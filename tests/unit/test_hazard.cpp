// The hazard analysis's trajectory model (hazard/): its dry limit against the dry lumped model of
// rigidbody/lumped_model and the analytic parabola and slide, its wet free fall against the Beranger closed
// form, and its profile, distributions and random streams.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "distribution.hpp"
#include "lumped_model.hpp"
#include "slide_motion.hpp"
#include "slope_profile.hpp"
#include "trajectory.hpp"

namespace chute {
namespace {

constexpr double g = 9.81;
constexpr double below_everything = -1e9, above_everything = 1e9;

Material material(double rn, double rt, double friction_deg = 30.0, double roughness = 0.0) {
    Material m;
    m.name = "test";
    m.normal_restitution = Distribution::fixed(rn);
    m.tangential_restitution = Distribution::fixed(rt);
    m.friction_angle = Distribution::fixed(friction_deg);
    m.roughness = roughness;
    return m;
}

TrajectorySettings tight() {
    TrajectorySettings s;
    s.relative_tolerance = 1e-11;  // as the dry lumped model integrates
    s.absolute_tolerance = 1e-13;
    s.end_time = 30.0;
    return s;
}

SlopeProfile plane(double angle_deg, double length, double water_level) {
    const double a = angle_deg * std::numbers::pi / 180.0;
    return SlopeProfile({Vec2(0.0, 0.0), Vec2(length * std::cos(a), -length * std::sin(a))}, {0}, water_level);
}

// Dry (water level below the profile), the trajectory is the dry lumped model's (rigidbody/lumped_model, the
// RocFall law) impact for impact, to 1e-9: same flight, same root finding, same rebound law.
TEST(Hazard, DryLimitIsTheDryLumpedModel) {
    for (double angle : {0.0, 30.0}) {
        const SlopeProfile profile = plane(angle, 200.0, below_everything);
        const std::vector<Material> materials{material(0.6, 0.85)};
        TrajectorySettings settings = tight();
        TrajectoryIntegrator integrator(profile, materials, {}, settings);
        HazardBlock block;
        const Vec2 x0(1.0, 4.0), v0(1.5, 0.5);
        std::mt19937_64 rng(1);
        const TrajectoryResult hazard = integrator.run(block, x0, v0, {}, rng);

        const SlopeSegment& seg = profile.segments()[0];
        const Obstacle ground{"ground", seg.start, seg.normal};
        ContactConfig contact;
        contact.normal_restitution = 0.6;
        contact.tangential_restitution = 0.85;
        contact.rest_speed = settings.sliding_speed;
        BodyState s;
        s.centre = x0;
        s.velocity = v0;
        const LumpedTrajectory dry = run_lumped_model(integrator.flight_model(block, false), Outline::circle(1e-200), s,
                                                      {ground}, contact, settings.end_time, 0.1);
        ASSERT_GE(dry.events.size(), 5u) << angle;
        ASSERT_GE(hazard.impacts.size(), dry.events.size()) << angle;
        for (std::size_t i = 0; i < dry.events.size(); ++i) {
            const ContactEvent& e = dry.events[i];
            const Impact& h = hazard.impacts[i];
            EXPECT_NEAR(h.t, e.time, 1e-9) << angle << " impact " << i;
            EXPECT_NEAR((h.position - e.centre).norm(), 0.0, 1e-9) << angle << " impact " << i;
            EXPECT_NEAR((h.velocity_before - e.velocity_before).norm(), 0.0, 1e-9) << angle << " impact " << i;
            EXPECT_NEAR((h.velocity_after - e.velocity_after).norm(), 0.0, 1e-9) << angle << " impact " << i;
            EXPECT_FALSE(h.wet);
        }
    }
}

// Dry bounces on flat ground are parabolas: impact k at t_k = t_0 + sum 2 w_j / g, w_j = Rn^j sqrt(2 g h).
TEST(Hazard, DryBouncesAreParabolas) {
    const SlopeProfile profile({Vec2(-10.0, 0.0), Vec2(100.0, 0.0)}, {0}, below_everything);
    const double rn = 0.7, rt = 0.9, h = 2.0, u0 = 1.2;
    const std::vector<Material> materials{material(rn, rt)};
    TrajectoryIntegrator integrator(profile, materials, {}, tight());
    std::mt19937_64 rng(1);
    const TrajectoryResult r = integrator.run(HazardBlock{}, Vec2(0.0, h), Vec2(u0, 0.0), {}, rng);
    ASSERT_GE(r.impacts.size(), 6u);
    double t = std::sqrt(2.0 * h / g), x = u0 * t, w = std::sqrt(2.0 * g * h), u = u0;
    for (std::size_t k = 0; k < 6; ++k) {
        EXPECT_NEAR(r.impacts[k].t, t, 1e-9) << k;
        EXPECT_NEAR(r.impacts[k].position.x(), x, 1e-9) << k;
        EXPECT_NEAR(r.impacts[k].position.y(), 0.0, 1e-9) << k;
        EXPECT_NEAR(r.impacts[k].velocity_before.y(), -w, 1e-9) << k;
        w *= rn, u *= rt;
        EXPECT_NEAR(r.apexes[k].height, w * w / (2.0 * g), 1e-9) << k;  // the bounce's top, found as a root
        t += 2.0 * w / g, x += u * 2.0 * w / g;
    }
}

// A dry slide with Coulomb friction: constant deceleration g (mu cos - sin) to rest, or acceleration to the
// segment's end; a rest where tan(friction) holds the weight.
TEST(Hazard, DrySlideIsAnalytic) {
    const double angle = 20.0, a = angle * std::numbers::pi / 180.0;
    const SlopeProfile profile = plane(angle, 50.0, below_everything);
    const SlopeSegment& seg = profile.segments()[0];
    std::mt19937_64 rng(1);
    const double v0 = 3.0, s0 = 2.0;
    {  // friction 35 deg > 20: stops
        const std::vector<Material> materials{material(0.5, 0.8, 35.0)};
        TrajectoryIntegrator integrator(profile, materials, {}, tight());
        const double dec = g * (std::tan(35.0 * std::numbers::pi / 180.0) * std::cos(a) - std::sin(a));
        const TrajectoryResult r =
            integrator.run(HazardBlock{}, seg.start + s0 * seg.tangent, v0 * seg.tangent, {}, rng);
        EXPECT_EQ(r.end, TrajectoryEnd::rest);
        EXPECT_NEAR(r.t, v0 / dec, 1e-9);
        EXPECT_NEAR((r.position - seg.start).dot(seg.tangent), s0 + v0 * v0 / (2.0 * dec), 1e-9);
        EXPECT_TRUE(r.impacts.empty());
    }
    {  // friction 10 deg < 20: accelerates off the end at s = L
        const std::vector<Material> materials{material(0.5, 0.8, 10.0)};
        TrajectoryIntegrator integrator(profile, materials, {}, tight());
        const double acc = g * (std::sin(a) - std::tan(10.0 * std::numbers::pi / 180.0) * std::cos(a));
        const TrajectoryResult r =
            integrator.run(HazardBlock{}, seg.start + s0 * seg.tangent, v0 * seg.tangent, {}, rng);
        EXPECT_EQ(r.end, TrajectoryEnd::past_end);
        const double t_end = (-v0 + std::sqrt(v0 * v0 + 2.0 * acc * (seg.length - s0))) / acc;
        EXPECT_NEAR(r.t, t_end, 1e-9);
        EXPECT_NEAR(r.velocity.norm(), v0 + acc * t_end, 1e-9);
    }
    {  // at rest where the friction holds it
        const std::vector<Material> materials{material(0.5, 0.8, 25.0)};
        TrajectoryIntegrator integrator(profile, materials, {}, tight());
        const TrajectoryResult r = integrator.run(HazardBlock{}, seg.start + s0 * seg.tangent, Vec2::Zero(), {}, rng);
        EXPECT_EQ(r.end, TrajectoryEnd::rest);
        EXPECT_EQ(r.t, 0.0);
    }
}

// Under the water level the free fall is the Beranger model's closed form (rigidbody/lumped_model.hpp) when
// given its coefficients.
TEST(Hazard, WetFreeFallIsBerangerClosedForm) {
    const SlopeProfile profile({Vec2(-10.0, -500.0), Vec2(10.0, -500.0)}, {0}, above_everything);
    const std::vector<Material> materials{material(0.8, 0.8)};
    TrajectorySettings settings = tight();
    settings.end_time = 4.0;
    TrajectoryIntegrator integrator(profile, materials, {}, settings);
    HazardBlock block;
    std::mt19937_64 rng(1);
    const TrajectoryResult r = integrator.run(block, Vec2::Zero(), Vec2::Zero(), {}, rng, true);
    const BerangerFreeFall closed = beranger_free_fall(integrator.flight_model(block, true));
    ASSERT_GT(r.path.size(), 10u);
    for (const PathSample& p : r.path) {
        EXPECT_NEAR(-p.position.y(), closed.distance(p.t), 1e-9 * (1.0 + closed.distance(p.t))) << p.t;
        EXPECT_NEAR(-p.velocity.y(), closed.speed(p.t), 1e-9 * closed.terminal_speed) << p.t;
        EXPECT_EQ(p.position.x(), 0.0);
    }
    EXPECT_NEAR(r.velocity.norm(), closed.speed(4.0), 1e-9);
    EXPECT_NEAR(closed.terminal_speed, 2.3, 0.2);  // the study's block: v_t = sqrt(2 (rho_s - rho_f) g a / (rho_f C_D))
}

// From a cliff into the water: the fall is a dry parabola down to the water level, then the Beranger model
// with the speed it entered with.
TEST(Hazard, FallIntoTheWaterChangesTheModelAtTheLevel) {
    const SlopeProfile profile({Vec2(-10.0, -500.0), Vec2(10.0, -500.0)}, {0}, -5.0);
    const std::vector<Material> materials{material(0.8, 0.8)};
    TrajectorySettings settings = tight();
    settings.end_time = 3.0;
    TrajectoryIntegrator integrator(profile, materials, {}, settings);
    std::mt19937_64 rng(1);
    const TrajectoryResult r = integrator.run(HazardBlock{}, Vec2::Zero(), Vec2::Zero(), {}, rng, true);
    const double t_entry = std::sqrt(2.0 * 5.0 / g), v_entry = g * t_entry;
    const LumpedModelConfig wet = integrator.flight_model(HazardBlock{}, true);
    for (std::size_t i = 1; i < r.path.size(); ++i) {
        const PathSample& p = r.path[i];
        if (p.t <= t_entry - 1e-6) {
            EXPECT_NEAR(-p.velocity.y(), g * p.t, 1e-9) << p.t;
        }
        if (p.t >= t_entry + 1e-6) {  // decelerating towards the terminal speed from above
            const double a = lumped_acceleration(wet, p.velocity).y();
            EXPECT_GT(a, 0.0) << p.t;
            EXPECT_LT(-p.velocity.y(), v_entry) << p.t;
        }
    }
}

// The closed-form slide (slide_motion.hpp) against a fine RK4 integration of du/dt = a - b u^2 in each of its
// regimes: accelerating to the terminal speed from below and from above, coasting, decelerating to rest, dry.
TEST(Hazard, ClosedFormSlideMatchesIntegration) {
    struct Case {
        double a, b, u0;
    };
    for (const Case& c : {Case{3.0, 1.1, 0.5}, Case{3.0, 1.1, 4.0}, Case{0.0, 1.1, 2.0}, Case{-2.0, 1.1, 3.0},
                          Case{-2.0, 0.0, 3.0}, Case{1.5, 0.0, 0.0}, Case{3.0, 1.1, 0.0}}) {
        const SlideMotion m(c.a, c.b, c.u0);
        double u = c.u0, s = 0.0, t = 0.0;
        const double dt = 1e-4, t_end = std::min(2.0, m.stop_time());
        const auto f = [&](double v) { return c.a - c.b * v * v; };
        while (t + dt <= t_end) {
            const double k1 = f(u), k2 = f(u + 0.5 * dt * k1), k3 = f(u + 0.5 * dt * k2), k4 = f(u + dt * k3);
            const double l1 = u, l2 = u + 0.5 * dt * k1, l3 = u + 0.5 * dt * k2, l4 = u + dt * k3;
            u += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
            s += dt / 6.0 * (l1 + 2 * l2 + 2 * l3 + l4);
            t += dt;
        }
        EXPECT_NEAR(m.speed(t), u, 1e-9) << c.a << " " << c.b << " " << c.u0;
        EXPECT_NEAR(m.distance(t), s, 1e-9) << c.a << " " << c.b << " " << c.u0;
        EXPECT_NEAR(m.time_to(m.distance(t)), t, 1e-9) << c.a << " " << c.b << " " << c.u0;
    }
    const SlideMotion stop(-2.0, 1.1, 3.0);  // decelerating: rests after stop_distance
    EXPECT_NEAR(stop.distance(stop.stop_time()), stop.stop_distance(), 1e-12);
    EXPECT_NEAR(stop.speed(stop.stop_time()), 0.0, 1e-12);
    EXPECT_TRUE(std::isinf(stop.time_to(stop.stop_distance() * 1.001)));
    EXPECT_NEAR(SlideMotion(3.0, 1.1, 0.0).speed(50.0), std::sqrt(3.0 / 1.1), 1e-12);  // terminal
    EXPECT_NEAR(SlideMotion(3.0, 1.1, 0.5).time_to(5000.0), SlideMotion(3.0, 1.1, 0.5).time_to(5000.0), 0.0);
    EXPECT_TRUE(std::isfinite(SlideMotion(3.0, 1.1, 0.5).time_to(5000.0)));  // long slides do not overflow
}

TEST(Hazard, ProfileRefusesFoldsAndRepeats) {
    const auto message = [](const std::vector<Vec2>& points) {
        try {
            SlopeProfile(points, std::vector<int>(points.size() - 1, 0), 0.0);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message({{0, 10}, {5, 5}, {4, 0}}).find("point 2 (x = 4) folds the profile back"), std::string::npos);
    EXPECT_NE(message({{0, 10}, {5, 5}, {5, 0}}).find("point 2 (x = 5) repeats the x"), std::string::npos);
    EXPECT_NE(message({{0, 10}, {5, NAN}}).find("point 1 is not a finite number"), std::string::npos);
    EXPECT_NE(message({{0, 10}}).find("at least 2 points"), std::string::npos);
}

TEST(Hazard, ProfileCsvNamesTheBadRow) {
    // One folder per process: under unit_np2 both ranks run this test.
    const auto dir = std::filesystem::temp_directory_path() / ("chute_hazard_csv_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    {
        std::ofstream(dir / "good.csv") << "x,z,material\n0,10,rock\n5,2,rock\n# the seabed\n9,1.5,mud\n";
        const ProfileTable t = read_profile_csv(dir / "good.csv");
        ASSERT_EQ(t.points.size(), 3u);
        EXPECT_EQ(t.materials[2], "mud");
        EXPECT_EQ(t.points[1], Vec2(5.0, 2.0));
    }
    std::ofstream(dir / "bad.csv") << "x,z,material\n0,10,rock\n5,two,rock\n";
    try {
        read_profile_csv(dir / "bad.csv");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("line \"3\""), std::string::npos) << e.what();
    }
    std::filesystem::remove_all(dir);
}

TEST(Hazard, ProfileHeightAndClearance) {
    const SlopeProfile p({Vec2(0, 10), Vec2(10, 0), Vec2(20, 0)}, {0, 0}, 5.0);
    EXPECT_DOUBLE_EQ(p.height_at(5.0), 5.0);
    EXPECT_DOUBLE_EQ(p.height_at(15.0), 0.0);
    EXPECT_NEAR(p.clearance(Vec2(5.0, 6.0)), 1.0 / std::sqrt(2.0), 1e-15);
    EXPECT_EQ(p.segment_at(10.0), 1);
    EXPECT_TRUE(p.wet(4.9));
    EXPECT_FALSE(p.wet(5.1));
}

TEST(Hazard, DistributionsSampleTheirShapes) {
    std::mt19937_64 rng = trajectory_rng(7, 0);
    const int n = 200000;
    const auto moments = [&](const Distribution& d) {
        double s = 0.0, s2 = 0.0, lo = 1e300, hi = -1e300;
        for (int i = 0; i < n; ++i) {
            const double v = d.sample(rng);
            s += v, s2 += v * v, lo = std::min(lo, v), hi = std::max(hi, v);
        }
        const double mean = s / n;
        return std::array<double, 4>{mean, std::sqrt(s2 / n - mean * mean), lo, hi};
    };
    const auto u = moments(Distribution::uniform(2.0, 4.0));
    EXPECT_NEAR(u[0], 3.0, 4.0 * (2.0 / std::sqrt(12.0)) / std::sqrt(n));
    EXPECT_GE(u[2], 2.0);
    EXPECT_LE(u[3], 4.0);
    const auto gn = moments(Distribution::normal(1.0, 0.2));
    EXPECT_NEAR(gn[0], 1.0, 4.0 * 0.2 / std::sqrt(n));
    EXPECT_NEAR(gn[1], 0.2, 0.002);
    const auto ln = moments(Distribution::lognormal(0.3, 0.1));  // mean and sd of the quantity itself
    EXPECT_NEAR(ln[0], 0.3, 4.0 * 0.1 / std::sqrt(n));
    EXPECT_NEAR(ln[1], 0.1, 0.002);
    EXPECT_GT(ln[2], 0.0);
    const auto tn = moments(Distribution::normal(0.8, 0.2, 0.5, 1.0));  // truncated
    EXPECT_GE(tn[2], 0.5);
    EXPECT_LE(tn[3], 1.0);
    EXPECT_EQ(moments(Distribution::fixed(1.5))[1], 0.0);
}

TEST(Hazard, TrajectoryStreamsDependOnlyOnSeedAndIndex) {
    std::mt19937_64 a = trajectory_rng(42, 17), b = trajectory_rng(42, 17), c = trajectory_rng(42, 18),
                    d = trajectory_rng(43, 17);
    const auto first = a();
    EXPECT_EQ(first, b());
    EXPECT_NE(first, c());
    EXPECT_NE(first, d());
}

// Roughness perturbs each impact: the same seed gives the same trajectory, another seed another one.
TEST(Hazard, RoughnessIsReproducible) {
    const SlopeProfile profile = plane(35.0, 100.0, below_everything);
    const std::vector<Material> materials{material(0.5, 0.8, 30.0, 5.0)};
    TrajectoryIntegrator integrator(profile, materials, {}, TrajectorySettings{});
    std::mt19937_64 r1 = trajectory_rng(1, 3), r2 = trajectory_rng(1, 3), r3 = trajectory_rng(2, 3);
    const TrajectoryResult a = integrator.run(HazardBlock{}, Vec2(0.0, 3.0), Vec2(1.0, 0.0), {}, r1);
    const TrajectoryResult b = integrator.run(HazardBlock{}, Vec2(0.0, 3.0), Vec2(1.0, 0.0), {}, r2);
    const TrajectoryResult c = integrator.run(HazardBlock{}, Vec2(0.0, 3.0), Vec2(1.0, 0.0), {}, r3);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.t, b.t);
    EXPECT_EQ(a.impacts.size(), b.impacts.size());
    EXPECT_NE(a.t, c.t);
}

}  // namespace
}  // namespace chute
