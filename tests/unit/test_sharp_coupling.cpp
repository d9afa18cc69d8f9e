// The strong coupling of a free body on the sharp interface with ghost faces (ibm/immersed_boundary.hpp,
// added_mass / body_moved; ibm/cut_faces.hpp, pressure_wrenches): the body's translation is solved with the added
// mass the cut pressure problem gives it, and the flow is brought to the body's final velocity. Runs on 1 and 2 ranks.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "case_file.hpp"
#include "falling_square.hpp"
#include "model.hpp"
#include "step.hpp"

using namespace chute;

namespace {

// The unit square of falling_square.hpp at 16 cells across on the sharp interface, 0.3 cell off the grid lines.
CaseConfig sharp_falling_square(double density) {
    return parse_case_text(falling_square_case(64, 128),
                           {"bodies.square.density=" + std::to_string(density), "bodies.square.carrier=immersed",
                            "bodies.square.centre=[0.01875, 0.01875]", "numerics.ibm.interface=sharp",
                            "numerics.ibm.sharp_faces=ghost", "numerics.poisson={tolerance: 1.0e-12}"});
}

}  // namespace

// The same contract as the body-fitted carrier's (test_body_fitted.cpp, FreeBodyIsCoupledExactlyEveryStep): after
// every step the force of the flow as the update left it (a, the record) is the force that moved the body,
// m a = F + W, to the Poisson tolerance, whatever the density ratio; a body ten times lighter than the water it
// displaces rises smoothly, its acceleration never above the start's (m - m_f) g / (m + M).
// The added mass the cut problem finds is the square's in this channel: 1.1885 rho d^2 unbounded (Sedov 1965), 1.30
// with the side walls 1.5 d away on the body-fitted carrier at 8 cells across (test_body_fitted.cpp); measured here
// 1.335 at 16 cells across. The first step answers with a little more (measured 1.430 light, 1.419 heavy, from
// -F / a): the ghost faces' mirrored values, which the cut faces' open parts carry, answer the body's velocity too,
// and the response (the shut parts alone) leaves them out; held to 10 %.
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
            const Eigen::Matrix2d M = *model.carrier().added_mass(0);
            if (k == 0) {
                ca = M(1, 1) / m_f;
                a_start = (m - m_f) * -g / (m + M(1, 1));
                const double start_ca = -f.forcing.y() / s.acceleration.y() / m_f;
                EXPECT_NEAR(start_ca, ca, 0.1 * ca) << "density " << density;
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
