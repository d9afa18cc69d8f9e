#pragma once
// Moving a cell array between two decompositions of the same global grid with one MPI_Alltoallv: from the
// ranks' patches to whole lines of one direction (pencils), from x pencils to y pencils and back. The
// transform-based Poisson solve (direct_poisson.hpp) needs each transform and each tridiagonal system on
// one rank, as CaNS does (Costa 2018, Comput. Math. Appl. 76:1853) with its 2D pencil decomposition.
#include <mpi.h>

#include <cstddef>
#include <vector>

namespace chute {

// A half-open rectangle of global cell indices [i0, i1) x [j0, j1).
struct CellBox {
    int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
    long long cells() const { return i1 > i0 && j1 > j0 ? 1LL * (i1 - i0) * (j1 - j0) : 0; }
};

// A rank's part of an array: its box and how it is stored (cell (i, j) at data[(i - i0) si + (j - j0) sj]).
struct BoxStorage {
    CellBox box;
    std::ptrdiff_t si = 1, sj = 0;
};

class PencilTranspose {
public:
    // Every rank of `comm` passes its own box and storage before and after; the boxes of each side must tile
    // the same global index space.
    PencilTranspose(MPI_Comm comm, const BoxStorage& from, const BoxStorage& to);
    void run(const double* from, double* to);

private:
    struct Block {  // the cells one rank sends to (or receives from) another
        CellBox box;
        int rank;
        int offset;  // into the send (receive) buffer
    };
    MPI_Comm comm_;
    BoxStorage from_, to_;
    std::vector<Block> sends_, receives_;
    CellBox self_;  // what stays on this rank: copied directly
    std::vector<int> send_counts_, send_offsets_, receive_counts_, receive_offsets_;
    std::vector<double> send_buffer_, receive_buffer_;
    bool alone_ = true;  // nothing crosses ranks: no MPI call
};

}  // namespace chute
