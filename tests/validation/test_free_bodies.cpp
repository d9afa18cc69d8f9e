// Free bodies in fluid: the rigid-body update coupled to the direct forcing (rigidbody/fluid_body_coupling).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "body_run.hpp"

using namespace chute;
using namespace chute::validation;

namespace {

// A disc of diameter 0.1 m at the middle of a closed 0.5 m box (nu = 1e-4), 32 cells across it.
CaseConfig disc_in_box(double density) {
    return load_case(kExamples + "settling_cylinder/case.yaml",
                     {"domain.x={start: 0.0, end: 0.5, cells: 160}", "domain.y={start: 0.0, end: 0.5, cells: 160}",
                      "fluid.viscosity=1.0e-4", "bodies.disc.centre=[0.25, 0.25]", "bodies.disc.diameter=0.1",
                      "bodies.disc.density=" + std::to_string(density)});
}

}  // namespace

// Gravity and buoyancy cancel and the fluid is at rest: nothing may move, to round-off.
TEST(FreeBodies, NeutrallyBuoyantDiscStaysAtRest) {
    BodyRun run(disc_in_box(1000.0), MPI_COMM_WORLD);
    for (int k = 0; k < 50; ++k) run.step(0.002);
    const BodyState& s = run.carrier.bodies()[0].state();
    EXPECT_LT(s.velocity.norm(), 1e-12);
    EXPECT_LT((s.centre - Vec2(0.25, 0.25)).norm(), 1e-12);
}

// A disc half as dense as the fluid rises; just after release the flow is potential and the disc
// accelerates at a = (rho_f - rho_s) g / (rho_s + C_a rho_f). Water viscosity, a closed 1 m box (10 D),
// 32 cells across the disc; the first 0.005 s ring (as for prescribed bodies) and are left out.
//
// Two checks. (1) The coupling: the free disc's acceleration must agree within 3 % with the one the added mass
// of the same disc under prescribed acceleration gives on the same grid (C_a read from force (a) over the same
// window). (2) Against potential flow, C_a = 1.02 in this box ((R_o^2 + R^2) / (R_o^2 - R^2) for a circle in
// a circular container, Brennen 1982): the immersed disc reads C_a ~ 1.13, about 10 % high at D/h = 32
// (docs/validation.md); held to 12 %. The coupling is explicit; without the virtual mass it diverges at this
// density ratio (Schwarz, Kempe & Froehlich 2015).
TEST(FreeBodies, LightDiscRisesWithItsAddedMass) {
    const std::vector<std::string> box = {"domain.x={start: 0.0, end: 1.0, cells: 320}",
                                          "domain.y={start: 0.0, end: 1.0, cells: 320}", "fluid.viscosity=1.0e-6"};
    auto with = [&](std::string body) {
        std::vector<std::string> o = box;
        o.push_back("bodies.disc={shape: circle, centre: [0.5, 0.5], diameter: 0.1, " + body + "}");
        return load_case(kExamples + "settling_cylinder/case.yaml", o);
    };
    const double m_f = 1000.0 * 3.14159265358979 * 0.05 * 0.05, m_s = 0.5 * m_f, t0 = 0.005, t1 = 0.02;

    BodyRun prescribed(with("motion: {type: uniform_acceleration, acceleration: [0.0, 3.0]}"), MPI_COMM_WORLD);
    prescribed.run_to(t1, 0.0005);
    const double ca = -prescribed.mean(t0, t1, [](const BodyForces& f) { return f.forcing.y(); }) / (m_f * 3.0);

    BodyRun run(with("density: 500.0, motion: {type: free}"), MPI_COMM_WORLD);
    run.run_to(t0, 0.0005);
    const double v0 = run.carrier.bodies()[0].state().velocity.y();
    run.run_to(t1, 0.0005);
    const BodyState& s = run.carrier.bodies()[0].state();
    const double a_mean = (s.velocity.y() - v0) / (t1 - t0);
    const double a_coupled = (m_f - m_s) * 9.81 / (m_s + ca * m_f),
                 a_potential = (m_f - m_s) * 9.81 / (m_s + 1.02 * m_f);
    if (root())
        std::printf(
            "light disc: mean acceleration %.4f m/s^2; from the prescribed disc's C_a %.4f: %.4f; potential "
            "flow (C_a 1.02): %.4f\n",
            a_mean, ca, a_coupled, a_potential);
    EXPECT_NEAR(a_mean, a_coupled, 0.03 * a_coupled);
    EXPECT_NEAR(a_mean, a_potential, 0.12 * a_potential);
    EXPECT_LT(std::abs(s.velocity.x()), 1e-3 * s.velocity.y());  // straight up (markers are not mirror-exact)
}

