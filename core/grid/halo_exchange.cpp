#include "halo_exchange.hpp"

#include <mpi.h>

namespace chute {

void HaloExchange::exchange(Field2D& f) {
    const int nx = f.nx(), ny = f.ny();
    MPI_Comm comm = grid_.comm();
    const int lo_x = grid_.neighbour(Side::left), hi_x = grid_.neighbour(Side::right);
    const int lo_y = grid_.neighbour(Side::bottom), hi_y = grid_.neighbour(Side::top);

    // x direction: kGhost columns of the owned rows.
    const int nxmsg = kGhost * ny;
    send_lo_.resize(nxmsg);
    send_hi_.resize(nxmsg);
    recv_lo_.resize(nxmsg);
    recv_hi_.resize(nxmsg);
    for (int j = 0; j < ny; ++j)
        for (int g = 0; g < kGhost; ++g) {
            send_lo_[j * kGhost + g] = f(g, j);
            send_hi_[j * kGhost + g] = f(nx - kGhost + g, j);
        }
    MPI_Sendrecv(send_lo_.data(), nxmsg, MPI_DOUBLE, lo_x, 0, recv_hi_.data(), nxmsg, MPI_DOUBLE, hi_x, 0, comm,
                 MPI_STATUS_IGNORE);
    MPI_Sendrecv(send_hi_.data(), nxmsg, MPI_DOUBLE, hi_x, 1, recv_lo_.data(), nxmsg, MPI_DOUBLE, lo_x, 1, comm,
                 MPI_STATUS_IGNORE);
    if (lo_x != MPI_PROC_NULL)
        for (int j = 0; j < ny; ++j)
            for (int g = 0; g < kGhost; ++g) f(g - kGhost, j) = recv_lo_[j * kGhost + g];
    if (hi_x != MPI_PROC_NULL)
        for (int j = 0; j < ny; ++j)
            for (int g = 0; g < kGhost; ++g) f(nx + g, j) = recv_hi_[j * kGhost + g];

    // y direction: kGhost rows, all columns including the x ghosts just filled.
    const int width = nx + 2 * kGhost;
    const int nymsg = kGhost * width;
    send_lo_.resize(nymsg);
    send_hi_.resize(nymsg);
    recv_lo_.resize(nymsg);
    recv_hi_.resize(nymsg);
    for (int g = 0; g < kGhost; ++g)
        for (int i = -kGhost; i < nx + kGhost; ++i) {
            send_lo_[g * width + i + kGhost] = f(i, g);
            send_hi_[g * width + i + kGhost] = f(i, ny - kGhost + g);
        }
    MPI_Sendrecv(send_lo_.data(), nymsg, MPI_DOUBLE, lo_y, 2, recv_hi_.data(), nymsg, MPI_DOUBLE, hi_y, 2, comm,
                 MPI_STATUS_IGNORE);
    MPI_Sendrecv(send_hi_.data(), nymsg, MPI_DOUBLE, hi_y, 3, recv_lo_.data(), nymsg, MPI_DOUBLE, lo_y, 3, comm,
                 MPI_STATUS_IGNORE);
    if (lo_y != MPI_PROC_NULL)
        for (int g = 0; g < kGhost; ++g)
            for (int i = -kGhost; i < nx + kGhost; ++i) f(i, g - kGhost) = recv_lo_[g * width + i + kGhost];
    if (hi_y != MPI_PROC_NULL)
        for (int g = 0; g < kGhost; ++g)
            for (int i = -kGhost; i < nx + kGhost; ++i) f(i, ny + g) = recv_hi_[g * width + i + kGhost];
}

}  // namespace chute
