// The k-epsilon model's parts: the Boussinesq stress operator, the source treatment (decay of homogeneous
// turbulence against its closed form), free-stream behaviour without a body, and the case-file errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "case_file.hpp"
#include "case_settings.hpp"
#include "diffusion.hpp"
#include "flow_solver.hpp"
#include "immersed_boundary.hpp"
#include "k_epsilon.hpp"
#include "print_on_rank0.hpp"
#include "wall_function.hpp"

using namespace chute;

namespace {

CaseConfig periodic_box(int n) {
    CaseConfig c;
    const double L = 2.0 * std::numbers::pi;
    c.x = AxisConfig{0.0, L, n, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{0.0, L, n, "uniform", 2.0, 1.05, {}};
    for (auto& b : c.boundary) b.type = BoundaryType::periodic;
    c.viscosity = 0.01;
    return c;
}

double max_difference(const Grid& g, const Velocity& a, const Velocity& b) {
    double m = 0.0;
    for (int j = 0; j < g.ny(); ++j)
        for (int i = 0; i < g.nx(); ++i)
            m = std::max({m, std::abs(a.u(i, j) - b.u(i, j)), std::abs(a.v(i, j) - b.v(i, j))});
    MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_MAX, g.comm());
    return m;
}

}  // namespace

// With a uniform eddy viscosity c the stress divergence is (nu + c) laplacian(u) on a divergence-free
// field (the transpose part is grad(div u) = 0 discretely on the MAC grid): the Taylor-Green vortex.
TEST(KEpsilon, ViscousStressWithUniformEddyViscosityIsTheLaplacian) {
    CaseConfig c = periodic_box(32);
    c.initial = InitialCondition::taylor_green;
    FlowSolver s(c, MPI_COMM_WORLD);
    const Grid& g = s.grid();
    for (double nu_t : {0.0, 0.37}) {
        EddyViscosity e(g);
        e.cell.fill(nu_t);
        e.corner.fill(nu_t);
        Velocity a(g), b(g);
        add_viscous_stress(g, c.viscosity, e, s.velocity(), 0, 0, a);
        add_diffusion(g, c.viscosity + nu_t, s.velocity(), 0, 0, b);
        EXPECT_LT(max_difference(g, a, b), 1e-12) << "nu_t = " << nu_t;
    }
}

// Fluid at rest in a periodic box with uniform k and eps: no production, no transport, so
//   dk/dt = -eps, deps/dt = -C_2 eps^2 / k  =>  k(t) = k0 (1 + (C_2 - 1) eps0 t / k0)^(-1/(C_2 - 1)).
// The implicit sinks are first order in time: the error at t = 2 k0/eps0 must be below 1 % and halve
// with the step.
TEST(KEpsilon, DecayOfHomogeneousTurbulenceFollowsTheClosedForm) {
    auto error = [](double dt) {
        CaseConfig c = periodic_box(8);
        c.turbulence.model = TurbulenceModelType::k_epsilon;
        c.turbulence.velocity_scale = 1.0;
        FlowSolver s(c, MPI_COMM_WORLD);
        std::vector<Body> no_bodies;
        ImmersedBoundary none(s.grid(), immersed_boundary_settings(c), no_bodies);
        KEpsilon model(k_epsilon_settings(c), s, none);
        const double k0 = model.inflow_k(), e0 = model.inflow_epsilon(), T = 2.0 * k0 / e0;
        const int steps = static_cast<int>(std::lround(T / dt));
        for (int n = 0; n < steps; ++n) model.update(T / steps);
        const double C2 = KEpsilonConstants::c2;
        const double exact = k0 * std::pow(1.0 + (C2 - 1.0) * e0 * T / k0, -1.0 / (C2 - 1.0));
        return std::abs(model.k()(3, 3) - exact) / exact;
    };
    const double e1 = error(0.05), e2 = error(0.025);
    print_on_rank0("homogeneous decay: relative error of k at t = 2 k0/eps0: %.3e (dt), %.3e (dt/2)\n", e1, e2);
    EXPECT_LT(e2, 0.01);
    EXPECT_NEAR(e1 / e2, 2.0, 0.2);
}

