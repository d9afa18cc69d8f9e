#pragma once
// std::printf on rank 0 of MPI_COMM_WORLD only, so that a test's report line appears once on 2 ranks too
// (the values printed must be the same on every rank: reduce them first).
#include <mpi.h>

#include <cstdarg>
#include <cstdio>

namespace chute {

[[gnu::format(printf, 1, 2)]] inline void print_on_rank0(const char* format, ...) {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank != 0) return;
    std::va_list args;
    va_start(args, format);
    std::vprintf(format, args);
    va_end(args);
}

}  // namespace chute
