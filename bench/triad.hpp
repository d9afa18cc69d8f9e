#pragma once
// STREAM's triad, a = b + s c (McCalpin 1995, https://www.cs.virginia.edu/stream/), run by every rank at once:
// the memory bandwidth the benchmarks measure themselves against, in the same run. Bytes are counted as STREAM
// counts them, 24 per element (two reads, one write; the write-allocate read not counted), and the arrays are far
// larger than any cache the guest reports (3 x 2^26 doubles, 1.5 GiB per rank).
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <vector>

namespace chute::bench {

struct Triad {
    double total_gbs = 0.0;     // all ranks together, GB/s (1e9 bytes)
    double per_rank_gbs = 0.0;  // total / ranks
};

inline Triad measure_triad(MPI_Comm comm, std::size_t elements = std::size_t{1} << 26, int repeats = 10) {
    int ranks = 1;
    MPI_Comm_size(comm, &ranks);
    std::vector<double> a(elements, 0.0), b(elements, 1.0), c(elements, 2.0);  // first touch by this rank
    const double s = 3.0;
    double best = INFINITY;
    for (int r = 0; r < repeats; ++r) {
        MPI_Barrier(comm);
        const auto t0 = std::chrono::steady_clock::now();
        double* __restrict pa = a.data();
        const double* __restrict pb = b.data();
        const double* __restrict pc = c.data();
        for (std::size_t i = 0; i < elements; ++i) pa[i] = pb[i] + s * pc[i];
        double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        MPI_Allreduce(MPI_IN_PLACE, &t, 1, MPI_DOUBLE, MPI_MAX, comm);
        best = std::min(best, t);
    }
    volatile double keep = a[elements / 2];  // the loop's result is used
    (void)keep;
    Triad t;
    t.total_gbs = 24.0 * static_cast<double>(elements) * ranks / best / 1e9;
    t.per_rank_gbs = t.total_gbs / ranks;
    return t;
}

}  // namespace chute::bench