// A uniform current between slip sides without a body: no shear, so no production, and k and eps only
// decay downstream of the inflow. Nothing rises above the inflow level (no spurious turbulence).
TEST(KEpsilon, UniformCurrentWithoutBodyMakesNoTurbulence) {
    CaseConfig c;
    c.x = AxisConfig{0.0, 4.0, 48, "uniform", 2.0, 1.05, {}};
    c.y = AxisConfig{0.0, 2.0, 24, "uniform", 2.0, 1.05, {}};
    c.boundary[0].type = BoundaryType::inflow;
    c.boundary[0].velocity = {1.0, 0.0};
    c.boundary[1].type = BoundaryType::outflow;
    c.boundary[2].type = c.boundary[3].type = BoundaryType::slip;
    c.initial_velocity = {1.0, 0.0};
    c.viscosity = 1e-4;
    c.convection = ConvectionScheme::van_leer;
    c.turbulence.model = TurbulenceModelType::k_epsilon;
    FlowSolver s(c, MPI_COMM_WORLD);
    std::vector<Body> no_bodies;
    ImmersedBoundary none(s.grid(), immersed_boundary_settings(c), no_bodies);
    KEpsilon model(k_epsilon_settings(c), s, none);
    const double nu_t_in = KEpsilonConstants::c_mu * model.inflow_k() * model.inflow_k() / model.inflow_epsilon();
    for (int n = 0; n < 400; ++n) {
        const double dt = s.next_dt();
        s.advance(dt);
        model.update(dt);
    }
    double m[2] = {0.0, 0.0};
    for (int j = 0; j < s.grid().ny(); ++j)
        for (int i = 0; i < s.grid().nx(); ++i)
            m[0] = std::max(m[0], model.k()(i, j)), m[1] = std::max(m[1], model.eddy_viscosity()(i, j));
    MPI_Allreduce(MPI_IN_PLACE, m, 2, MPI_DOUBLE, MPI_MAX, s.grid().comm());
    EXPECT_LE(m[0], model.inflow_k() * (1.0 + 1e-12));
    EXPECT_LE(m[1], nu_t_in * (1.0 + 1e-9));
}

// The wall function is consistent with the log law: at equilibrium (k = u_tau^2 / sqrt(C_mu), U_t from the
// log law) the shear is u_tau^2 and production balances dissipation.
TEST(KEpsilon, WallFunctionIsConsistentWithTheLogLaw) {
    using C = KEpsilonConstants;
    const double nu = 1e-6, u_tau = 0.05, y = 0.01;
    const double k = u_tau * u_tau / std::sqrt(C::c_mu);
    const WallFunction wf(k, y, nu);
    EXPECT_NEAR(wf.y_plus, u_tau * y / nu, 1e-9 * wf.y_plus);
    const double U = u_tau / C::kappa * std::log(C::E * wf.y_plus);
    const double tau = wf.shear(U, y, nu);
    EXPECT_NEAR(tau, u_tau * u_tau, 1e-12);
    EXPECT_NEAR(wf.production(tau, y), wf.dissipation(k, y, nu), 1e-12 * wf.dissipation(k, y, nu));
}

// The law of the wall as the sharp interface uses it (speed at y from the speed at L): from a log-layer profile with
// u_tau = 0.05 m/s (nu 1e-6, L 1 cm: y+ 500) it recovers the profile at y+ 250 and 50, and in the viscous layer
// (L 0.1 mm: y+ 5) it is linear. Newton's method to 1e-12 relative: held to 1e-10.
TEST(KEpsilon, LawOfTheWallSpeedFollowsTheTwoLayers) {
    using C = KEpsilonConstants;
    const double nu = 1e-6, u_tau = 0.05;
    auto log_law = [&](double y) { return u_tau / C::kappa * std::log(C::E * u_tau * y / nu); };
    const double L = 0.01;
    for (double y : {0.005, 0.001, 0.01})
        EXPECT_NEAR(law_of_the_wall_speed(log_law(L), L, y, nu), log_law(y), 1e-10 * log_law(y)) << "y " << y;
    // Below the switch (y+ 11.53 at y = 0.23 mm) the viscous layer: u = u_tau^2 y / nu.
    EXPECT_NEAR(law_of_the_wall_speed(log_law(L), L, 1e-4, nu), u_tau * u_tau * 1e-4 / nu, 1e-10);
    const double speed = 0.02, Lv = 1e-4;  // y+ = sqrt(speed Lv / nu) = 1.4: viscous
    EXPECT_NEAR(law_of_the_wall_speed(speed, Lv, 0.5 * Lv, nu), 0.5 * speed, 1e-15);
    EXPECT_EQ(law_of_the_wall_speed(0.0, L, 0.5 * L, nu), 0.0);
}
// k-epsilon in still water needs a speed for the initial k: the error names the key.
TEST(KEpsilon, StillWaterWithoutVelocityScaleIsAnError) {
    CaseConfig c = parse_case_text(R"(
domain: {x: {start: 0, end: 1, cells: 8}, y: {start: 0, end: 1, cells: 8}}
boundaries: {left: {type: wall}, right: {type: wall}, bottom: {type: wall}, top: {type: wall}}
fluid: {density: 1000.0, viscosity: 1.0e-6}
turbulence: {model: k_epsilon}
time: {end: 1.0}
)");
    FlowSolver s(c, MPI_COMM_WORLD);
    std::vector<Body> no_bodies;
    ImmersedBoundary none(s.grid(), immersed_boundary_settings(c), no_bodies);
    try {
        KEpsilon model(k_epsilon_settings(c), s, none);
        ADD_FAILURE() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("turbulence.velocity_scale"), std::string::npos) << e.what();
    }
    c.turbulence.velocity_scale = 2.0;
    KEpsilon model(k_epsilon_settings(c), s, none);
    EXPECT_NEAR(model.inflow_k(), 1.5 * std::pow(0.05 * 2.0, 2), 1e-15);
}