// The start of the study's free fall (0.3 m square block, 2500 kg/m^3, released from rest in water at rest;
// examples/free_fall_block at 40 cells across, in a 3 m x 3.5 m box). Before any drag, potential flow gives the
// block's first acceleration from buoyancy and added mass: a_0 = (rho_s - rho_f) g / (rho_s + C_a rho_f) = 3.990
// m/s^2 with the square's C_a = 1.1885 (Sedov 1965; DNV-RP-H103 table A-1; VALIDATION.md), the box's 10 %
// blockage adding a little. Held to 3 % (the forces issue's). The first step is 0.04 s long (the free body's
// step limit from the estimate 4.2 m/s^2 of the virtual-mass form): with a single forcing and projection the
// fluid around the block takes up only about half of its added mass in that step and the block read 4.72
// m/s^2, the force then overshooting to 2.3 times the added-mass force at t = 0.085 s (docs/validation.md).
// No spike: over the first 0.05 s (5 steps) the force stays below 1.2 C_a m_f a_0, the added-mass reaction
// plus a drag below 20 N (0.5 rho C_D L v^2 with C_D 2 at v < 0.25 m/s) and the corner vortices' start (C_a
// reads 1.21 at t = 0.1 s on the accelerated square, docs/validation.md). Later the block starts crossing
// cells, and the volume forcing's faces switching on jolt the force (+15 % at t = 0.051 and 0.089 s): the
// cell-crossing ripple, a defect of its own (docs/validation.md, "Cell-crossing ripple").
TEST(FreeBodies, StudyBlockStartsWithItsPotentialFlowAcceleration) {
    const CaseConfig c = load_case(kExamples + "free_fall_block/case.yaml",
                                   {"domain.x={start: -1.5, end: 1.5, cells: 400}",
                                    "domain.y={start: -2.5, end: 1.0, cells: 467}", "time.end=0.1"});
    BodyRun run(c, MPI_COMM_WORLD);
    run.step();
    const double a_first = -run.carrier.bodies()[0].state().acceleration.y();
    const double first_dt = run.solver.time();
    run.run_to(0.1);
    const double m_f = 1000.0 * 0.3 * 0.3, m_s = 2.5 * m_f, ca = 1.1885;
    const double a_potential = (m_s - m_f) * 9.81 / (m_s + ca * m_f);
    double peak = 0.0;
    for (const ForceSample& h : run.history)
        if (h.t <= 0.05) peak = std::max(peak, h.f.forcing.y());
    if (root())
        std::printf(
            "study block start: first step %.4f s, acceleration %.4f m/s^2 (potential flow %.4f, %+.2f %%); "
            "largest force over 0.05 s %.1f N = %.3f C_a m_f a_0\n",
            first_dt, a_first, a_potential, 100.0 * (a_first / a_potential - 1.0), peak,
            peak / (ca * m_f * a_potential));
    EXPECT_NEAR(a_first, a_potential, 0.03 * a_potential);
    EXPECT_LT(peak, 1.2 * ca * m_f * a_potential);
}

