#pragma once
// Moving whole fields between the patches and rank 0, for output and restart.
//
// A global array is row-major with x fastest: (global_ny + extra_y) rows of (global_nx + extra_x) values,
// element (I, J) at [I + J * (global_nx + extra_x)] for global indices I, J. extra_x = 1 adds the face
// column at I = global_nx (the right boundary faces of u), extra_y = 1 the face row at J = global_ny (the
// top boundary faces of v). On a patch these live in the ghost slot i = nx (j = ny) of the patches that
// touch Side::right (Side::top). On a periodic axis that face is face 0, so the extra column (row) is a
// copy of column (row) 0.
#include <functional>
#include <vector>

#include "field.hpp"
#include "grid.hpp"

namespace chute {

// Collective over grid.comm(). Rank 0 receives the global array; the other ranks get an empty vector.
std::vector<double> gather_global(const Grid& grid, const Field2D& f, int extra_x = 0, int extra_y = 0);

// Not collective: each rank copies its own cells from `global` (held by every rank), and, where it touches
// Side::right (Side::top), the extra column (row) into its ghost slot i = nx (j = ny).
void scatter_global(const Grid& grid, const std::vector<double>& global, Field2D& f, int extra_x = 0, int extra_y = 0);

// Error agreement for collective I/O, so that no rank is left waiting in a collective call when another
// has thrown. Both are collective over `comm`; if `work` throws anywhere, every rank throws a
// std::runtime_error carrying the message of the lowest failing rank (an OutputError if that was one).
// run_on_root: `work` runs on rank 0 only (the rank that writes after a gather).
void run_on_root(MPI_Comm comm, const std::function<void()>& work);
// run_on_all: `work` runs on every rank (each reads its own part).
void run_on_all(MPI_Comm comm, const std::function<void()>& work);

}  // namespace chute
