#pragma once
// A scalar array on a patch, with kGhost ghost layers on every side; x varies fastest.
// Used for cell-centred quantities and, with the face convention of grid.hpp, for u and v.
#include <algorithm>
#include <cassert>
#include <vector>

#include "grid.hpp"

namespace chute {

class Field2D {
public:
    Field2D() = default;
    Field2D(int nx, int ny, double value = 0.0)
        : nx_(nx),
          ny_(ny),
          stride_(nx + 2 * kGhost),
          data_(static_cast<std::size_t>(stride_) * (ny + 2 * kGhost), value) {}
    explicit Field2D(const Grid& g, double value = 0.0) : Field2D(g.nx(), g.ny(), value) {}

    double& operator()(int i, int j) { return data_[index(i, j)]; }
    double operator()(int i, int j) const { return data_[index(i, j)]; }

    int nx() const { return nx_; }
    int ny() const { return ny_; }
    int stride() const { return stride_; }
    // Pointer to element (0, 0); element (i, j) is at [i + j * stride()].
    double* origin() { return data_.data() + index(0, 0); }
    const double* origin() const { return data_.data() + index(0, 0); }
    std::vector<double>& raw() { return data_; }
    const std::vector<double>& raw() const { return data_; }
    void fill(double value) { std::fill(data_.begin(), data_.end(), value); }

private:
    // Debug builds check the bounds (ghosts included); with NDEBUG (Release) the check compiles away.
    std::size_t index(int i, int j) const {
        assert(i >= -kGhost && i < nx_ + kGhost && "Field2D: i out of bounds");
        assert(j >= -kGhost && j < ny_ + kGhost && "Field2D: j out of bounds");
        return static_cast<std::size_t>(j + kGhost) * stride_ + (i + kGhost);
    }
    int nx_ = 0, ny_ = 0, stride_ = 0;
    std::vector<double> data_;
};

// The velocity on the staggered grid.
struct Velocity {
    Field2D u, v;
    explicit Velocity(const Grid& g) : u(g), v(g) {}
    Velocity() = default;
};

}  // namespace chute
