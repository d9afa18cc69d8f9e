// The strong coupling of a free body on the sharp interface with ghost faces (ibm/immersed_boundary.hpp,
// added_mass / body_moved; ibm/cut_faces.hpp, pressure_wrenches): the body's translation is solved with the added
// mass the cut pressure problem gives it, and the flow is brought to the body's final velocity. Runs on 1 and 2 ranks.
#include <gtest/gtest.h>
#include <mpi.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "case_file.hpp"
#include "falling_square.hpp"
#include "model.hpp"
#include "step.hpp"

using namespace chute;

namespace {

// The unit square of falling_square.hpp at 16 cells across (`refinement` times that) on the sharp interface, 0.3 cell
// off the grid lines.
CaseConfig sharp_falling_square(double density, int refinement = 1) {
    const std::string offset = std::to_string(0.3 / (16.0 * refinement));
    return parse_case_text(falling_square_case(64 * refinement, 128 * refinement),
                           {"bodies.square.density=" + std::to_string(density), "bodies.square.carrier=immersed",
                            "bodies.square.centre=[" + offset + ", " + offset + "]", "numerics.ibm.interface=sharp",
                            "numerics.ibm.sharp_faces=ghost", "numerics.poisson={tolerance: 1.0e-12}"});
}

// The first step's added mass, -F / (rho a), and the cut problem's (the response's M_yy / rho).
std::pair<double, double> start_added_mass(double density, int refinement) {
    Model model(sharp_falling_square(density, refinement), MPI_COMM_WORLD);
    take_step(model, model.stable_dt());
    const BodyForces f = measure_forces(model).at(0);
    const double a = model.carrier().bodies()[0].state().acceleration.y();
    return {-f.forcing.y() / a / 1000.0, (*model.carrier().added_mass(0))(1, 1) / 1000.0};
}

}  // namespace

