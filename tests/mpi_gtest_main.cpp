// GoogleTest main for Chute: MPI and hypre must be initialised once around all tests.
#include <gtest/gtest.h>
#include <mpi.h>

#include <HYPRE_utilities.h>

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    HYPRE_Init();
    ::testing::InitGoogleTest(&argc, argv);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    // Only rank 0 prints results, so a 2-rank test reads like a 1-rank one.
    if (rank != 0) {
        auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
        delete listeners.Release(listeners.default_result_printer());
    }
    const int result = RUN_ALL_TESTS();
    HYPRE_Finalize();
    MPI_Finalize();
    return result;
}