// Glowinski et al. (2001, J. Comput. Phys. 169:363, sec. 5.1), reproduced by Wan & Turek (2006, Int. J.
// Numer. Meth. Fluids 51:531): a disc (rho_s/rho_f = 1.25, d = 0.25 cm) settling in a 2 cm channel reaches
// a particle Reynolds number rho_s U d / mu ~ 17.3 (17.15-17.45 across the reproductions), U ~ 5.55 cm/s.
// 16 cells across the disc; terminal speed averaged over t in [0.45, 0.5] s. Band: 5 % (the issue's).
TEST(FreeBodies, SettlingDiscReachesTheGlowinskiTerminalReynoldsNumber) {
    const CaseConfig c = load_case(kExamples + "settling_cylinder/case.yaml", {"time.end=0.5"});
    BodyRun run(c, MPI_COMM_WORLD);
    double sum = 0.0;
    int n = 0;
    while (run.solver.time() < 0.5 - 1e-12) {
        run.step();
        if (run.solver.time() >= 0.45) sum += run.carrier.bodies()[0].state().velocity.y(), ++n;
    }
    const double U = -sum / n, re_solid = 1250.0 * U * 0.0025 / 0.01;
    if (root())
        std::printf("settling disc: U = %.5f m/s, rho_s U d / mu = %.3f (rho_f U d / mu = %.3f)\n", U, re_solid,
                    re_solid / 1.25);
    EXPECT_NEAR(re_solid, 17.3, 0.05 * 17.3);
    // It falls on the channel's axis (to 1 % of d: the markers are not exactly mirror-symmetric).
    EXPECT_NEAR(run.carrier.bodies()[0].state().centre.x(), 0.01, 0.01 * 0.0025);
}

// A free body that starts inside an obstacle (or within contact.distance of it) is a case error naming it.
TEST(FreeBodies, StartInsideAnObstacleIsAnError) {
    const CaseConfig c = load_case(kExamples + "settling_cylinder/case.yaml",
                                   {"bodies.disc.centre=[0.01, 0.0015]", "contact.distance=0.001"});
    try {
        Model model(c, MPI_COMM_WORLD);
        ADD_FAILURE() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("bodies.disc"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("`bottom`"), std::string::npos) << e.what();
    }
}

namespace {

// What a step-halving comparison of one impact needs: the first impact's event, the impulses recorded in
// its step, and the hydrodynamic force (a) of every step from 0.05 s before it to 0.1 s after.
struct ImpactRecord {
    ContactEvent event;
    Vec2 contact_impulse = Vec2::Zero(), water_impulse = Vec2::Zero();
    std::vector<double> times;
    std::vector<Vec2> forces, velocities;  // (a), N; the body's, m/s
};

ImpactRecord first_impact(const std::string& example, std::vector<std::string> set, double cfl) {
    set.push_back("numerics.cfl=" + std::to_string(cfl));
    BodyRun run(load_case(kExamples + example, set), MPI_COMM_WORLD);
    ImpactRecord r;
    double t_impact = NAN;
    std::vector<double> times;
    std::vector<Vec2> forces, velocities;
    while (std::isnan(t_impact) || run.solver.time() < t_impact + 0.1) {
        const auto& f = run.step();
        if (std::isnan(t_impact) && !run.free.events().empty()) {
            r.event = run.free.events().front();
            t_impact = r.event.time;
            r.contact_impulse = f[0].loads.contact_impulse;
            r.water_impulse = f[0].loads.water_impulse;
        }
        times.push_back(run.solver.time());
        forces.push_back(f[0].forcing);
        velocities.push_back(run.carrier.bodies()[0].state().velocity);
        if (run.solver.time() > 3.0) break;  // no impact: the checks below fail on the NaNs
    }
    for (std::size_t k = 0; k < times.size(); ++k)
        if (times[k] >= t_impact - 0.05)
            r.times.push_back(times[k]), r.forces.push_back(forces[k]), r.velocities.push_back(velocities[k]);
    return r;
}

// The largest impulse one step after the impact step gives the body through the force (a), |F| dt in N s: a
// force that is an impulse / dt carries a fixed impulse in one step whatever dt is.
double largest_step_impulse_after(const ImpactRecord& r) {
    double worst = 0.0;
    for (std::size_t k = 1; k < r.forces.size(); ++k)
        if (r.times[k - 1] > r.event.time) worst = std::max(worst, r.forces[k].norm() * (r.times[k] - r.times[k - 1]));
    return worst;
}

// The body's velocity `after` seconds after the impact, interpolated in the record.
Vec2 velocity_after(const ImpactRecord& r, double after) {
    const double t = r.event.time + after;
    for (std::size_t k = 0; k + 1 < r.times.size(); ++k)
        if (r.times[k] <= t && t <= r.times[k + 1]) {
            const double w = (t - r.times[k]) / (r.times[k + 1] - r.times[k]);
            return (1.0 - w) * r.velocities[k] + w * r.velocities[k + 1];
        }
    return Vec2(NAN, NAN);
}

}  // namespace

