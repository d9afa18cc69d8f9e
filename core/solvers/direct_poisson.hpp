#pragma once
// The projection's Poisson problem (poisson_solver.hpp's finite-volume operator, the same boundaries) solved
// directly where one axis is uniform: a real Fourier, cosine or sine transform along it diagonalises the
// operator in that direction (Schumann & Sweet 1988, J. Comput. Phys. 75:123; CaNS, Costa 2018, Comput. Math.
// Appl. 76:1853), which leaves one tridiagonal system per mode along the other axis, stretched or not. Cost:
// O(N log N), no iterations, exact to round-off.
//
// Along the uniform axis (cells of width h, cell-centred unknowns) the 3-point Laplacian's eigenvectors are, by
// its two ends (Neumann: mirrored ghost p; Dirichlet p = 0 on the face: ghost -p):
//   Neumann-Neumann   DCT-II  (FFTW REDFT10, inverse REDFT01)  theta_m = pi m / N
//   Dirichlet-both    DST-II  (RODFT10 / RODFT01)               theta_m = pi (m + 1) / N
//   Neumann-Dirichlet DCT-IV  (REDFT11, its own inverse)        theta_m = pi (m + 1/2) / N
//   Dirichlet-Neumann DST-IV  (RODFT11)                         theta_m = pi (m + 1/2) / N
//   periodic          real DFT (R2HC / HC2R)                    theta_m = 2 pi k / N (k = m or N - m)
// with eigenvalue -4 sin^2(theta_m / 2) / h^2. The data move between the ranks' patches and whole lines of one
// direction with pencil transposes (pencil_transpose.hpp): patches -> lines along the transform (transform) ->
// lines along the other axis (tridiagonal solves, cyclic if periodic) -> back.
#include <array>
#include <memory>
#include <vector>

#include "field.hpp"
#include "pencil_transpose.hpp"

struct fftw_plan_s;

namespace chute {

class DirectPoissonSolver {
public:
    // The axis (0: x, 1: y) the transform would run along on this grid, or -1 if none: neither axis uniform.
    // Prefers a periodic uniform axis (the other's systems are then not cyclic), else x.
    static int transform_axis(const Grid& grid);

    DirectPoissonSolver(const Grid& grid, std::array<bool, 4> dirichlet_sides);
    ~DirectPoissonSolver();
    DirectPoissonSolver(const DirectPoissonSolver&) = delete;
    DirectPoissonSolver& operator=(const DirectPoissonSolver&) = delete;

    int axis() const { return t_; }
    // The lines of the other axis moved (the transform axis must still be uniform: transform_axis()).
    void update_lines();
    // laplacian(p) = source on the owned cells. With no Dirichlet side the source's mean (the component the
    // Neumann problem cannot take) is removed first and p has zero mean, as PoissonSolver does.
    void solve(const Field2D& source, Field2D& p);

private:
    void solve_lines();  // the tridiagonal systems of this rank's modes (d_)

    const Grid& grid_;
    std::array<bool, 4> dirichlet_;
    int t_ = 0;             // transform axis (0: x, 1: y); the other, d = 1 - t_, carries the tridiagonal systems
    int nt_ = 0, nd_ = 0;   // global cells along each
    bool singular_ = false; // no Dirichlet side: mode 0 is the Neumann (or periodic) problem's null space
    bool cyclic_ = false;   // the tridiagonal axis is periodic
    double h_ = 0.0;        // cell width along the transform axis
    double normalisation_ = 1.0;  // the forward and inverse transforms multiply by this
    std::vector<double> eigenvalue_;  // per mode (global index along the transform axis)
    // Tridiagonal coefficients per cell along the other axis (global index): lower, upper, diagonal without the
    // mode's term, and the cell width that multiplies the mode's eigenvalue.
    std::vector<double> lower_, upper_, diagonal_, width_;
    std::vector<double> scratch_, cyclic_z_;

    BoxStorage patch_, lines_t_, lines_d_;  // this rank's patch, transform-axis lines, other-axis lines
    std::unique_ptr<PencilTranspose> to_t_, t_to_d_, d_to_t_, from_t_;
    std::vector<double> t_data_, d_data_;
    fftw_plan_s *forward_ = nullptr, *inverse_ = nullptr;
};

}  // namespace chute
