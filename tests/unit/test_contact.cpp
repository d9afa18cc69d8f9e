// Rigid-body motion, contact and the lumped models without fluid, against closed forms
// (docs/validation-targets.md, "Free fall in air" and "Contact": dry runs match the analytic ballistic trajectory
// and rebound to 1e-6 relative). Held accelerations and impacts located by bisection make them exact to
// round-off, so the tests ask for 1e-9 relative, well inside the 1e-6.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "impacts.hpp"
#include "lumped_model.hpp"
#include "print_on_rank0.hpp"

using namespace chute;

namespace {

constexpr double g = 9.81;
constexpr double deg = std::numbers::pi / 180.0;

// The study's block: a 0.3 m square, 2500 kg/m^3, depth 1 m (Turmel & Locat 2008).
const Outline kBlock = Outline::rectangle(0.3, 0.3);

RigidInertia block_inertia(bool rotation_locked) {
    return rigid_inertia(kBlock, 2500.0, 1.0, {false, false, rotation_locked});
}

Obstacle plane_through_origin(double angle_deg) {
    // Solid below the line through the origin at this angle; normal into the fluid.
    return {"bed", Vec2::Zero(), Vec2(-std::sin(angle_deg * deg), std::cos(angle_deg * deg))};
}

// Steps a body under gravity alone with a fixed dt, collecting impacts.
std::vector<ContactEvent> fly(BodyState& s, ContactState& c, double t_end, double dt, const RigidInertia& m,
                              const std::vector<Obstacle>& obstacles, const ContactConfig& config) {
    std::vector<ContactEvent> all;
    double t = 0.0;
    while (t < t_end - 1e-12) {
        const double h = std::min(dt, t_end - t);
        set_accelerations(s, {m.mass * Vec2(0.0, -g), 0.0}, m);
        const auto ev = move_with_contacts(s, c, t, h, "block", kBlock, m, obstacles, config);
        all.insert(all.end(), ev.begin(), ev.end());
        t += h;
    }
    return all;
}

}  // namespace

