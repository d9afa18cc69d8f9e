#include "grid.hpp"

#include <stdexcept>
#include <string>

namespace chute {

void LocalAxis::build(const Axis& axis, int first_cell, int cells) {
    n = cells;
    offset = first_cell;
    const int size = cells + 2 * kGhost + 1;
    f_.assign(size, 0.0);
    c_.assign(size, 0.0);
    w_.assign(size, 0.0);
    dc_.assign(size, 0.0);
    for (int k = -kGhost; k < cells + kGhost + 1; ++k) {
        const int g = first_cell + k;
        f_[k + kGhost] = axis.line(g);
        c_[k + kGhost] = axis.centre(g);
        w_[k + kGhost] = axis.width(g);
        dc_[k + kGhost] = axis.centre(g) - axis.centre(g - 1);
    }
}

void block_range(int n, int p, int r, int& first, int& count) {
    count = n / p + (r < n % p ? 1 : 0);
    first = r * (n / p) + std::min(r, n % p);
}

Grid::Grid(Axis x, Axis y, MPI_Comm comm, int ranks_x, int ranks_y) : x_(std::move(x)), y_(std::move(y)) {
    int world = 1;
    MPI_Comm_size(comm, &world);
    dims_[0] = ranks_x > 0 ? ranks_x : 0;
    dims_[1] = ranks_y > 0 ? ranks_y : 0;
    if (dims_[0] > 0 && dims_[1] > 0 && dims_[0] * dims_[1] != world)
        throw std::invalid_argument("parallel.ranks: " + std::to_string(dims_[0]) + " x " + std::to_string(dims_[1]) +
                                    " patches do not match " + std::to_string(world) + " MPI ranks");
    // Prefer splitting the longer direction first (MPI_Dims_create returns dims in decreasing order).
    if (dims_[0] == 0 && dims_[1] == 0 && x_.cells() < y_.cells()) {
        int d[2] = {0, 0};
        MPI_Dims_create(world, 2, d);
        dims_[0] = d[1];
        dims_[1] = d[0];
    } else {
        MPI_Dims_create(world, 2, dims_);
    }
    // The halo exchange sends kGhost layers, so every patch needs at least kGhost cells each way.
    if (dims_[0] * kGhost > x_.cells() || dims_[1] * kGhost > y_.cells())
        throw std::invalid_argument("parallel.ranks: " + std::to_string(dims_[0]) + " x " + std::to_string(dims_[1]) +
                                    " patches leave fewer than " + std::to_string(kGhost) + " cells per patch in a " +
                                    "direction of the " + std::to_string(x_.cells()) + " x " +
                                    std::to_string(y_.cells()) + " grid: use fewer ranks or more cells");
    int periods[2] = {x_.periodic() ? 1 : 0, y_.periodic() ? 1 : 0};
    MPI_Cart_create(comm, 2, dims_, periods, 0, &cart_);
    MPI_Comm_rank(cart_, &rank_);
    MPI_Comm_size(cart_, &size_);
    MPI_Cart_coords(cart_, rank_, 2, coords_);
    MPI_Cart_shift(cart_, 0, 1, &neighbour_[0], &neighbour_[1]);
    MPI_Cart_shift(cart_, 1, 1, &neighbour_[2], &neighbour_[3]);
    touches_[0] = coords_[0] == 0;
    touches_[1] = coords_[0] == dims_[0] - 1;
    touches_[2] = coords_[1] == 0;
    touches_[3] = coords_[1] == dims_[1] - 1;
    update_geometry();
}

Grid::~Grid() {
    if (cart_ != MPI_COMM_NULL) MPI_Comm_free(&cart_);
}

void Grid::update_geometry() {
    int first = 0, count = 0;
    block_range(x_.cells(), dims_[0], coords_[0], first, count);
    lx_.build(x_, first, count);
    block_range(y_.cells(), dims_[1], coords_[1], first, count);
    ly_.build(y_, first, count);
}

void Grid::set_lines(std::vector<double> x_lines, std::vector<double> y_lines) {
    if (static_cast<int>(x_lines.size()) != x_.cells() + 1 || static_cast<int>(y_lines.size()) != y_.cells() + 1)
        throw std::invalid_argument("Grid::set_lines: the number of lines must not change");
    x_.set_lines(std::move(x_lines));
    y_.set_lines(std::move(y_lines));
    update_geometry();
    ++lines_version_;
}

}  // namespace chute
