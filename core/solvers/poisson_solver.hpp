#pragma once
// The pressure Poisson problem of the projection: solved directly (direct_poisson.hpp: a transform along a
// uniform axis, tridiagonal systems along the other) where the grid allows it, else with hypre's structured
// interface, as follows.
//
// Finite-volume form on cell (i, j) of volume V = w_x(i) w_y(j):
//   sum over the four faces  A_f (p_nb - p_ij) / d_f  =  V * s_ij
// with A_f the face length and d_f the distance between the two cell centres (mirrored ghost at a boundary).
// Multiplied by -1 the matrix is symmetric positive (semi-)definite and solved with PCG preconditioned by
// one PFMG V-cycle. Boundaries: Neumann (no flux) everywhere, except p = 0 on zero-stress outflows
// (ghost p = -p_ij, d_f = w). With Neumann on all sides the matrix is singular: the right-hand side is
// made zero-mean, the preconditioner's output is projected onto zero-mean vectors (without this PCG
// breaks down on stretched grids: PFMG does not keep the null space out), and the solution's mean is
// removed. The matrix is kept as it is (STACK.md: pinning a cell slows PFMG five-fold).
// Solid cells (core/grid/solid_cells.hpp, a body-fitted hole) are left out: their rows are the identity (scaled
// like a Laplacian row there) with a zero right-hand side, and no flux crosses their sides (Neumann); the null
// space and the means are the fluid cells'. With solid cells on a grid with no periodic direction the
// preconditioner is SMG instead of PFMG (update_matrix() says why).
// Cut along sharp surfaces (face apertures) on a grid with a uniform axis, the preconditioner is instead the whole
// grid's direct solve with an exact solve in a window around the cut cells (cut_poisson_preconditioner.hpp).
#include <HYPRE_struct_ls.h>

#include <array>
#include <memory>
#include <vector>

#include "cut_poisson_preconditioner.hpp"
#include "direct_poisson.hpp"
#include "field.hpp"
#include "poisson_method.hpp"

namespace chute {

struct PoissonStats {
    int iterations = 0;              // 0: a direct solve
    double relative_residual = 0.0;  // 0 for a direct solve (exact to round-off: ~1e-13, test_poisson_solver.cpp)
};

class PoissonSolver {
public:
    PoissonSolver(const Grid& grid, std::array<bool, 4> dirichlet_sides, double tolerance, int max_iterations,
                  PoissonMethod method = PoissonMethod::automatic);
    ~PoissonSolver();
    PoissonSolver(const PoissonSolver&) = delete;
    PoissonSolver& operator=(const PoissonSolver&) = delete;

    // Rebuild the matrix and the multigrid hierarchy (after grid lines moved).
    void update_matrix();
    // Only the matrix's coefficients (after lines moved a little: a modifier layer stretching): PCG solves the new
    // matrix, preconditioned by the multigrid cycle of the last update_matrix()'s (a fixed preconditioner of a
    // nearby matrix), which saves the hierarchy's setup.
    void update_coefficients();
    // Leave the cells where `fluid` is 0 out of the problem (null: none); `fluid_cells` counts the others over
    // all ranks. Rebuilds the matrix; the field must outlive the solver or the next call.
    void set_fluid_cells(const Field2D* fluid, long long fluid_cells);
    // Scale each face's coefficient A / d by its open fraction (cut faces, FlowSolver::PressureBoundary; null: none).
    // Takes effect at the next update_matrix() or update_coefficients(); the fields must outlive the solver.
    void set_face_apertures(const Field2D* aperture_u, const Field2D* aperture_v) {
        aperture_u_ = aperture_u;
        aperture_v_ = aperture_v;
    }
    // Solve laplacian(p) = source; p holds the initial guess on entry (warm start) and the solution on exit.
    // absolute_tolerance bounds the residual norm from below (for source ~ 0); relative_tolerance > 0 replaces the
    // solver's own (numerics.poisson.tolerance) for this solve.
    PoissonStats solve(const Field2D& source, Field2D& p, double absolute_tolerance = 0.0,
                       double relative_tolerance = 0.0);
    bool singular() const { return singular_; }
    bool direct() const { return direct_ != nullptr; }
    // Cut along surfaces, PCG preconditioned by the direct solve and a window's (cut_poisson_preconditioner.hpp).
    bool cut_direct() const { return cut_direct_used_; }

private:
    void destroy_solver();
    std::vector<double> matrix_values(bool with_cut = true) const;
    HYPRE_StructMatrix new_matrix() const;
    void set_values(HYPRE_StructMatrix m) const;

    bool direct_applies() const;
    bool cut_direct_applies() const;
    // Cells around the cut ones in the window of cut_direct_. The study's free fall on ghost faces (1 rank, t = 0-0.3):
    // margin 4 / 8 / 16 / 24 took 6.0 / 5.0 / 3.9 / 3.1 PCG iterations per step, 16 the shortest step (a window of
    // about 2900 cells around the block 20 cells across; docs/performance.md).
    static constexpr int kCutWindowMargin = 16;

    const Grid& grid_;
    std::array<bool, 4> dirichlet_;
    PoissonMethod method_;
    std::unique_ptr<DirectPoissonSolver> direct_;  // null: hypre solves
    bool singular_;
    double tolerance_;
    int max_iterations_;
    HYPRE_StructGrid hgrid_ = nullptr;
    HYPRE_StructStencil stencil_ = nullptr;
    HYPRE_StructMatrix matrix_ = nullptr;
    HYPRE_StructVector b_ = nullptr, x_ = nullptr;
    HYPRE_StructSolver pcg_ = nullptr, pfmg_ = nullptr;
    HYPRE_StructVector ones_ = nullptr;  // the null space of the all-Neumann matrix
    std::vector<double> buffer_;
    const Field2D* fluid_ = nullptr;       // 1 in fluid cells, 0 in solid ones (null: all fluid)
    const Field2D* aperture_u_ = nullptr;  // open fractions of the faces (null: all open)
    const Field2D* aperture_v_ = nullptr;
    double fluid_cells_ = 0.0;  // global count of fluid cells
    double solid_cells_ = 0.0;  // and of solid ones
    bool smg_ = false;          // the preconditioner (pfmg_) is SMG: there are solid cells
    // With face apertures on a grid with a uniform axis: the direct solve with a window's exact solve around the
    // surfaces preconditions PCG (pfmg_ is then this object's handle).
    std::unique_ptr<CutPoissonPreconditioner> cut_direct_;
    bool cut_direct_used_ = false;
    std::vector<double> whole_values_;    // the whole grid's coefficients (matrix_values(false)), for cut_direct_
    mutable std::vector<double> values_;  // the coefficients set_values() gave the matrix last
    std::array<int, 2> lower_{}, upper_{};
};

}  // namespace chute