// The same contract as the body-fitted carrier's (test_body_fitted.cpp, FreeBodyIsCoupledExactlyEveryStep): after
// every step the force of the flow as the update left it (a, the record) is the force that moved the body,
// m a = F + W, to the Poisson tolerance, whatever the density ratio; a body ten times lighter than the water it
// displaces rises smoothly, its acceleration never above the start's (m - m_f) g / (m + M).
// The added mass the cut problem finds is the square's in this channel: 1.1885 rho d^2 unbounded (Sedov 1965), 1.30
// with the side walls 1.5 d away on the body-fitted carrier at 8 cells across (test_body_fitted.cpp); measured here
// 1.335 at 16 cells across. The first step answers with more (from -F / a): the force counts the momentum the fluid
// gains, and the fluid's share of the faces beside the surface (SharpForcing::held_momentum: the part of each face's
// volume outside the body) starts with the body's velocity in that step, a layer the response (the shut parts'
// pressure alone) leaves out. It is a layer of cells: measured 1.4900 / 1.4634 (light / heavy) against 1.3346 at 16
// cells, 1.4190 / 1.4075 against 1.3468 at 32 (+11.6 / +9.7 %, then +5.4 / +4.5 %: the excess halves), so held to
// first order: the excess at 32 cells at most 0.65 of that at 16. (The set of faces whose centres are inside, the
// measure before, read 1.430 / 1.419 at 16 cells.)
// Before (the pressure a step late, no response) the study's block diverged as it neared the bed and its start
// kept 93 % of a 2.2 m/s release speed where its added mass leaves 64 % (docs/validation.md, "Sharp interface",
// seventh step).
TEST(SharpCoupling, FreeBodyIsCoupledExactlyEveryStep) {
    for (const double density : {100.0, 2500.0}) {
        Model model(sharp_falling_square(density), MPI_COMM_WORLD);
        const double m = density, m_f = 1000.0, g = 9.81;
        double worst = 0.0, v_last = 0.0, a_start = 0.0, ca = 0.0;
        bool monotonic = true, bounded = true;
        for (int k = 0; k < 40; ++k) {
            take_step(model, model.stable_dt());
            const BodyForces f = measure_forces(model).at(0);
            const BodyState& s = model.carrier().bodies()[0].state();
            const Eigen::Matrix3d M = *model.carrier().added_mass(0);
            if (k == 0) {
                ca = M(1, 1) / m_f;
                a_start = (m - m_f) * -g / (m + M(1, 1));
                const double start_ca = -f.forcing.y() / s.acceleration.y() / m_f;
                const auto [fine_start, fine_ca] = start_added_mass(density, 2);
                int me = 0;
                MPI_Comm_rank(MPI_COMM_WORLD, &me);
                if (me == 0)
                    std::printf("density %.0f: first step's C_a %.4f against %.4f (16 cells), %.4f against %.4f (32)\n",
                                density, start_ca, ca, fine_start, fine_ca);
                EXPECT_GT(start_ca, ca);
                EXPECT_LT(fine_start - fine_ca, 0.65 * (start_ca - ca)) << "density " << density;
                EXPECT_EQ(M(0, 0), 0.0);  // x is locked: not solved for
                // The square sits 0.3 cell off the channel's middle: a little sideways push (measured 0.36 %).
                EXPECT_NEAR(M(0, 1), 0.0, 0.01 * M(1, 1));
            }
            const double residual =
                m * s.acceleration.y() - (f.forcing.y() + f.loads.gravity.y() + f.loads.buoyancy.y());
            worst = std::max(worst, std::abs(residual) / std::abs((m_f - m) * g));
            monotonic = monotonic && std::abs(s.velocity.y()) > std::abs(v_last);
            bounded = bounded && std::abs(s.acceleration.y()) <= std::abs(a_start) * 1.01;
            v_last = s.velocity.y();
            if (std::getenv("CHUTE_TRACE"))
                std::printf("  t %.4f a %.5f v %.5f F %.6e W %.6e M %.2f residual %.3e\n", model.flow().time(),
                            s.acceleration.y(), s.velocity.y(), f.forcing.y(),
                            f.loads.gravity.y() + f.loads.buoyancy.y(), M(1, 1), residual);
            EXPECT_EQ(s.velocity.x(), 0.0);
        }
        int rank = 0;
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        if (rank == 0)
            std::printf(
                "free sharp square, density %.0f: C_a %.4f, start %.4f m/s^2, after 40 steps v %.4f m/s, "
                "worst |m a - F - W| %.1e of the net weight\n",
                density, ca, a_start, v_last, worst);
        EXPECT_GT(ca, 1.30);
        EXPECT_LT(ca, 1.37);
        EXPECT_LT(worst, 1e-9);
        EXPECT_TRUE(monotonic);
        EXPECT_TRUE(bounded);
    }
}

