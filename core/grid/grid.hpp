#pragma once
// The staggered (MAC) rectilinear grid and its decomposition into rectangular MPI patches.
//
// Storage convention (local indices, ghost width kGhost on every side):
//   cell (i, j)         centre (xc[i], yc[j]), size dx[i] x dy[j]; pressure lives here
//   u(i, j)             on the LEFT face of cell (i, j): x = xf[i], y = yc[j]
//   v(i, j)             on the BOTTOM face of cell (i, j): x = xc[i], y = yf[j]
// so u, v and p arrays all have the shape of the cell array. A rank owns cells [0, nx) x [0, ny) and the
// faces with the same indices; the face at local index nx is its right neighbour's (or the domain
// boundary's). Geometry arrays are indexed the same way, ghosts included, so loops never special-case.
#include <mpi.h>

#include <array>
#include <vector>

#include "axis.hpp"

namespace chute {

inline constexpr int kGhost = 2;

enum class Side { left = 0, right = 1, bottom = 2, top = 3 };
inline constexpr std::array<Side, 4> kSides = {Side::left, Side::right, Side::bottom, Side::top};

// Local geometry of one direction of a patch: arrays indexed from -kGhost to n + kGhost - 1.
class LocalAxis {
public:
    void build(const Axis& axis, int first_cell, int cells);

    int n = 0;       // owned cells
    int offset = 0;  // global index of local cell 0
    // f: line at the low face of cell k; c: centre of cell k; w: width of cell k;
    // dc: distance between centres k-1 and k (across face k).
    double f(int k) const { return f_[k + kGhost]; }
    double c(int k) const { return c_[k + kGhost]; }
    double w(int k) const { return w_[k + kGhost]; }
    double dc(int k) const { return dc_[k + kGhost]; }
    const double* f_ptr() const { return f_.data() + kGhost; }
    const double* c_ptr() const { return c_.data() + kGhost; }
    const double* w_ptr() const { return w_.data() + kGhost; }
    const double* dc_ptr() const { return dc_.data() + kGhost; }

private:
    std::vector<double> f_, c_, w_, dc_;
};

// Block distribution of n cells over p ranks: rank r gets [first, first + count); the first n % p ranks get one more.
void block_range(int n, int p, int r, int& first, int& count);

class Grid {
public:
    // ranks_x, ranks_y <= 0: let MPI choose the decomposition.
    Grid(Axis x, Axis y, MPI_Comm comm, int ranks_x = 0, int ranks_y = 0);
    ~Grid();
    Grid(const Grid&) = delete;
    Grid& operator=(const Grid&) = delete;

    const Axis& x_axis() const { return x_; }
    const Axis& y_axis() const { return y_; }
    const LocalAxis& lx() const { return lx_; }
    const LocalAxis& ly() const { return ly_; }
    int nx() const { return lx_.n; }  // owned cells on this rank
    int ny() const { return ly_.n; }
    int global_nx() const { return x_.cells(); }
    int global_ny() const { return y_.cells(); }
    long long global_cells() const { return 1LL * x_.cells() * y_.cells(); }

    MPI_Comm comm() const { return cart_; }
    int rank() const { return rank_; }
    int size() const { return size_; }
    std::array<int, 2> ranks() const { return {dims_[0], dims_[1]}; }
    // Neighbour rank across a side (MPI_PROC_NULL at a non-periodic domain boundary).
    int neighbour(Side s) const { return neighbour_[static_cast<int>(s)]; }
    // True if this patch touches the given side of the domain.
    bool touches(Side s) const { return touches_[static_cast<int>(s)]; }

    // Move or replace grid lines; recomputes every local geometry array. Cell counts must not change
    // (inserting lines needs fields to be remapped, which is the ALE band's job).
    void set_lines(std::vector<double> x_lines, std::vector<double> y_lines);
    // Counts the calls of set_lines(): what is placed once on the lines (a static immersed surface's faces, markers
    // and wall cells) is placed again when it changes (a grid that follows a body moves under a fixed plane).
    long long lines_version() const { return lines_version_; }

private:
    void update_geometry();

    Axis x_, y_;
    LocalAxis lx_, ly_;
    MPI_Comm cart_ = MPI_COMM_NULL;
    int rank_ = 0, size_ = 1;
    int dims_[2] = {1, 1};
    int coords_[2] = {0, 0};
    std::array<int, 4> neighbour_{};
    std::array<bool, 4> touches_{};
    long long lines_version_ = 0;
};

}  // namespace chute
