// Bodies with prescribed motion, and static planes (../shared/VALIDATION.md, docs/validation.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "body_run.hpp"
#include "euler_lagrange.hpp"

using namespace chute;
using namespace chute::validation;

namespace {

// A square of side d = 1 in a 20 d x 20 d box of fluid at rest (slip walls), accelerated from rest with
// a = 1 m/s^2 in `direction`. Grid: 40 cells per side in the window [-0.75, 0.75]^2, growing by 4 % per cell
// to the walls; dt = 0.002 s. nu = 1e-6: the boundary layer (~sqrt(nu t) = 1e-4 d) carries a negligible force.
//
// The added mass is read from the impulse: C_a = -(integral of F dt from 0 to T) / (rho d^2 U(T)), so the
// few-step start-up transient of the explicit forcing-projection coupling (an overshoot that rings for ~10
// steps) integrates out. T = 0.02 s (10 steps, displacement 2e-4 d): "early time". Later the separation at
// the corners adds a growing vortex force (C_a read this way is 1.21 at T = 0.1 s, docs/validation.md).
struct AddedMass {
    double ca_forcing, ca_surface;
};

AddedMass accelerated_square(Vec2 direction) {
    CaseConfig c;
    for (AxisConfig* a : {&c.x, &c.y}) {
        a->spacing = "clustered";
        a->start = -10.0;
        a->end = 10.0;
        a->core = {-0.75, 0.75};
        a->core_cells = 60;
        a->ratio = 1.04;
    }
    for (auto& b : c.boundary) b.type = BoundaryType::slip;
    c.density = 1000.0;
    c.viscosity = 1e-6;
    c.fixed_dt = 0.002;
    c.poisson_tolerance = 1e-10;
    BodyConfig square;
    square.name = "square";
    square.shape = BodyShape::rectangle;
    square.size = {1.0, 1.0};
    square.motion.type = MotionType::uniform_acceleration;
    direction.normalize();
    square.motion.acceleration = {direction.x(), direction.y()};
    c.bodies = {square};
    BodyRun run(c, MPI_COMM_WORLD);
    const double T = 0.02, a = 1.0;
    run.run_to(T);
    double impulse_forcing = 0.0, impulse_surface = 0.0, t_previous = 0.0;
    for (const auto& h : run.history) {
        impulse_forcing += (h.t - t_previous) * h.f.forcing.dot(direction);
        impulse_surface += (h.t - t_previous) * (h.f.surface.pressure + h.f.surface.viscous).dot(direction);
        t_previous = h.t;
    }
    const double rho_d2_U = c.density * 1.0 * a * T;  // rho d^2 U(T), depth 1
    AddedMass r{-impulse_forcing / rho_d2_U, -impulse_surface / rho_d2_U};
    if (run.solver.grid().rank() == 0)
        std::printf("square accelerated along (%.3f, %.3f): C_a forcing %.4f, surface %.4f (potential flow 1.1885)\n",
                    direction.x(), direction.y(), r.ca_forcing, r.ca_surface);
    return r;
}

}  // namespace

// Potential flow: the added mass of a square of side d is 1.1885 rho d^2 per unit span for translation in
// any direction (Sedov 1965; VALIDATION.md). Tolerance 5 % (the issue's), for both force measures.
TEST(MovingBodies, AddedMassOfSquareAlongFaceNormal) {
    const AddedMass r = accelerated_square({1.0, 0.0});
    EXPECT_NEAR(r.ca_forcing, 1.1885, 0.05 * 1.1885);
    EXPECT_NEAR(r.ca_surface, 1.1885, 0.05 * 1.1885);
}

TEST(MovingBodies, AddedMassOfSquareAlongDiagonal) {
    const AddedMass r = accelerated_square({1.0, 1.0});
    EXPECT_NEAR(r.ca_forcing, 1.1885, 0.05 * 1.1885);
    EXPECT_NEAR(r.ca_surface, 1.1885, 0.05 * 1.1885);
}

// Uniform flow U along a plane inclined at 30 degrees: no flow may cross the plane. Domain [0, 4] x [0, 2.5],
// plane through (2, 1) rising to the right, solid below; inflow U (cos 30, sin 30) on the left and bottom,
// zero-stress outflow on the right and top; Re = U L / nu = 1000, h = 1/32. After 3 flow-throughs the
// net flux through the outline, |sum (u . n) ds|, and the flux of |u . n|, must be below 0.5 % of U times the
// plane's length: the forcing leaves a slip of ~1e-3 U at the markers after the projection.
TEST(MovingBodies, NoFlowThroughAnInclinedPlane) {
    const double U = 1.0, angle = 30.0 * std::numbers::pi / 180.0;
    const std::array<double, 2> inflow = {U * std::cos(angle), U * std::sin(angle)};
    CaseConfig c;
    c.x = AxisConfig{0.0, 4.0, 128, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{0.0, 2.5, 80, "uniform", 2.0, 1.05, {}};
    c.boundary[0] = BoundaryConfig{BoundaryType::inflow, inflow, InflowProfile::uniform, 0.0, OutflowKind::convective};
    c.boundary[2] = c.boundary[0];
    c.boundary[1].type = c.boundary[3].type = BoundaryType::outflow;
    c.boundary[1].outflow = c.boundary[3].outflow = OutflowKind::zero_stress;
    c.initial_velocity = inflow;
    c.viscosity = U * 1.0 / 1000.0;
    c.cfl = 0.5;
    BodyConfig plane;
    plane.name = "slope";
    plane.shape = BodyShape::plane;
    plane.point = {2.0, 1.0};
    plane.angle = angle;
    c.bodies = {plane};
    BodyRun run(c, MPI_COMM_WORLD);
    run.run_to(3.0 * 4.0 / U);

    const Body& body = run.ibm.bodies()[0];
    const auto markers = body.outline().markers(0.5 / 32);
    std::vector<Vec2> points;
    for (const Marker& m : markers) points.push_back(m.position);
    const Grid& g = run.solver.grid();
    const auto su = delta_stencils(g, DeltaKernel::roma3, Staggering::u_face, points);
    const auto sv = delta_stencils(g, DeltaKernel::roma3, Staggering::v_face, points);
    const auto Uat = interpolate_velocity(g, su, sv, run.solver.velocity());
    double net = 0.0, gross = 0.0, length = 0.0;
    for (std::size_t l = 0; l < markers.size(); ++l) {
        const double un = Uat[l].dot(markers[l].normal);
        net += un * markers[l].length;
        gross += std::abs(un) * markers[l].length;
        length += markers[l].length;
    }
    std::printf("inclined plane (30 deg, length %.3f): net flux %.2e U L, gross |u.n| flux %.2e U L, max slip "
                "after forcing %.2e U\n",
                length, net / (U * length), gross / (U * length), run.last[0].max_slip / U);
    EXPECT_LT(std::abs(net) / (U * length), 0.005);
    EXPECT_LT(gross / (U * length), 0.005);
}
