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
// with eigenvalue -4 sin^2(theta_m / 2) / h^2. Where the data lie while they are transformed and solved:
//   one rank: in p itself (transform out of place from the source, sweeps, inverse in place), no copy;
//   patches holding whole transform lines, splitting the other axis (what an automatic decomposition makes): the
//     transform in p, the tridiagonal systems partitioned over the ranks where they lie (solve_partitioned);
//   any other decomposition: pencil transposes (pencil_transpose.hpp) to whole lines along the transform, then
//     along the other axis, and back.
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
    // Of two uniform axes: the one the decomposition does not split, else a periodic one, else x.
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
    // Where the data sit while they are transformed (whole lines along the transform axis) and while the
    // tridiagonal systems are solved (whole lines along the other): in p itself when the rank's patch already
    // holds such lines (one rank: both, no copy at all), else in a buffer the pencil transposes fill.
    struct Layout {
        BoxStorage storage;
        bool in_patch = false;
    };
    void plan_transforms();
    void prepare_cyclic();  // the Sherman-Morrison vectors of the periodic systems
    // The tridiagonal systems of the modes in `layout`, right-hand sides in, solutions out.
    void solve_modes(double* data, const BoxStorage& layout);
    void sweep_modes(double* data, std::ptrdiff_t sm, std::ptrdiff_t sk, int first_mode, int l_begin, int modes, int k0,
                     int n, bool cyclic);
    // The systems split over the ranks along their axis, solved where they lie (no transpose).
    void partition_prepare();
    void solve_partitioned(double* data, std::ptrdiff_t sm, std::ptrdiff_t sk);
    void solve_null_mode(double* x, std::ptrdiff_t stride);  // mode 0 of the singular problem

    const Grid& grid_;
    std::array<bool, 4> dirichlet_;
    int t_ = 0;                   // transform axis (0: x, 1: y); the other, d = 1 - t_, carries the tridiagonal systems
    int nt_ = 0, nd_ = 0;         // global cells along each
    bool singular_ = false;       // no Dirichlet side: mode 0 is the Neumann (or periodic) problem's null space
    bool cyclic_ = false;         // the tridiagonal axis is periodic
    double h_ = 0.0;              // cell width along the transform axis
    double normalisation_ = 1.0;  // the forward and inverse transforms multiply by this
    std::vector<double> eigenvalue_;  // per mode (global index along the transform axis)
    // Tridiagonal coefficients per cell along the other axis (global index): lower, upper, diagonal without the
    // mode's term, the cell width that multiplies the mode's eigenvalue, and the right-hand side's factor.
    std::vector<double> lower_, upper_, diagonal_, width_, rhs_scale_;
    std::vector<double> scratch_;
    // Periodic systems, per mode of this rank: gamma, 1 / (1 + z_0 + beta z_{n-1} / gamma), and z (nd_ each).
    std::vector<double> cyclic_gamma_, cyclic_inverse_, cyclic_z_;

    // The partitioned solve: this rank's rows [row0_, row0_ + rows_) of the systems' axis, every rank's (for the
    // gathers), g and h per mode and row (stored like the patch: element (m, k) at m partition_sm_ + k partition_sk_),
    // and every rank's first and last values of g and h per mode.
    bool partitioned_ = false;
    int row0_ = 0, rows_ = 0;
    std::vector<int> row_starts_, row_counts_;
    std::vector<double> partition_g_, partition_h_, partition_edges_;
    std::ptrdiff_t partition_sm_ = 1, partition_sk_ = 1;

    BoxStorage patch_;
    Layout transform_, systems_;
    std::unique_ptr<PencilTranspose> patch_to_transform_, transform_to_systems_, systems_to_transform_,
        transform_to_patch_;
    std::vector<double> transform_data_, systems_data_;
    fftw_plan_s *forward_ = nullptr, *inverse_ = nullptr;
};

}  // namespace chute
