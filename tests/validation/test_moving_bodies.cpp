// Bodies with prescribed motion, and static planes (docs/validation-targets.md, docs/validation.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "body_run.hpp"
#include "diagnostics.hpp"
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

namespace {

// Flow along a plane inclined at 30 degrees to the grid (examples/inclined_plane): in the doubly periodic box
// the plane and its images bound an inclined channel of width W = cos 30; a body force f along the plane
// drives the exact Poiseuille flow u_t = f n (W - n) / (2 nu), peak 1 m/s, and no flow may cross the plane.
struct PlaneFlow {
    double net_flux, gross_flux, profile_error;  // relative to u_max L, u_max L, u_max
};

PlaneFlow inclined_channel(int cells_x, int cells_y) {
    const CaseConfig c =
        load_case(std::string(CHUTE_SOURCE_DIR) + "/examples/inclined_plane/case.yaml",
                  {"domain.x.cells=" + std::to_string(cells_x), "domain.y.cells=" + std::to_string(cells_y)});
    BodyRun run(c, MPI_COMM_WORLD);
    run.run_to(c.end_time);

    const double angle = c.bodies[0].angle, W = std::cos(angle), nu = c.viscosity;
    const Vec2 t(std::cos(angle), std::sin(angle)), n(-std::sin(angle), std::cos(angle));
    const double f = Vec2(c.body_force[0], c.body_force[1]).dot(t), u_max = f * W * W / (8 * nu);
    const Body& body = run.ibm.bodies()[0];
    const Grid& g = run.solver.grid();
    const double h = g.x_axis().width(0);
    const auto markers = body.outline().markers(0.5 * h);
    std::vector<Vec2> points;
    for (const Marker& m : markers) points.push_back(m.position);
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
    // Profile: distance of each cell centre from the nearest image of the plane, n in [0, W).
    Field2D uc(g), vc(g);
    cell_centred_velocity(g, run.solver.velocity(), uc, vc);
    double profile_error = 0.0;
    for (int j = 0; j < g.ny(); ++j)
        for (int i = 0; i < g.nx(); ++i) {
            const Vec2 x(g.lx().c(i), g.ly().c(j));
            const double d = std::fmod(std::fmod(x.dot(n), W) + W, W);
            if (d < 3 * h || d > W - 3 * h) continue;
            const double exact = f * d * (W - d) / (2 * nu);
            profile_error = std::max(profile_error, std::abs(Vec2(uc(i, j), vc(i, j)).dot(t) - exact));
        }
    MPI_Allreduce(MPI_IN_PLACE, &profile_error, 1, MPI_DOUBLE, MPI_MAX, g.comm());
    const PlaneFlow r{net / (u_max * length), gross / (u_max * length), profile_error / u_max};
    if (g.rank() == 0)
        std::printf(
            "inclined plane (30 deg), %dx%d: net flux %.2e u_max L, gross |u.n| flux %.2e u_max L, "
            "max slip after forcing %.2e u_max, profile error %.3f u_max\n",
            cells_x, cells_y, r.net_flux, r.gross_flux, run.last[0].max_slip / u_max, r.profile_error);
    return r;
}

}  // namespace

// Steady state (6 s = 4 viscous times W^2/nu) at W/h = 14 and 28:
//   - the net flux through the outline, |sum (u . n) ds|, and the flux of |u . n|, below 0.5 % of u_max L
//     (the forcing leaves a slip of ~1e-3 u_max at the markers after the projection);
//   - the along-plane velocity at least 3 cells from the plane converges to the exact profile at first order
//     (observed order >= 0.9): the diffuse interface thickens the plane by about one cell (the channel is
//     narrower by ~1.1 h; docs/validation.md), the first-order error of regularised-delta forcing.
TEST(MovingBodies, NoFlowThroughAnInclinedPlane) {
    const PlaneFlow coarse = inclined_channel(28, 16), fine = inclined_channel(56, 32);
    for (const PlaneFlow& r : {coarse, fine}) {
        EXPECT_LT(std::abs(r.net_flux), 0.005);
        EXPECT_LT(r.gross_flux, 0.005);
    }
    const double order = std::log2(coarse.profile_error / fine.profile_error);
    std::printf("inclined plane: profile error order %.2f\n", order);
    EXPECT_GE(order, 0.9);
    EXPECT_LT(fine.profile_error, 0.1);
}