// Kato & Launder (1993): P_k = nu_t S Omega. In irrotational plane strain (u = a x, v = -a y) it vanishes
// where the standard nu_t S^2 = 4 a^2 nu_t does not (the stagnation-point excess of k); in simple shear
// (u = g y) both give nu_t g^2.
TEST(KEpsilon, KatoLaunderProductionVanishesInPureStrain) {
    for (bool kl : {false, true}) {
        CaseConfig c;
        c.x = AxisConfig{-1.0, 1.0, 16, "uniform", 2.0, 1.05, {}};
        c.y = AxisConfig{-1.0, 1.0, 16, "tanh", 1.5, 1.05, {}};
        for (auto& b : c.boundary) b.type = BoundaryType::slip;
        c.turbulence.model = TurbulenceModelType::k_epsilon;
        c.turbulence.velocity_scale = 1.0;
        c.turbulence.production_limit = 0.0;
        c.turbulence.kato_launder = kl;
        FlowSolver s(c, MPI_COMM_WORLD);
        std::vector<Body> no_bodies;
        ImmersedBoundary none(s.grid(), immersed_boundary_settings(c), no_bodies);
        KEpsilon model(k_epsilon_settings(c), s, none);
        const Grid& g = s.grid();
        const double nu_t = model.eddy_viscosity()(3, 3), a = 0.7, shear_rate = 1.3;
        Field2D P(g);
        double strain_err = 0.0, shear_err = 0.0;
        for (int flow = 0; flow < 2; ++flow) {
            Velocity& vel = s.velocity();
            for (int j = -kGhost; j < g.ny() + kGhost; ++j)
                for (int i = -kGhost; i < g.nx() + kGhost; ++i) {
                    vel.u(i, j) = flow == 0 ? a * g.lx().f(i) : shear_rate * g.ly().c(j);
                    vel.v(i, j) = flow == 0 ? -a * g.ly().f(j) : 0.0;
                }
            model.production(P);
            const double expected = flow == 0 ? (kl ? 0.0 : 4.0 * a * a * nu_t) : nu_t * shear_rate * shear_rate;
            double& err = flow == 0 ? strain_err : shear_err;
            for (int j = 0; j < g.ny(); ++j)
                for (int i = 0; i < g.nx(); ++i) err = std::max(err, std::abs(P(i, j) - expected));
        }
        MPI_Allreduce(MPI_IN_PLACE, &strain_err, 1, MPI_DOUBLE, MPI_MAX, g.comm());
        MPI_Allreduce(MPI_IN_PLACE, &shear_err, 1, MPI_DOUBLE, MPI_MAX, g.comm());
        print_on_rank0("%s production: pure strain error %.2e, simple shear error %.2e (of nu_t g^2 = %.3e)\n",
                       kl ? "Kato-Launder" : "standard", strain_err, shear_err, nu_t * shear_rate * shear_rate);
        EXPECT_LT(strain_err, 1e-12 * nu_t);
        EXPECT_LT(shear_err, 1e-12 * nu_t);
    }
}