// Issue 15 (forces a user can trust), item 3: an impact in water does not depend on the time step. The
// rebound law acts at one instant; the water the block carries (its added mass) is reversed within the impact
// step by coupling passes, and its impulse is recorded as an impulse, not as impulse / dt in one step's force.
// The study's bed bounce (rotation locked, lumped law) and its 45 degree slope with rotation free (impulse
// law), with either choice of who supplies the water's impulse (contact.water_impulse), each with the step
// halved (cfl 0.4 and 0.2): impact and rebound velocities and the water's impulse within 2 %, and no step after
// the impact step in which the force (a) gives the body more than 2 % of the water's impulse (at first the step
// after an impact carried about all of it as one force of 1.2e4-5.3e4 N; then passes stopped by the change of
// the last one left 15 % of it to come out over the next 10-20 steps, a transient whose peak grew as the step
// shrank; the passes now run until the change still to come is under 1 %, and what is left per step is the
// drag's own impulse, docs/validation.md). With the default choice the motion 0.05 s after the impact also
// agrees within 2 % of the impact speed; the block that the `body` choice leaves at 0.03 of its impact speed
// makes millimetre bounces whose timing that does not fix.
TEST(FreeBodies, ImpactsDoNotDependOnTheTimeStep) {
    struct Case {
        std::string name, example;
        std::vector<std::string> set;
    };
    std::vector<Case> cases;
    for (const std::string who : {"obstacle", "body"}) {
        cases.push_back({"bed, water_impulse " + who, "bounce_bed/case.yaml", {"contact.water_impulse=" + who}});
        cases.push_back(
            {"slope 45 deg, rotation free, water_impulse " + who,
             "bounce_slope/case.yaml",
             {"contact.law=impulse", "bodies.block.motion.lock_rotation=false", "contact.water_impulse=" + who}});
    }
    for (const Case& c : cases) {
        const ImpactRecord coarse = first_impact(c.example, c.set, 0.4), fine = first_impact(c.example, c.set, 0.2);
        const double speed = fine.event.velocity_before.norm();
        const double impact_change = (coarse.event.velocity_before - fine.event.velocity_before).norm() / speed;
        // The rebound with the water is the law's rebound less the water's impulse over the mass, V_law + J_w / m.
        // With `body` on the bed the two nearly cancel (the block leaves at 3 % of its impact speed), and a change
        // of J_w is amplified 25 times relative to their difference; so the rebound's change is measured against
        // the law's rebound speed, the scale of both terms (for `obstacle` it is the rebound itself), and the
        // water's impulse is checked on its own.
        const double rebound_scale = fine.event.velocity_after.norm();
        const double rebound_change = (coarse.event.velocity_wet - fine.event.velocity_wet).norm() / rebound_scale;
        const double spin_change =
            std::abs(coarse.event.angular_velocity_wet - fine.event.angular_velocity_wet) * 0.15 / rebound_scale;
        const double water_change = (coarse.water_impulse - fine.water_impulse).norm() / fine.water_impulse.norm();
        if (root()) {
            for (const ImpactRecord* r : {&coarse, &fine})
                std::printf(
                    "%s, cfl %.1f: impact (%.4f, %.4f) m/s, law (%.4f, %.4f), with the water (%.4f, %.4f) m/s, spin "
                    "%.4f rad/s; wet restitution n %.4f t %.4f; impulses: contact (%.1f, %.1f), water (%.1f, %.1f) "
                    "N s; largest impulse of (a) in one step after it %.2f N s\n",
                    c.name.c_str(), r == &coarse ? 0.4 : 0.2, r->event.velocity_before.x(),
                    r->event.velocity_before.y(), r->event.velocity_after.x(), r->event.velocity_after.y(),
                    r->event.velocity_wet.x(), r->event.velocity_wet.y(), r->event.angular_velocity_wet,
                    r->event.wet_normal_restitution, r->event.wet_tangential_restitution, r->contact_impulse.x(),
                    r->contact_impulse.y(), r->water_impulse.x(), r->water_impulse.y(), largest_step_impulse_after(*r));
            std::printf(
                "%s: step halved, impact velocity changes %.2f %%, rebound %.2f %% and spin (x 0.15 m) %.2f %% of the "
                "law's rebound speed, water's impulse %.2f %%\n",
                c.name.c_str(), 100 * impact_change, 100 * rebound_change, 100 * spin_change, 100 * water_change);
        }
        const double later_change = (velocity_after(coarse, 0.05) - velocity_after(fine, 0.05)).norm() / speed;
        if (root())
            std::printf(
                "%s: velocity 0.05 s after the impact (%.4f, %.4f) against (%.4f, %.4f) m/s, %.2f %% of the "
                "impact speed\n",
                c.name.c_str(), velocity_after(coarse, 0.05).x(), velocity_after(coarse, 0.05).y(),
                velocity_after(fine, 0.05).x(), velocity_after(fine, 0.05).y(), 100 * later_change);
        if (c.name.find("obstacle") != std::string::npos) {
            EXPECT_LT(later_change, 0.02) << c.name;
        }
        EXPECT_LT(impact_change, 0.02) << c.name;
        EXPECT_LT(rebound_change, 0.02) << c.name;
        EXPECT_LT(spin_change, 0.02) << c.name;
        EXPECT_LT(water_change, 0.02) << c.name;
        for (const ImpactRecord* r : {&coarse, &fine})
            EXPECT_LT(largest_step_impulse_after(*r), 0.02 * r->water_impulse.norm()) << c.name;
    }
}

