// GoogleTest main for Chute: MPI and hypre must be initialised once around all tests.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdio>

#include <HYPRE_utilities.h>

#include "leak_check.hpp"

int main(int argc, char** argv) {
    CHUTE_LSAN_IGNORE_BEGIN;
    MPI_Init(&argc, &argv);
    HYPRE_Init();
    CHUTE_LSAN_IGNORE_END;
    ::testing::InitGoogleTest(&argc, argv);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    // Only rank 0 prints results, so a 2-rank test reads like a 1-rank one.
    if (rank != 0) {
        auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
        delete listeners.Release(listeners.default_result_printer());
    }
    const int result = RUN_ALL_TESTS();
    // Ranks other than 0 print nothing while the tests run: name what failed there, so a failure seen
    // only on rank 1 (a patch-local check, say) is not a silent non-zero exit.
    if (rank != 0 && result != 0) {
        const auto& unit = *::testing::UnitTest::GetInstance();
        for (int s = 0; s < unit.total_test_suite_count(); ++s) {
            const auto& suite = *unit.GetTestSuite(s);
            for (int t = 0; t < suite.total_test_count(); ++t)
                if (suite.GetTestInfo(t)->result()->Failed())
                    std::fprintf(stderr, "rank %d: FAILED %s.%s\n", rank, suite.name(), suite.GetTestInfo(t)->name());
        }
    }
    CHUTE_LSAN_IGNORE_BEGIN;
    HYPRE_Finalize();
    MPI_Finalize();
    CHUTE_LSAN_IGNORE_END;
    return result;
}
