// The stopping rule of the strong coupling's passes (rigidbody/free_bodies.hpp, remaining_change).
#include <gtest/gtest.h>

#include <cmath>

#include "free_bodies.hpp"

using namespace chute;

// For a geometric sequence of changes the estimate is the exact sum of the changes still to come.
TEST(Coupling, RemainingChangeIsExactForAGeometricSequence) {
    for (const double r : {0.6, 0.9, 0.98}) {
        const double previous = 0.02, change = r * previous;
        const double to_come = change * r / (1.0 - r);  // sum over k >= 1 of change r^k
        EXPECT_NEAR(remaining_change(change, previous), to_come, 1e-12 * to_come) << "r = " << r;
    }
}

// A change of 1e-4 looks converged against a tolerance of 1e-2 by itself, but in a sequence converging at
// r = 0.98 (the impact passes' ratio, docs/validation.md) 49 times as much is still to come.
TEST(Coupling, SlowConvergenceIsNotTakenForConvergence) {
    EXPECT_GT(remaining_change(1e-4, 1e-4 / 0.98), 1e-2 * 0.45);
    EXPECT_LT(remaining_change(1e-4, 1e-4 / 0.5), 1e-2);
}

// Without an earlier change (the step's first correction), a fast contraction (r < 1/2) or a growing change,
// the estimate is never below the last change; a growing change counts as r = 0.99.
TEST(Coupling, RemainingChangeIsNeverBelowTheLastChange) {
    EXPECT_DOUBLE_EQ(remaining_change(0.3, -1.0), 0.3);
    EXPECT_DOUBLE_EQ(remaining_change(0.01, 0.1), 0.01);
    EXPECT_NEAR(remaining_change(0.05, 0.04), 0.05 * 99.0, 1e-12);
}

// The passes a geometric sequence still needs: at r = 0.9 from a remaining change of 0.09 (last change 0.01) to a
// tolerance of 0.01, 0.09 r^n <= 0.01 takes n = 21 (0.9^21 = 0.109, 0.9^20 = 0.122).
TEST(Coupling, PassesToToleranceCountsTheGeometricSequence) {
    EXPECT_DOUBLE_EQ(passes_to_tolerance(0.01, 0.01 / 0.9, 0.01), 21.0);
    EXPECT_DOUBLE_EQ(passes_to_tolerance(0.001, 0.002, 0.01), 0.0);  // there already
    EXPECT_DOUBLE_EQ(passes_to_tolerance(0.5, -1.0, 0.01), 0.0);     // no ratio yet: pass on and see
}

// A sequence whose change does not shrink (a flow far out of scale) needs more passes than the most allowed
// (1000): at the capped ratio 0.99 the remaining change 1e3 x 99 falls to 1e-2 in ln(1.01e-7) / ln(0.99) = 1603.
TEST(Coupling, AChangeThatDoesNotShrinkNeedsMorePassesThanAnyBudget) {
    EXPECT_DOUBLE_EQ(passes_to_tolerance(1e3, 1e3, 0.01), 1603.0);
}
