// k-epsilon with wall functions against DNS (VALIDATION.md): the fully developed turbulent channel of
// examples/turbulent_channel, Re_tau 550 (del Alamo & Jimenez 2003) and 950 (Hoyas & Jimenez 2006).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "body_run.hpp"

using namespace chute;
using namespace chute::validation;

namespace {

struct ChannelResult {
    double bulk_plus, friction;  // U_b / u_tau, C_f = tau_w / (rho U_b^2 / 2) = 2 / U_b+^2
};

// u_tau = delta = 1, so U_b+ is the bulk velocity. Steady to 1e-10 relative change of U_b per unit time:
// the driving force fixes tau_w = 1 at the steady state, so U_b+ is what the model decides.
ChannelResult channel(double re_tau, int cells = 20) {
    const CaseConfig c = load_case(kExamples + "turbulent_channel/case.yaml",
                                   {"fluid.viscosity=" + std::to_string(1.0 / re_tau),
                                    "domain.y.cells=" + std::to_string(cells)});
    BodyRun run(c, MPI_COMM_WORLD);
    const Grid& g = run.solver.grid();
    auto bulk = [&] {
        double s[2] = {0.0, 0.0};
        for (int j = 0; j < g.ny(); ++j)
            for (int i = 0; i < g.nx(); ++i) s[0] += run.solver.velocity().u(i, j) * g.lx().w(i) * g.ly().w(j), s[1] += g.lx().w(i) * g.ly().w(j);
        MPI_Allreduce(MPI_IN_PLACE, s, 2, MPI_DOUBLE, MPI_SUM, g.comm());
        return s[0] / s[1];
    };
    double previous = bulk(), t_check = 1.0;
    for (;;) {
        run.step();
        if (run.solver.time() >= t_check) {
            const double now = bulk();
            if (std::abs(now - previous) < 1e-10 * now || run.solver.time() > 400.0) break;
            previous = now;
            t_check += 1.0;
        }
    }
    const double ub = bulk();
    return {ub, 2.0 / (ub * ub)};
}

}  // namespace

// DNS: U_b+ 18.40, C_f 5.91e-3 (Re_tau 550); 19.83, 5.09e-3 (Re_tau 950). The issue asks both within 5 %.
TEST(Turbulence, ChannelBulkVelocity) {
    const ChannelResult r550 = channel(550.0), r950 = channel(950.0);
    if (root())
        std::printf("turbulent channel, 20 cells: Re_tau 550: U_b+ %.3f (DNS 18.40), C_f %.4e (5.91e-3); "
                    "Re_tau 950: U_b+ %.3f (DNS 19.83), C_f %.4e (5.09e-3)\n",
                    r550.bulk_plus, r550.friction, r950.bulk_plus, r950.friction);
    EXPECT_NEAR(r550.bulk_plus, 18.40, 0.05 * 18.40);
    EXPECT_NEAR(r950.bulk_plus, 19.83, 0.05 * 19.83);
}

// C_f = 2 / U_b+^2 doubles the relative error of U_b+; standard k-epsilon with E = 9.8 puts C_f 6-7 % low
// (docs/validation.md). Kept at the 5 % and labelled slow: it fails, as a record of the model error.
TEST(Turbulence, ChannelFrictionCoefficient) {
    const ChannelResult r550 = channel(550.0), r950 = channel(950.0);
    if (root()) std::printf("turbulent channel: C_f %.4e (Re_tau 550), %.4e (950)\n", r550.friction, r950.friction);
    EXPECT_NEAR(r550.friction, 5.91e-3, 0.05 * 5.91e-3);
    EXPECT_NEAR(r950.friction, 5.09e-3, 0.05 * 5.09e-3);
}

// The answer does not depend on where the first cell centre sits inside the log layer (y+ 55, 27.5, 18).
TEST(Turbulence, ChannelIndependentOfTheFirstCell) {
    const double u10 = channel(550.0, 10).bulk_plus, u20 = channel(550.0, 20).bulk_plus, u30 = channel(550.0, 30).bulk_plus;
    if (root()) std::printf("turbulent channel Re_tau 550: U_b+ %.4f (10 cells), %.4f (20), %.4f (30)\n", u10, u20, u30);
    EXPECT_NEAR(u10, u20, 0.01 * u20);
    EXPECT_NEAR(u30, u20, 0.01 * u20);
}
