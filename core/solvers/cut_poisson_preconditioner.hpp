#pragma once
// A preconditioner for the pressure problem cut along sharp immersed surfaces (PoissonSolver with face apertures,
// ibm/cut_faces.hpp) that keeps the direct solve (direct_poisson.hpp) on a grid with a uniform axis.
//
// The cut matrix A differs from the whole grid's L only in the rows of the cells a surface crosses or covers. Near
// them an exact sparse factorisation of A restricted to a window W (those cells and `margin` cells around them,
// zero outside) is cheap (a few thousand unknowns for a block); away from them L is A, and the direct solve
// inverts L. Symmetric multiplicative Schwarz (Smith, Bjorstad & Gropp 1996, Domain Decomposition, ch. 1; the
// window solve, the whole-grid solve, the window solve again):
//   z  = R^T A_WW^-1 R r
//   z += L^-1 (r - A z)
//   z += R^T A_WW^-1 R (r - A z)
// is symmetric positive definite, so PCG runs on it (hypre's Struct PCG, the matrix products hypre's). One direct
// solve per iteration. Measured on a model of the study's free fall (docs/performance.md): 6-8 iterations to a
// relative residual of 1e-8 from a zero start at margin 6-16, against 164 with the direct solve alone.
// Covered cells away from the surfaces have rows of their diagonal alone (no flux through a shut face), so A is
// block diagonal: fluid and those cells. They stay out of the window and out of the whole-grid step (its residual
// and correction zero there) and are solved by their diagonal, which keeps the preconditioner symmetric positive
// definite; the window then covers the surfaces only, not the half of the grid below a plane.
#include <HYPRE_struct_ls.h>

#include <Eigen/SparseCholesky>
#include <array>
#include <memory>
#include <vector>

#include "direct_poisson.hpp"
#include "field.hpp"

namespace chute {

class CutPoissonPreconditioner {
public:
    CutPoissonPreconditioner(const Grid& grid, std::array<bool, 4> dirichlet_sides, int margin);
    CutPoissonPreconditioner(const CutPoissonPreconditioner&) = delete;
    CutPoissonPreconditioner& operator=(const CutPoissonPreconditioner&) = delete;

    // cut, whole: this rank's coefficients of -V laplacian (5 per cell: diagonal, west, east, south, north, as
    // PoissonSolver stores them) with and without the surfaces. Finds the window and factorises its matrix. False when
    // the window would not pay (more than a quarter of the grid) or its matrix is singular (a region of fluid closed
    // inside it): the caller then uses multigrid. Collective.
    bool set_up(const std::vector<double>& cut, const std::vector<double>& whole);
    // The lines moved (the transform axis still uniform): the direct solve's coefficients follow.
    void update_lines() { direct_.update_lines(); }
    // x = P b (hypre vectors on this rank's box). Collective.
    void apply(HYPRE_StructVector b, HYPRE_StructVector x);
    std::size_t window_cells() const { return window_.size(); }

private:
    const std::vector<double>& window_values(const std::vector<double>& owned);  // gathered over the ranks
    const Eigen::VectorXd& window_solve(const Eigen::VectorXd& window_residual);
    // z += the window's solve of its residual window_rhs_ - A z (the window's rows only: no product over the grid).
    void add_window_correction(std::vector<double>& z);

    const Grid& grid_;
    int margin_;
    DirectPoissonSolver direct_;
    std::array<int, 2> lower_{}, upper_{};
    std::vector<long long> window_;      // global cell indices (j * global_nx + i), ascending, the same on every rank
    std::vector<int> local_;             // per window cell: its index in this rank's box, or -1
    Eigen::SparseMatrix<double> block_;  // the window's rows of the cut matrix, its own columns
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
    Eigen::VectorXd window_rhs_, window_residual_, window_solution_;
    // The couplings from the window's cells to this rank's cells just outside it: what a solution in the window
    // leaves in their residual (apply()'s first residual without a matrix product).
    struct RingCoupling {
        int window_cell;
        int cell;  // in this rank's box
        double coefficient;
    };
    std::vector<RingCoupling> ring_;
    // The covered cells outside the window (a row of the diagonal alone): this rank's, with their diagonal.
    struct Covered {
        int cell;  // in this rank's box
        double diagonal;
    };
    std::vector<Covered> covered_;
    std::vector<double> covered_rhs_;
    Field2D source_, correction_;
    std::vector<double> volume_;         // of each owned cell
    std::vector<double> rhs_, z_, r_;    // apply()'s work, per owned cell
    std::vector<double> window_buffer_;  // window_values()'s, add_window_correction()'s
};

}  // namespace chute