TEST(Contact, GapOfTurnedSquareIsItsLowestCorner) {
    BodyState s;
    s.centre = Vec2(0.0, 1.0);
    s.angle = 45.0 * deg;
    const Gap gp = gap(kBlock, s, plane_through_origin(0.0));
    EXPECT_NEAR(gp.distance, 1.0 - 0.15 * std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(gp.point.x(), 0.0, 1e-15);
}

TEST(Contact, MassPropertiesOfTheBlock) {
    const RigidInertia m = block_inertia(false);
    EXPECT_NEAR(m.mass, 2500.0 * 0.09, 1e-10);
    EXPECT_NEAR(m.inertia, 2500.0 * 0.09 * (0.09 + 0.09) / 12.0, 1e-10);  // m (a^2 + b^2) / 12
}

// Dropped from rest with its bottom 2 m above a horizontal bed, RocFall's lumped law, Rn = 0.8: impact at
// t1 = sqrt(2 H / g) at speed g t1, rebound at 0.8 g t1, next impact 2 (0.8 g t1) / g later.
TEST(Contact, DryDropOnHorizontalBedMatchesTheBallisticRebound) {
    const double H = 2.0, t1 = std::sqrt(2.0 * H / g), v1 = g * t1, t2 = t1 + 2.0 * 0.8 * v1 / g;
    const RigidInertia m = block_inertia(true);
    ContactConfig config;  // lumped, Rn = Rt = 0.8
    BodyState s;
    s.centre = Vec2(0.0, H + 0.15);
    ContactState c;
    const double t_end = t1 + 0.8 * v1 / g;  // the apex of the first rebound
    const auto events = fly(s, c, t_end, 0.0137, m, {plane_through_origin(0.0)}, config);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_NEAR(events[0].time, t1, 1e-9 * t1);
    EXPECT_NEAR(events[0].velocity_before.y(), -v1, 1e-9 * v1);
    EXPECT_NEAR(events[0].velocity_after.y(), 0.8 * v1, 1e-9 * v1);
    EXPECT_NEAR(events[0].normal_restitution, 0.8, 1e-12);
    EXPECT_NEAR(s.centre.y() - 0.15, 0.64 * H, 1e-9 * H);  // rebound height Rn^2 H
    EXPECT_NEAR(s.velocity.y(), 0.0, 1e-9 * v1);
    // On to the second impact (fly() counts time from 0 again).
    const auto more = fly(s, c, t2 - t_end + 0.01, 0.0137, m, {plane_through_origin(0.0)}, config);
    ASSERT_EQ(more.size(), 1u);
    EXPECT_NEAR(t_end + more[0].time, t2, 1e-9 * t2);
    EXPECT_NEAR(more[0].velocity_after.y(), 0.64 * v1, 1e-9 * v1);
}

// Vertical fall at 1.86 m/s onto a 30 and a 45 degree plane (the study's inclined-plane cases), lumped law:
// the rebound is v' = -Rn v_n n + Rt v_t t; the flight after it is a parabola until the block's lowest corner
// meets the plane again, found here in closed form and compared with the stepped motion and the CVODE model.
class DryInclinedBounce : public ::testing::TestWithParam<double> {};

TEST_P(DryInclinedBounce, StepsAndCvodeMatchTheParabola) {
    const double angle = GetParam();
    const Obstacle plane = plane_through_origin(angle);
    const Vec2 n = plane.normal, t = -perp(n);
    const RigidInertia m = block_inertia(true);
    ContactConfig config;
    // Start with the lowest corner 0.1 m straight above the plane's point, falling so that it arrives at
    // 1.86 m/s.
    BodyState s;
    const Vec2 corner = kBlock.support_point(-n);  // unrotated block
    const double drop = 0.1, v_impact = 1.86;
    s.centre = Vec2(0.0, drop) - corner;
    const double vy0 = -std::sqrt(v_impact * v_impact - 2.0 * g * drop);
    s.velocity = Vec2(0.0, vy0);
    const double t_hit = (v_impact + vy0) / g;
    const Vec2 v_before(0.0, -v_impact);
    const Vec2 v_after = -0.8 * v_before.dot(n) * n + 0.8 * v_before.dot(t) * t;
    const Vec2 x_hit = s.centre + Vec2(0.0, -drop);
    // Next impact: the corner's gap grows as (v_after . n) tau + (g . n) tau^2 / 2 and closes again at tau2;
    // stop at 0.7 tau2, in flight.
    const double gn = Vec2(0.0, -g).dot(n);
    const double tau2 = -2.0 * v_after.dot(n) / gn;
    const double t_end = t_hit + 0.7 * tau2;
    const Vec2 x_end = x_hit + v_after * 0.7 * tau2 + 0.5 * Vec2(0.0, -g) * std::pow(0.7 * tau2, 2);

    BodyState stepped = s;
    ContactState c;
    const auto events = fly(stepped, c, t_end, 0.0071, m, {plane}, config);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_NEAR(events[0].time, t_hit, 1e-9 * t_hit);
    EXPECT_NEAR((events[0].velocity_after - v_after).norm(), 0.0, 1e-9 * v_impact);
    EXPECT_NEAR((stepped.centre - x_end).norm(), 0.0, 1e-9 * (x_end - s.centre).norm());

    LumpedModelConfig dry;
    dry.mass = m.mass;
    dry.volume = m.volume;
    const LumpedTrajectory lumped = run_lumped_model(dry, kBlock, s, {plane}, config, t_end, 0.05);
    ASSERT_EQ(lumped.events.size(), 1u);
    EXPECT_NEAR(lumped.events[0].time, t_hit, 1e-8 * t_hit);
    EXPECT_NEAR((lumped.samples.back().position - x_end).norm(), 0.0, 1e-7 * (x_end - s.centre).norm());
}

INSTANTIATE_TEST_SUITE_P(Contact, DryInclinedBounce, ::testing::Values(30.0, 45.0));

// The impulse law with rotation: a square turned 30 degrees falls corner first onto the bed. At the contact
// point the normal velocity reverses with Rn and the tangential one scales with Rt (here the corner moves
// along the bed only through the spin the impact gives it); after the impact the block flies with constant
// spin and its centre on a parabola.
TEST(Contact, ImpulseLawWithRotationKeepsTheContactPointCoefficients) {
    const RigidInertia m = block_inertia(false);
    ContactConfig config;
    config.law = ReboundLaw::impulse;
    config.normal_restitution = 0.8;
    config.tangential_restitution = 0.5;
    BodyState s;
    s.angle = 30.0 * deg;
    s.velocity = Vec2(0.7, 0.0);
    const double H = 1.0;
    const Gap g0 = gap(kBlock, s, plane_through_origin(0.0));
    s.centre = Vec2(0.0, H - g0.distance);
    const double t1 = std::sqrt(2.0 * H / g);
    ContactState c;
    BodyState stepped = s;
    const double t_end = t1 + 0.05;  // shortly after: before any second corner can touch
    const auto events = fly(stepped, c, t_end, 0.0093, m, {plane_through_origin(0.0)}, config);
    ASSERT_EQ(events.size(), 1u);
    const ContactEvent& e = events[0];
    EXPECT_NEAR(e.time, t1, 1e-9 * t1);
    EXPECT_NEAR(e.normal_restitution, 0.8, 1e-12);
    EXPECT_NEAR(e.tangential_restitution, 0.5, 1e-12);
    EXPECT_NE(e.angular_velocity_after, 0.0);
    // Linear momentum change is the impulse; angular momentum about the contact point is kept except for the
    // impulse's own moment (zero there): I w' + m r x v' = I w + m r x v, with r from the contact point.
    const double tau = t_end - t1;  // the centre at the impact, back from the end of the parabola
    const Vec2 centre_at_hit = stepped.centre - e.velocity_after * tau - 0.5 * Vec2(0.0, -g) * tau * tau;
    const Vec2 rc = centre_at_hit - e.point;
    const double L_before = m.inertia * e.angular_velocity_before + m.mass * cross(rc, e.velocity_before);
    const double L_after = m.inertia * e.angular_velocity_after + m.mass * cross(rc, e.velocity_after);
    EXPECT_NEAR(L_after, L_before, 1e-9 * std::abs(L_before) + 1e-9);
    EXPECT_NEAR(stepped.angle, 30.0 * deg + e.angular_velocity_after * tau, 1e-9);
    EXPECT_NEAR(stepped.velocity.x(), e.velocity_after.x(), 1e-12);
}

// Rn = 0.8 gives ever smaller bounces; below the rest speed the block stays on the bed without sinking.
TEST(Contact, BouncesDieOutAndTheBlockRestsOnTheBed) {
    const RigidInertia m = block_inertia(true);
    ContactConfig config;
    BodyState s;
    s.centre = Vec2(0.0, 0.5 + 0.15);
    ContactState c;
    const auto events = fly(s, c, 5.0, 0.01, m, {plane_through_origin(0.0)}, config);
    ASSERT_FALSE(events.empty());
    EXPECT_TRUE(events.back().rests);
    EXPECT_EQ(c.resting_on, 0);
    EXPECT_NEAR(s.centre.y(), 0.15, 1e-12);
    EXPECT_EQ(s.velocity.norm(), 0.0);
    // Speeds after successive bounces fall by Rn each time: v_k = 0.8^k v_1 down to the rest speed.
    const double v1 = std::sqrt(2.0 * g * 0.5);
    const std::size_t expected = static_cast<std::size_t>(std::ceil(std::log(0.01 / v1) / std::log(0.8)));
    EXPECT_EQ(events.size(), expected);
}

// Resting on a 30 degree slope with Coulomb friction mu = 0.3: it slides with a = g (sin 30 - mu cos 30).
TEST(Contact, SlidingDownASlopeWithFriction) {
    const RigidInertia m = block_inertia(true);
    ContactConfig config;
    config.friction = 0.3;
    const Obstacle plane = plane_through_origin(30.0);
    BodyState s;
    s.centre = plane.point - kBlock.support_point(-plane.normal);
    ContactState c;
    c.resting_on = 0;
    const double T = 0.8;
    fly(s, c, T, 0.01, m, {plane}, config);
    const double a = g * (std::sin(30.0 * deg) - 0.3 * std::cos(30.0 * deg));
    const Vec2 down(-std::cos(30.0 * deg), -std::sin(30.0 * deg));
    EXPECT_NEAR(s.velocity.dot(down), a * T, 1e-9 * a * T);
    EXPECT_NEAR(gap(kBlock, s, plane).distance, 0.0, 1e-12);
}

namespace {

// The study's block (0.3 m square, 2500 kg/m^3, per metre of depth) in still water.
LumpedModelConfig study_block_in_water() {
    LumpedModelConfig model;
    model.mass = 2500.0 * 0.09;
    model.volume = 0.09;
    model.fluid_density = 1000.0;
    model.frontal_area = 0.3;
    return model;
}

}  // namespace

// The Beranger model's free fall against its closed form (the study's block in water: C_D 2, C_a 0.5).
TEST(LumpedModel, BerangerFreeFallMatchesItsClosedForm) {
    LumpedModelConfig model = study_block_in_water();
    const BerangerFreeFall exact = beranger_free_fall(model);
    // Terminal speed sqrt(2 (rho_s/rho_f - 1) g L / C_D) = sqrt(1.5 * 9.81 * 0.3) = 2.10 m/s (VALIDATION.md).
    EXPECT_NEAR(exact.terminal_speed, std::sqrt(2.0 * 1.5 * g * 0.3 / 2.0), 1e-12);
    BodyState s;
    s.centre = Vec2(0.0, 100.0);
    const LumpedTrajectory run = run_lumped_model(model, kBlock, s, {}, ContactConfig{}, 4.0, 0.1);
    for (const LumpedSample& p : run.samples) {
        EXPECT_NEAR(-p.velocity.y(), exact.speed(p.t), 1e-8 * exact.terminal_speed) << "t = " << p.t;
        EXPECT_NEAR(100.0 - p.position.y(), exact.distance(p.t), 1e-8 * (1.0 + exact.distance(p.t)));
    }
    EXPECT_NEAR(-run.samples.back().velocity.y(), exact.terminal_speed, 1e-3 * exact.terminal_speed);
}

// A current carries the block sideways until it drifts with it (the study's 1 m/s current, Fig. 5).
TEST(LumpedModel, CurrentCarriesTheBlock) {
    LumpedModelConfig model = study_block_in_water();
    model.current = Vec2(1.0, 0.0);
    BodyState s;
    s.centre = Vec2(0.0, 100.0);
    const LumpedTrajectory run = run_lumped_model(model, kBlock, s, {}, ContactConfig{}, 30.0, 1.0);
    EXPECT_NEAR(run.samples.back().velocity.x(), 1.0, 1e-3);
}

// The soft law (spring-dashpot tuned to Rn and a contact time) rebounds with e = Rn: VALIDATION.md gives
// e = exp(-pi xi / sqrt(1 - xi^2)) for a linear spring-dashpot, and the law picks xi from Rn. Gravity acts
// during the 0.1 ms contact too (g T / v = 2e-4), and the midpoint sub-steps add their own error: held to
// 2e-3. Also with rotation free and the block turned, where the effective mass of the corner sets k and c.
TEST(Contact, SoftLawReboundsWithItsRestitution) {
    for (const bool turned : {false, true}) {
        const RigidInertia m = block_inertia(!turned);
        ContactConfig config;
        config.law = ReboundLaw::soft;
        config.duration = 1e-4;
        BodyState s;
        s.angle = turned ? 30.0 * deg : 0.0;
        s.centre = Vec2(0.0, 2.0 - gap(kBlock, s, plane_through_origin(0.0)).distance);
        ContactState c;
        const double t1 = std::sqrt(2.0 * 2.0 / g);
        const auto events = fly(s, c, t1 + 0.01, 0.0137, m, {plane_through_origin(0.0)}, config);
        ASSERT_EQ(events.size(), 1u) << "turned " << turned;
        EXPECT_NEAR(events[0].time, t1, 1e-9 * t1);
        print_on_rank0("soft law, %s: effective restitution %.6f (Rn 0.8)\n", turned ? "turned 30 deg" : "flat",
                       events[0].normal_restitution);
        EXPECT_NEAR(events[0].normal_restitution, 0.8, 2e-3 * 0.8) << "turned " << turned;
        EXPECT_GT(gap(kBlock, s, plane_through_origin(0.0)).distance, 0.0);  // it left the bed
        if (turned) {
            EXPECT_NE(s.angular_velocity, 0.0);
        }
    }
}
