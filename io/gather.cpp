#include "gather.hpp"

#include <exception>
#include <stdexcept>
#include <string>

#include "output_error.hpp"

namespace chute {

namespace {

void check_field(const char* who, const Grid& grid, const Field2D& f, int extra_x, int extra_y) {
    if (f.nx() != grid.nx() || f.ny() != grid.ny())
        throw std::invalid_argument(std::string(who) + ": field of " + std::to_string(f.nx()) + " x " +
                                    std::to_string(f.ny()) + " cells on a patch of " + std::to_string(grid.nx()) +
                                    " x " + std::to_string(grid.ny()));
    if (extra_x < 0 || extra_x > 1 || extra_y < 0 || extra_y > 1)
        throw std::invalid_argument(std::string(who) + ": extra_x and extra_y must be 0 or 1");
}

// The block of the global array a patch contributes: its cells, plus the extra face column (row) if it
// touches the right (top) side of a non-periodic axis. (On a periodic axis rank 0 copies column 0 instead.)
struct Block {
    int i0, j0, w, h;
};

Block own_block(const Grid& grid, int extra_x, int extra_y, bool for_scatter) {
    const bool add_x = extra_x > 0 && grid.touches(Side::right) && (for_scatter || !grid.x_axis().periodic());
    const bool add_y = extra_y > 0 && grid.touches(Side::top) && (for_scatter || !grid.y_axis().periodic());
    return {grid.lx().offset, grid.ly().offset, grid.nx() + (add_x ? 1 : 0), grid.ny() + (add_y ? 1 : 0)};
}

}  // namespace

std::vector<double> gather_global(const Grid& grid, const Field2D& f, int extra_x, int extra_y) {
    check_field("gather_global", grid, f, extra_x, extra_y);
    const MPI_Comm comm = grid.comm();
    const int size = grid.size();
    const bool root = grid.rank() == 0;

    const Block b = own_block(grid, extra_x, extra_y, false);
    std::vector<double> send(static_cast<std::size_t>(b.w) * b.h);
    for (int j = 0; j < b.h; ++j)
        for (int i = 0; i < b.w; ++i) send[static_cast<std::size_t>(j) * b.w + i] = f(i, j);

    int mine[4] = {b.i0, b.j0, b.w, b.h};
    std::vector<int> blocks(root ? 4 * size : 0);
    MPI_Gather(mine, 4, MPI_INT, blocks.data(), 4, MPI_INT, 0, comm);

    std::vector<int> counts(root ? size : 0), displs(root ? size : 0);
    int total = 0;
    if (root) {
        for (int r = 0; r < size; ++r) {
            counts[r] = blocks[4 * r + 2] * blocks[4 * r + 3];
            displs[r] = total;
            total += counts[r];
        }
    }
    std::vector<double> recv(root ? total : 0);
    MPI_Gatherv(send.data(), static_cast<int>(send.size()), MPI_DOUBLE, recv.data(), counts.data(), displs.data(),
                MPI_DOUBLE, 0, comm);
    if (!root) return {};

    const int gw = grid.global_nx() + extra_x;
    const int gh = grid.global_ny() + extra_y;
    std::vector<double> global(static_cast<std::size_t>(gw) * gh, 0.0);
    for (int r = 0; r < size; ++r) {
        const int i0 = blocks[4 * r], j0 = blocks[4 * r + 1], w = blocks[4 * r + 2], h = blocks[4 * r + 3];
        const double* src = recv.data() + displs[r];
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                global[static_cast<std::size_t>(j0 + j) * gw + (i0 + i)] = src[static_cast<std::size_t>(j) * w + i];
    }
    // Periodic axes: the face at the far end is face 0.
    if (extra_x > 0 && grid.x_axis().periodic())
        for (int j = 0; j < gh; ++j)
            global[static_cast<std::size_t>(j) * gw + (gw - 1)] = global[static_cast<std::size_t>(j) * gw];
    if (extra_y > 0 && grid.y_axis().periodic())
        for (int i = 0; i < gw; ++i) global[static_cast<std::size_t>(gh - 1) * gw + i] = global[i];
    return global;
}

void scatter_global(const Grid& grid, const std::vector<double>& global, Field2D& f, int extra_x, int extra_y) {
    check_field("scatter_global", grid, f, extra_x, extra_y);
    const int gw = grid.global_nx() + extra_x;
    const int gh = grid.global_ny() + extra_y;
    if (global.size() != static_cast<std::size_t>(gw) * gh)
        throw std::invalid_argument("scatter_global: global array of " + std::to_string(global.size()) +
                                    " values, expected " + std::to_string(gh) + " rows of " + std::to_string(gw));
    const Block b = own_block(grid, extra_x, extra_y, true);
    for (int j = 0; j < b.h; ++j)
        for (int i = 0; i < b.w; ++i) f(i, j) = global[static_cast<std::size_t>(b.j0 + j) * gw + (b.i0 + i)];
}

namespace {

// Every rank says whether it failed; if any did, the lowest failing rank's message is sent to all, and its
// kind: an OutputError (a result file that could not be written) stays one on every rank, so that every rank
// stops with the same exit code.
void agree(MPI_Comm comm, const std::string& error, bool failed, bool output_error) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    int mine = failed ? rank : size;
    int first = size;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
    if (first == size) return;
    int header[2] = {rank == first ? static_cast<int>(error.size()) : 0, output_error ? 1 : 0};
    MPI_Bcast(header, 2, MPI_INT, first, comm);
    std::string message = rank == first ? error : std::string(static_cast<std::size_t>(header[0]), '\0');
    MPI_Bcast(message.data(), header[0], MPI_CHAR, first, comm);
    if (header[1] != 0) throw OutputError(message);
    throw std::runtime_error(message);
}

void run_and_agree(MPI_Comm comm, const std::function<void()>& work, bool run_here) {
    std::string error;
    bool failed = false, output_error = false;
    if (run_here) {
        try {
            work();
        } catch (const OutputError& e) {
            error = e.what();
            failed = output_error = true;
        } catch (const std::exception& e) {
            error = e.what();
            failed = true;
        } catch (...) {
            error = "unknown error";
            failed = true;
        }
    }
    agree(comm, error, failed, output_error);
}

}  // namespace

void run_on_root(MPI_Comm comm, const std::function<void()>& work) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    run_and_agree(comm, work, rank == 0);
}

void run_on_all(MPI_Comm comm, const std::function<void()>& work) { run_and_agree(comm, work, true); }

}  // namespace chute
