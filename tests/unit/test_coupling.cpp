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