// The wet restitution a contact resolved by the flow gives (VALIDATION.md, contact: "rebound approaches the dry
// value above St ~ 500"; Joseph et al. 2001, J. Fluid Mech. 433:329, and Gondret et al. 2002, Phys. Fluids
// 14:643, find e_wet / e_dry of 0.8-1 at St of 1e3-1e4; the study's block hits the bed at St ~ 1e6). The soft
// law presses the block into the bed over 0.02 s, some 15 of the flow's steps, so the water the block carries
// is stopped by the flow itself, not by a choice of model: its rebound over the dry one (the law's Rn = 0.8)
// must stay above 0.7. The two impulse-law choices give 1 (`obstacle`) and 0.09 (`body`): this is the
// measurement that chose `obstacle` as the default (docs/validation.md, Impacts in water). About 1 minute.
TEST(FreeBodies, ResolvedContactInWaterReboundsNearTheDryRestitution) {
    BodyRun run(load_case(kExamples + "bounce_bed/case.yaml", {"contact.law=soft", "contact.duration=0.02"}),
                MPI_COMM_WORLD);
    std::vector<ContactEvent> events;
    while (events.empty() && run.solver.time() < 2.0) {
        run.step();
        events = run.free.events();
    }
    ASSERT_FALSE(events.empty()) << "the block never left the bed";
    const ContactEvent& e = events.front();
    const double wet = e.normal_restitution, dry = 0.8;
    if (root())
        std::printf(
            "resolved contact (soft, 0.02 s) on the bed in water: impact %.4f m/s, leaves at %.4f m/s, wet "
            "restitution %.4f = %.3f of the dry %.2f\n",
            -e.velocity_before.y(), e.velocity_after.y(), wet, wet / dry, dry);
    EXPECT_GT(wet / dry, 0.7);
    EXPECT_LT(wet / dry, 1.1);
}