// A body free in all three motions: a 1 x 0.5 rectangle turned 0.5 rad, denser and lighter than the water. The added
// mass couples its translation and rotation (a turned body pushed along one axis turns and drifts); the update solves
// all three with it, so m a = F + W along x and y and I alpha = T about the centre hold to the Poisson tolerance in
// every step. The matrix is the cut problem's own: M = B^T L^-1 B with B the shut parts' flux and its transpose the
// shut parts' pressure force (CutFaces::pressure_wrenches), so it is symmetric to the response's solve tolerance
// (1e-8 here: 1e4 times the projection's 1e-12) and positive definite, as a potential flow's added mass is.
TEST(SharpCoupling, TurnedRectangleIsCoupledExactlyInAllThreeMotions) {
    for (const double density : {500.0, 2500.0}) {
        const CaseConfig c =
            parse_case_text(falling_square_case(64, 128),
                            {"bodies.square.density=" + std::to_string(density), "bodies.square.carrier=immersed",
                             "bodies.square.size=[1.0, 0.5]", "bodies.square.angle=0.5",
                             "bodies.square.motion={type: free}", "numerics.ibm.interface=sharp",
                             "numerics.ibm.sharp_faces=ghost", "numerics.poisson={tolerance: 1.0e-12}"});
        Model model(c, MPI_COMM_WORLD);
        const double area = 0.5, m = density * area, inertia = m * (1.0 + 0.25) / 12.0, g = 9.81;
        double worst_force = 0.0, worst_torque = 0.0, worst_asymmetry = 0.0, omega_last = 0.0;
        for (int k = 0; k < 30; ++k) {
            take_step(model, model.stable_dt());
            const BodyForces f = measure_forces(model).at(0);
            const BodyState& s = model.carrier().bodies()[0].state();
            const Eigen::Matrix3d M = *model.carrier().added_mass(0);
            const Vec2 residual = m * s.acceleration - (f.forcing + f.loads.gravity + f.loads.buoyancy);
            const double weight = std::abs(1000.0 - density) * area * g;
            worst_force = std::max(worst_force, residual.norm() / weight);
            worst_torque = std::max(worst_torque, std::abs(inertia * s.angular_acceleration - f.forcing_torque) /
                                                      (weight * 0.5));  // a lever of half the length
            worst_asymmetry = std::max(worst_asymmetry, (M - M.transpose()).norm() / M.norm());
            EXPECT_GT(
                Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(0.5 * (M + M.transpose())).eigenvalues().minCoeff(),
                0.0);
            omega_last = s.angular_velocity;
        }
        int rank = 0;
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        const Eigen::Matrix3d M = *model.carrier().added_mass(0);
        if (rank == 0)
            std::printf(
                "free sharp rectangle, density %.0f: M = [%.1f %.1f %.1f; %.1f %.1f %.1f; %.1f %.1f %.2f], omega %.4f "
                "rad/s, worst |m a - F - W| %.1e, |I alpha - T| %.1e, asymmetry %.1e\n",
                density, M(0, 0), M(0, 1), M(0, 2), M(1, 0), M(1, 1), M(1, 2), M(2, 0), M(2, 1), M(2, 2), omega_last,
                worst_force, worst_torque, worst_asymmetry);
        EXPECT_LT(worst_force, 1e-9);
        EXPECT_LT(worst_torque, 1e-9);
        EXPECT_LT(worst_asymmetry, 1e-6);
        EXPECT_NE(omega_last, 0.0);  // it turns
    }
}

// Measure (a) is the same for a prescribed body as for a free one on ghost faces (ImmersedBoundary::measure): the
// square of the first test, accelerated from rest at a = -2 m/s^2 along y in steps of 5 ms (0.04 of a cell in all,
// so no face changes class), reads the added mass the free square's coupling solves for, C_a 1.335 in this channel
// (first test): -F_y / a = C_a m_f to within the ghost faces' share that the response leaves out (+7 % in the first
// test's first step; measured here 1.400 to 1.446, +5 to +8 %), held to -3 / +12 %. The viscous drag is small beside
// it (estimated: C_D about 2 at Re = |v| d / nu = 100 at the end gives 10 N against 2800 N). The rigid-body form it
// replaced took the faces inside as moving with the body, where ghost faces hold mirror images, and met the
// projection's pressure a step late: it read C_a 0.108 in the first step and 1.51 after (+13 %).
TEST(SharpCoupling, PrescribedBodyReadsTheFreeBodysAddedMass) {
    std::string text = falling_square_case(64, 128);
    text.erase(text.find("    density: 2500.0\n"), std::string("    density: 2500.0\n").size());  // not free
    const CaseConfig c =
        parse_case_text(text, {"bodies.square.carrier=immersed", "bodies.square.centre=[0.01875, 0.01875]",
                               "bodies.square.motion={type: uniform_acceleration, acceleration: [0.0, -2.0]}",
                               "numerics.ibm.interface=sharp", "numerics.ibm.sharp_faces=ghost",
                               "numerics.poisson={tolerance: 1.0e-12}"});
    Model model(c, MPI_COMM_WORLD);
    const double a = -2.0, m_f = 1000.0;
    double lowest = 1e9, highest = 0.0;
    for (int k = 0; k < 10; ++k) {
        take_step(model, 0.005);  // 10 steps: 0.04 of a cell, the flow barely started (Re = |v| d / nu <= 100)
        const double ca = -measure_forces(model).at(0).forcing.y() / a / m_f;
        if (std::getenv("CHUTE_TRACE"))
            std::printf("  t %.4f v %.4f C_a %.4f\n", model.flow().time(),
                        model.carrier().bodies()[0].state().velocity.y(), ca);
        lowest = std::min(lowest, ca);
        highest = std::max(highest, ca);
    }
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0)
        std::printf("prescribed sharp square accelerated from rest: C_a from -F / a over 10 steps %.4f to %.4f\n",
                    lowest, highest);
    EXPECT_GT(lowest, 1.335 * 0.97);
    EXPECT_LT(highest, 1.335 * 1.12);
}

