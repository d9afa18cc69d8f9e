#include "poisson_solver.hpp"

#include <_hypre_struct_mv.h>
#include <mpi.h>

#include <cmath>
#include <map>
#include <stdexcept>

namespace chute {

namespace {
// hypre calls the preconditioner with its own fixed signature; the null-space vector and the number of
// cells of each singular solver are found through the PFMG handle.
struct NullSpace {
    HYPRE_StructVector ones;  // null: a non-singular matrix (the wrapper only runs the cycle)
    double cells;
    // The matrix the multigrid hierarchy was set up on, when PCG's own has moved on since (update_coefficients):
    // the cycle runs on it, a fixed preconditioner of the nearby matrix PCG solves. Null: PCG's matrix.
    HYPRE_StructMatrix hierarchy_matrix = nullptr;
};
std::map<HYPRE_StructSolver, NullSpace>& null_spaces() {
    static std::map<HYPRE_StructSolver, NullSpace> registry;
    return registry;
}

// x -= mean(x) over the fluid cells, when the matrix is singular.
void remove_null_space(HYPRE_StructSolver preconditioner, HYPRE_StructVector x) {
    const NullSpace& ns = null_spaces().at(preconditioner);
    if (!ns.ones) return;
    auto* xv = reinterpret_cast<hypre_StructVector*>(x);
    auto* ov = reinterpret_cast<hypre_StructVector*>(ns.ones);
    hypre_StructAxpy(-hypre_StructInnerProd(xv, ov) / ns.cells, ov, xv);
}

HYPRE_StructMatrix cycle_matrix(HYPRE_StructSolver preconditioner, HYPRE_StructMatrix A) {
    const NullSpace& ns = null_spaces().at(preconditioner);
    return ns.hierarchy_matrix ? ns.hierarchy_matrix : A;
}

// One PFMG V-cycle, then x -= mean(x): the preconditioner of PCG restricted to zero-mean vectors.
HYPRE_Int pfmg_zero_mean(HYPRE_StructSolver pfmg, HYPRE_StructMatrix A, HYPRE_StructVector b, HYPRE_StructVector x) {
    HYPRE_StructPFMGSolve(pfmg, cycle_matrix(pfmg, A), b, x);
    remove_null_space(pfmg, x);
    return 0;
}

// The same with one SMG cycle (solid cells: see update_matrix()).
HYPRE_Int smg_zero_mean(HYPRE_StructSolver smg, HYPRE_StructMatrix A, HYPRE_StructVector b, HYPRE_StructVector x) {
    HYPRE_StructSMGSolve(smg, cycle_matrix(smg, A), b, x);
    remove_null_space(smg, x);
    return 0;
}

// The cut problem's direct solve with its window (cut_poisson_preconditioner.hpp), then x -= mean(x).
HYPRE_Int cut_direct_zero_mean(HYPRE_StructSolver handle, HYPRE_StructMatrix, HYPRE_StructVector b,
                               HYPRE_StructVector x) {
    reinterpret_cast<CutPoissonPreconditioner*>(handle)->apply(b, x);
    remove_null_space(handle, x);
    return 0;
}

// The preconditioner's setup when its hierarchy is kept (update_coefficients): nothing to do.
HYPRE_Int keep_hierarchy(HYPRE_StructSolver, HYPRE_StructMatrix, HYPRE_StructVector, HYPRE_StructVector) { return 0; }

}  // namespace

PoissonSolver::PoissonSolver(const Grid& grid, std::array<bool, 4> dirichlet_sides, double tolerance,
                             int max_iterations, PoissonMethod method)
    : grid_(grid),
      dirichlet_(dirichlet_sides),
      method_(method),
      tolerance_(tolerance),
      max_iterations_(max_iterations) {
    singular_ = !(dirichlet_[0] || dirichlet_[1] || dirichlet_[2] || dirichlet_[3]);
    MPI_Comm comm = grid_.comm();
    lower_ = {grid_.lx().offset, grid_.ly().offset};
    upper_ = {grid_.lx().offset + grid_.nx() - 1, grid_.ly().offset + grid_.ny() - 1};
    HYPRE_StructGridCreate(comm, 2, &hgrid_);
    HYPRE_StructGridSetExtents(hgrid_, lower_.data(), upper_.data());
    int periodic[2] = {grid_.x_axis().periodic() ? grid_.global_nx() : 0,
                       grid_.y_axis().periodic() ? grid_.global_ny() : 0};
    HYPRE_StructGridSetPeriodic(hgrid_, periodic);
    HYPRE_StructGridAssemble(hgrid_);

    // 5-point stencil: centre, west, east, south, north.
    int offsets[5][2] = {{0, 0}, {-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    HYPRE_StructStencilCreate(2, 5, &stencil_);
    for (int e = 0; e < 5; ++e) HYPRE_StructStencilSetElement(stencil_, e, offsets[e]);

    HYPRE_StructVectorCreate(comm, hgrid_, &b_);
    HYPRE_StructVectorCreate(comm, hgrid_, &x_);
    HYPRE_StructVectorInitialize(b_);
    HYPRE_StructVectorInitialize(x_);
    if (singular_) {
        HYPRE_StructVectorCreate(comm, hgrid_, &ones_);
        HYPRE_StructVectorInitialize(ones_);
        HYPRE_StructVectorSetConstantValues(ones_, 1.0);
        HYPRE_StructVectorAssemble(ones_);
    }
    buffer_.resize(static_cast<std::size_t>(grid_.nx()) * grid_.ny());
    fluid_cells_ = static_cast<double>(grid_.global_cells());
    update_matrix();
}

void PoissonSolver::set_fluid_cells(const Field2D* fluid, long long fluid_cells) {
    fluid_ = fluid;
    fluid_cells_ = static_cast<double>(fluid ? fluid_cells : grid_.global_cells());
    solid_cells_ = static_cast<double>(grid_.global_cells()) - fluid_cells_;
    if (singular_) {  // the null vector: the constant on the fluid cells
        const int nx = grid_.nx(), ny = grid_.ny();
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) buffer_[static_cast<std::size_t>(j) * nx + i] = fluid_ ? (*fluid_)(i, j) : 1.0;
        HYPRE_StructVectorSetBoxValues(ones_, lower_.data(), upper_.data(), buffer_.data());
        HYPRE_StructVectorAssemble(ones_);
    }
    update_matrix();
}

PoissonSolver::~PoissonSolver() {
    destroy_solver();
    if (matrix_) HYPRE_StructMatrixDestroy(matrix_);
    HYPRE_StructVectorDestroy(b_);
    HYPRE_StructVectorDestroy(x_);
    if (ones_) HYPRE_StructVectorDestroy(ones_);
    HYPRE_StructStencilDestroy(stencil_);
    HYPRE_StructGridDestroy(hgrid_);
}

void PoissonSolver::destroy_solver() {
    if (pfmg_) {
        // The matrix the hierarchy was set up on, when PCG's had moved on (update_coefficients).
        if (HYPRE_StructMatrix kept = null_spaces().at(pfmg_).hierarchy_matrix) HYPRE_StructMatrixDestroy(kept);
        null_spaces().erase(pfmg_);
    }
    if (pcg_) HYPRE_StructPCGDestroy(pcg_);
    // The window's preconditioner (cut_direct_) is not hypre's: it stays, its direct solve planned once.
    if (pfmg_ && !cut_direct_used_) {
        if (smg_)
            HYPRE_StructSMGDestroy(pfmg_);
        else
            HYPRE_StructPFMGDestroy(pfmg_);
    }
    pcg_ = pfmg_ = nullptr;
    cut_direct_used_ = false;
}

// The coefficients of -V laplacian on this rank's cells (5 per cell: diagonal, west, east, south, north); with_cut
// false: those of the whole grid, as if no cell were solid and every face open.
std::vector<double> PoissonSolver::matrix_values(bool with_cut) const {
    const Field2D* fluid_ = with_cut ? this->fluid_ : nullptr;
    const Field2D* aperture_u_ = with_cut ? this->aperture_u_ : nullptr;
    const Field2D* aperture_v_ = with_cut ? this->aperture_v_ : nullptr;
    const auto& X = grid_.lx();
    const auto& Y = grid_.ly();
    const int nx = grid_.nx(), ny = grid_.ny();
    const bool px = grid_.x_axis().periodic(), py = grid_.y_axis().periodic();
    std::vector<double> values(static_cast<std::size_t>(nx) * ny * 5);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            // Coefficients of -V * laplacian: a_nb = A_f / d_f, diagonal = sum.
            double w = Y.w(j) / X.dc(i), e = Y.w(j) / X.dc(i + 1);
            double s = X.w(i) / Y.dc(j), n = X.w(i) / Y.dc(j + 1);
            double diag = 0.0;
            auto boundary = [&](double& a, Side side, bool at_side, bool periodic) {
                if (!at_side || periodic) return;
                if (dirichlet_[static_cast<int>(side)]) diag += 2.0 * a;  // p = 0 on the face: ghost -p
                a = 0.0;
            };
            boundary(w, Side::left, grid_.touches(Side::left) && i == 0, px);
            boundary(e, Side::right, grid_.touches(Side::right) && i == nx - 1, px);
            boundary(s, Side::bottom, grid_.touches(Side::bottom) && j == 0, py);
            boundary(n, Side::top, grid_.touches(Side::top) && j == ny - 1, py);
            double* v = &values[5 * (static_cast<std::size_t>(j) * nx + i)];
            if (fluid_) {
                const Field2D& f = *fluid_;
                if (f(i, j) == 0.0) {  // a solid cell: phi = 0, an identity row (scaled like its neighbours')
                    v[0] = w + e + s + n;
                    v[1] = v[2] = v[3] = v[4] = 0.0;
                    continue;
                }
                // No flux across a hole's side.
                w *= f(i - 1, j);
                e *= f(i + 1, j);
                s *= f(i, j - 1);
                n *= f(i, j + 1);
            }
            if (aperture_u_) {  // a cut face passes flux through its open part only
                w *= (*aperture_u_)(i, j);
                e *= (*aperture_u_)(i + 1, j);
                s *= (*aperture_v_)(i, j);
                n *= (*aperture_v_)(i, j + 1);
            }
            diag += w + e + s + n;
            v[0] = diag;
            v[1] = -w;
            v[2] = -e;
            v[3] = -s;
            v[4] = -n;
        }
    return values;
}

HYPRE_StructMatrix PoissonSolver::new_matrix() const {
    HYPRE_StructMatrix m = nullptr;
    HYPRE_StructMatrixCreate(grid_.comm(), hgrid_, stencil_, &m);
    HYPRE_StructMatrixSetSymmetric(m, 1);  // stores 3 of the 5 coefficients: less to read per iteration
    HYPRE_StructMatrixInitialize(m);
    set_values(m);
    return m;
}

// This rank's coefficients (matrix_values) into `m`, assembled.
void PoissonSolver::set_values(HYPRE_StructMatrix m) const {
    values_ = matrix_values();
    std::vector<double>& values = values_;
    int entries[5] = {0, 1, 2, 3, 4};
    std::array<int, 2> lower = lower_, upper = upper_;  // hypre takes them non-const
    HYPRE_StructMatrixSetBoxValues(m, lower.data(), upper.data(), 5, entries, values.data());
    HYPRE_StructMatrixAssemble(m);
}

// PCG solves with the new matrix; the multigrid cycle stays the one set up on the matrix of the last
// update_matrix(), now a fixed preconditioner of a nearby matrix. (Changing the coefficients under hypre's SMG
// hierarchy instead, measured 2026-11-24, took 90 PCG iterations per step on the body-fitted free fall: its setup
// keeps data derived from the fine matrix.)
void PoissonSolver::update_coefficients() {
    if (direct_ && DirectPoissonSolver::transform_axis(grid_) == direct_->axis()) return direct_->update_lines();
    if (cut_direct_used_) {
        // The lines moved: the whole grid's direct solve and coefficients are made again (the solver first, so that
        // update_matrix() does not set the values in place on the old preconditioner).
        destroy_solver();
        cut_direct_.reset();
        return update_matrix();
    }
    if (!matrix_ || !pcg_ || direct_) return update_matrix();
    NullSpace& ns = null_spaces().at(pfmg_);
    if (ns.hierarchy_matrix) {
        // PCG's own matrix already: the same grid and stencil, new values in place (PCG's setup, its vectors and the
        // matrix-vector product's communication, stays valid).
        set_values(matrix_);
        return;
    }
    ns.hierarchy_matrix = matrix_;
    matrix_ = new_matrix();
    HYPRE_StructPCGSetPrecond(pcg_, smg_ ? smg_zero_mean : pfmg_zero_mean, keep_hierarchy, pfmg_);
    HYPRE_StructPCGSetup(pcg_, matrix_, b_, x_);
}

bool PoissonSolver::cut_direct_applies() const {
    return method_ == PoissonMethod::automatic && aperture_u_ && DirectPoissonSolver::transform_axis(grid_) >= 0;
}

bool PoissonSolver::direct_applies() const {
    return method_ == PoissonMethod::automatic && solid_cells_ == 0.0 &&
           DirectPoissonSolver::transform_axis(grid_) >= 0;
}

void PoissonSolver::update_matrix() {
    // Cut along a moving surface the matrix changes every step, its grid and stencil do not: the new values in place
    // and the window made again; PCG's vectors and its matrix product's communication stay valid (as in
    // update_coefficients()).
    if (cut_direct_used_ && matrix_ && pcg_ && cut_direct_applies()) {
        set_values(matrix_);
        null_spaces().at(pfmg_).cells = singular_ ? fluid_cells_ : 0.0;
        if (cut_direct_->set_up(values_, whole_values_)) return;
    }
    destroy_solver();
    if (matrix_) HYPRE_StructMatrixDestroy(matrix_);
    matrix_ = nullptr;
    direct_.reset();
    if (direct_applies()) {
        direct_ = std::make_unique<DirectPoissonSolver>(grid_, dirichlet_);
        return;
    }
    matrix_ = new_matrix();
    HYPRE_StructPCGCreate(grid_.comm(), &pcg_);
    HYPRE_StructPCGSetTol(pcg_, tolerance_);
    HYPRE_StructPCGSetMaxIter(pcg_, max_iterations_);
    HYPRE_StructPCGSetTwoNorm(pcg_, 1);  // stop on the true relative residual (STACK.md)
    HYPRE_StructPCGSetRelChange(pcg_, 0);
    smg_ = solid_cells_ > 0.0 && !grid_.x_axis().periodic() && !grid_.y_axis().periodic();
    if (cut_direct_applies()) {
        // A surface cuts the problem on a grid the direct solve fits: keep it, with the window's exact solve
        // (cut_poisson_preconditioner.hpp); multigrid only where the window would not pay.
        if (!cut_direct_) {
            cut_direct_ = std::make_unique<CutPoissonPreconditioner>(grid_, dirichlet_, kCutWindowMargin);
            whole_values_ = matrix_values(false);
        }
        if (cut_direct_->set_up(values_, whole_values_)) {
            cut_direct_used_ = true;
            pfmg_ = reinterpret_cast<HYPRE_StructSolver>(cut_direct_.get());
            null_spaces()[pfmg_] = NullSpace{singular_ ? ones_ : nullptr, singular_ ? fluid_cells_ : 0.0};
            HYPRE_StructPCGSetPrecond(pcg_, cut_direct_zero_mean, keep_hierarchy, pfmg_);
            HYPRE_StructVectorAssemble(b_);
            HYPRE_StructVectorAssemble(x_);
            HYPRE_StructPCGSetup(pcg_, matrix_, b_, x_);
            return;
        }
    }
    if (smg_) {
        // Measured (2026-11-24), not understood yet: with the solid cells' identity rows PFMG took 50 iterations
        // or broke down at the first (a square at the centre or a quarter above it in a 128 x 64 channel with
        // inflow and outflow), and with the solid cells as a Neumann block of their own its setup failed; SMG
        // (line relaxation, a higher cost per cycle) converges in 10 iterations in both. On a periodic grid the
        // opposite: SMG went wrong on a solid strip across the periodic width, where PFMG converges (and so it
        // does on the doubly periodic square of tests/unit/test_body_fitted.cpp). On the body-fitted free fall
        // (150 x 202, 2026-11-24) PFMG takes 15.6 iterations at 0.45 ms, SMG 4.9-6.1 at 1.2 ms: SMG is cheaper.
        HYPRE_StructSMGCreate(grid_.comm(), &pfmg_);
        HYPRE_StructSMGSetMaxIter(pfmg_, 1);
        HYPRE_StructSMGSetTol(pfmg_, 0.0);
        HYPRE_StructSMGSetZeroGuess(pfmg_);
        HYPRE_StructSMGSetNumPreRelax(pfmg_, 1);
        HYPRE_StructSMGSetNumPostRelax(pfmg_, 1);
        null_spaces()[pfmg_] = NullSpace{singular_ ? ones_ : nullptr, singular_ ? fluid_cells_ : 0.0};
        HYPRE_StructPCGSetPrecond(pcg_, smg_zero_mean, HYPRE_StructSMGSetup, pfmg_);
    } else {
        HYPRE_StructPFMGCreate(grid_.comm(), &pfmg_);
        HYPRE_StructPFMGSetMaxIter(pfmg_, 1);
        HYPRE_StructPFMGSetTol(pfmg_, 0.0);
        HYPRE_StructPFMGSetZeroGuess(pfmg_);
        // Red-black Gauss-Seidel on every level: fewer PCG iterations than the default weighted Jacobi with
        // skipped levels (12 against 24 on a 48x40 stretched grid).
        HYPRE_StructPFMGSetRelaxType(pfmg_, 2);
        HYPRE_StructPFMGSetSkipRelax(pfmg_, 0);
        HYPRE_StructPFMGSetNumPreRelax(pfmg_, 1);
        HYPRE_StructPFMGSetNumPostRelax(pfmg_, 1);
        null_spaces()[pfmg_] = NullSpace{singular_ ? ones_ : nullptr, singular_ ? fluid_cells_ : 0.0};
        HYPRE_StructPCGSetPrecond(pcg_, pfmg_zero_mean, HYPRE_StructPFMGSetup, pfmg_);
    }
    HYPRE_StructVectorAssemble(b_);
    HYPRE_StructVectorAssemble(x_);
    HYPRE_StructPCGSetup(pcg_, matrix_, b_, x_);
}

PoissonStats PoissonSolver::solve(const Field2D& source, Field2D& p, double absolute_tolerance,
                                  double relative_tolerance) {
    if (direct_) {
        direct_->solve(source, p);
        return PoissonStats{};
    }
    const auto& X = grid_.lx();
    const auto& Y = grid_.ly();
    const int nx = grid_.nx(), ny = grid_.ny();
    MPI_Comm comm = grid_.comm();

    auto fluid = [&](int i, int j) { return fluid_ ? (*fluid_)(i, j) : 1.0; };
    double sums[2] = {0.0, 0.0};  // right-hand side, initial guess
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double b = -X.w(i) * Y.w(j) * source(i, j) * fluid(i, j);
            buffer_[static_cast<std::size_t>(j) * nx + i] = b;
            sums[0] += b;
        }
    if (singular_) {
        // Compatibility: the null space is the constants (on the fluid cells), so the right-hand side must sum
        // to zero.
        MPI_Allreduce(MPI_IN_PLACE, sums, 1, MPI_DOUBLE, MPI_SUM, comm);
        const double mean = sums[0] / fluid_cells_;
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) buffer_[static_cast<std::size_t>(j) * nx + i] -= mean * fluid(i, j);
    }
    HYPRE_StructVectorSetBoxValues(b_, lower_.data(), upper_.data(), buffer_.data());
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) buffer_[static_cast<std::size_t>(j) * nx + i] = p(i, j) * fluid(i, j);
    HYPRE_StructVectorSetBoxValues(x_, lower_.data(), upper_.data(), buffer_.data());
    HYPRE_StructVectorAssemble(b_);
    HYPRE_StructVectorAssemble(x_);

    HYPRE_StructPCGSetAbsoluteTol(pcg_, absolute_tolerance);
    if (relative_tolerance > 0.0) HYPRE_StructPCGSetTol(pcg_, relative_tolerance);
    HYPRE_StructPCGSolve(pcg_, matrix_, b_, x_);
    if (relative_tolerance > 0.0) HYPRE_StructPCGSetTol(pcg_, tolerance_);
    PoissonStats stats;
    HYPRE_StructPCGGetNumIterations(pcg_, &stats.iterations);
    HYPRE_StructPCGGetFinalRelativeResidualNorm(pcg_, &stats.relative_residual);
    HYPRE_ClearAllErrors();  // non-convergence is reported through the stats, not hypre's error flag

    HYPRE_StructVectorGetBoxValues(x_, lower_.data(), upper_.data(), buffer_.data());
    double mean = 0.0;
    if (singular_) {
        double local = 0.0;
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) local += buffer_[static_cast<std::size_t>(j) * nx + i] * fluid(i, j);
        MPI_Allreduce(&local, &mean, 1, MPI_DOUBLE, MPI_SUM, comm);
        mean /= fluid_cells_;
    }
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) p(i, j) = (buffer_[static_cast<std::size_t>(j) * nx + i] - mean) * fluid(i, j);
    return stats;
}

}  // namespace chute