// Cut momentum (numerics.ibm.cut_momentum) without ghost faces stops with a message naming the key (the schema's
// `when`); with k-epsilon and with several bodies it runs.
TEST(SharpCoupling, CutMomentumWithoutGhostFacesIsRefusedNamingTheKey) {
    const std::string base = R"(
domain:
  x: {start: 0.0, end: 1.0, cells: 20}
  y: {start: 0.0, end: 1.0, cells: 20}
fluid: {density: 1000.0, viscosity: 1.0e-3}
boundaries:
  left: {type: inflow, velocity: [1.0, 0.0]}
  right: {type: outflow}
  bottom: {type: slip}
  top: {type: slip}
bodies:
  block: {shape: rectangle, centre: [0.4, 0.5], size: [0.2, 0.2]}
numerics: {ibm: {interface: sharp, sharp_faces: ghost, cut_momentum: true}}
time: {end: 1.0}
)";
    auto message = [](const std::string& text, const std::vector<std::string>& overrides) {
        try {
            Model model(parse_case_text(text, overrides), MPI_COMM_WORLD);
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(message(base, {}), "");
    EXPECT_EQ(message(base, {"turbulence.model=k_epsilon"}), "");
    std::string second = base;
    second.replace(second.find("numerics:"), 0, "  stone: {shape: circle, centre: [0.75, 0.5], diameter: 0.1}\n");
    EXPECT_EQ(message(second, {}), "");
    EXPECT_NE(message(base, {"numerics.ibm.sharp_faces=forcing"}).find("cut_momentum"), std::string::npos);
}

// Galilean invariance of the force measure (a): a body carried at U through fluid moving at U everywhere is the
// fluid at rest about a body at rest, so the force is zero. The flow keeps the uniform stream to round-off (every face
// holds U, the ghosts' mirror is U, the cut fluxes are U's), so (a) is the change of the momentum the body's region
// holds, U times the sum of the parts of the faces' volumes inside the body. With those parts taken along the surface's
// normal, the corners' were wrong by a changing amount, and a square carried down a cell at 1 m/s read a force that
// swung between -0.06 and +0.06 (8 % of its drag at Re 100) with its place in its cells; with the parts' exact areas
// the sum is the body's area wherever it lies. Square, disk and a square turned 30 degrees, carried across cells in
// x and y over 30 steps.
TEST(SharpCoupling, BodyCarriedWithTheStreamFeelsNoForce) {
    const std::string common = R"(
domain:
  x: {start: -1.5, end: 1.5, cells: 36}
  y: {start: -1.5, end: 1.5, cells: 36}
fluid: {density: 1000.0, viscosity: 1.0e-5}
boundaries: {left: {type: periodic}, right: {type: periodic}, bottom: {type: periodic}, top: {type: periodic}}
initial: {velocity: [0.3, -1.0]}
numerics:
  convection: central
  dt: 0.01
  poisson: {tolerance: 1.0e-12}
  ibm: {interface: sharp, sharp_faces: ghost, cut_momentum: true}
time: {end: 1.0}
bodies:
  block:
    centre: [0.013, -0.021]
    motion: {type: constant_velocity, velocity: [0.3, -1.0]}
)";
    // The scale: the drag such a body has in a stream of U, rho U^2 d / 2 per unit depth.
    const double scale = 0.5 * 1000.0 * (0.09 + 1.0) * 1.0;
    for (const std::string shape : {"shape: rectangle\n    size: [1.0, 1.0]", "shape: circle\n    diameter: 1.0",
                                    "shape: rectangle\n    size: [1.0, 1.0]\n    angle: 30.0"}) {
        Model model(parse_case_text(common + "    " + shape + "\n"), MPI_COMM_WORLD);
        double largest = 0.0;
        for (int step = 0; step < 30; ++step) {
            take_step(model, 0.01);
            const BodyForces f = measure_forces(model).at(0);
            largest = std::max({largest, f.forcing.norm() / scale, std::abs(f.forcing_torque) / scale});
        }
        EXPECT_LT(largest, 1e-9) << shape;
    }
}
