#include "direct_poisson.hpp"

#include <fftw3.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace chute {

namespace {

bool uniform(const Axis& axis) {
    const double h = axis.length() / axis.cells();
    for (int k = 0; k < axis.cells(); ++k)
        if (std::abs(axis.width(k) - h) > 1e-10 * h) return false;
    return true;
}

const Axis& axis_of(const Grid& g, int a) { return a == 0 ? g.x_axis() : g.y_axis(); }

// The sides at the low and high end of axis a.
Side low_side(int a) { return a == 0 ? Side::left : Side::bottom; }
Side high_side(int a) { return a == 0 ? Side::right : Side::top; }

// Storage of a box whose cells are contiguous along axis `a` (lines of that axis one after another).
BoxStorage lines_along(int a, const CellBox& box) {
    BoxStorage s{box, 1, 1};
    if (a == 0)
        s.sj = box.i1 - box.i0;
    else
        s.si = box.j1 - box.j0;
    return s;
}

// Every line of axis `along` whole, the lines (indices along the other axis) shared out over the ranks.
CellBox whole_lines(const Grid& g, int along, int rank, int ranks) {
    const int across = along == 0 ? g.global_ny() : g.global_nx();
    int first = 0, count = 0;
    block_range(across, ranks, rank, first, count);
    if (along == 0) return {0, g.global_nx(), first, first + count};
    return {first, first + count, 0, g.global_ny()};
}

// Thomas' algorithm on x[0, n): a x_{k-1} + b x_k + c x_{k+1} = x (right-hand side in, solution out).
void thomas(int n, const double* a, const double* b, const double* c, double eigen_term, const double* width,
            double* x, double* cp) {
    double den = b[0] + eigen_term * width[0];
    cp[0] = c[0] / den;
    x[0] /= den;
    for (int k = 1; k < n; ++k) {
        den = b[k] + eigen_term * width[k] - a[k] * cp[k - 1];
        cp[k] = c[k] / den;
        x[k] = (x[k] - a[k] * x[k - 1]) / den;
    }
    for (int k = n - 2; k >= 0; --k) x[k] -= cp[k] * x[k + 1];
}

}  // namespace

int DirectPoissonSolver::transform_axis(const Grid& grid) {
    const bool ux = uniform(grid.x_axis()), uy = uniform(grid.y_axis());
    if (ux && uy) return grid.y_axis().periodic() && !grid.x_axis().periodic() ? 1 : 0;
    if (ux) return 0;
    if (uy) return 1;
    return -1;
}

DirectPoissonSolver::DirectPoissonSolver(const Grid& grid, std::array<bool, 4> dirichlet_sides)
    : grid_(grid), dirichlet_(dirichlet_sides) {
    t_ = transform_axis(grid_);
    if (t_ < 0) throw std::logic_error("DirectPoissonSolver: no uniform axis");
    const int d = 1 - t_;
    const Axis& T = axis_of(grid_, t_);
    nt_ = T.cells();
    nd_ = axis_of(grid_, d).cells();
    singular_ = !(dirichlet_[0] || dirichlet_[1] || dirichlet_[2] || dirichlet_[3]);
    cyclic_ = axis_of(grid_, d).periodic();

    // The transform along T and its modes' eigenvalues.
    const bool low_dirichlet = dirichlet_[static_cast<int>(low_side(t_))];
    const bool high_dirichlet = dirichlet_[static_cast<int>(high_side(t_))];
    fftw_r2r_kind forward_kind = FFTW_REDFT10, inverse_kind = FFTW_REDFT01;
    double shift = 0.0;  // theta_m = pi (m + shift) / N
    if (T.periodic()) {
        forward_kind = FFTW_R2HC;
        inverse_kind = FFTW_HC2R;
    } else if (low_dirichlet && high_dirichlet) {
        forward_kind = FFTW_RODFT10;
        inverse_kind = FFTW_RODFT01;
        shift = 1.0;
    } else if (high_dirichlet) {
        forward_kind = inverse_kind = FFTW_REDFT11;
        shift = 0.5;
    } else if (low_dirichlet) {
        forward_kind = inverse_kind = FFTW_RODFT11;
        shift = 0.5;
    }
    normalisation_ = T.periodic() ? nt_ : 2.0 * nt_;
    h_ = T.length() / nt_;
    eigenvalue_.resize(nt_);
    for (int m = 0; m < nt_; ++m) {
        const double theta = T.periodic() ? 2.0 * std::numbers::pi * std::min(m, nt_ - m) / nt_
                                          : std::numbers::pi * (m + shift) / nt_;
        const double s = std::sin(0.5 * theta);
        eigenvalue_[m] = -4.0 * s * s / (h_ * h_);
    }

    // The three layouts and the transposes between them.
    const int ranks = grid_.size(), rank = grid_.rank();
    const auto& X = grid_.lx();
    const auto& Y = grid_.ly();
    patch_ = BoxStorage{{X.offset, X.offset + X.n, Y.offset, Y.offset + Y.n}, 1, Field2D(grid_).stride()};
    lines_t_ = lines_along(t_, whole_lines(grid_, t_, rank, ranks));
    lines_d_ = lines_along(d, whole_lines(grid_, d, rank, ranks));
    to_t_ = std::make_unique<PencilTranspose>(grid_.comm(), patch_, lines_t_);
    t_to_d_ = std::make_unique<PencilTranspose>(grid_.comm(), lines_t_, lines_d_);
    d_to_t_ = std::make_unique<PencilTranspose>(grid_.comm(), lines_d_, lines_t_);
    from_t_ = std::make_unique<PencilTranspose>(grid_.comm(), lines_t_, patch_);
    t_data_.assign(static_cast<std::size_t>(lines_t_.box.cells()), 0.0);
    d_data_.assign(static_cast<std::size_t>(lines_d_.box.cells()), 0.0);
    scratch_.resize(nd_);
    if (cyclic_) cyclic_z_.resize(nd_);

    // One plan for all of this rank's lines along T, in place (FFTW_ESTIMATE leaves the data alone).
    const int lines = static_cast<int>(lines_t_.box.cells() / nt_);
    if (lines > 0) {
        int n[1] = {nt_};
        forward_ = fftw_plan_many_r2r(1, n, lines, t_data_.data(), nullptr, 1, nt_, t_data_.data(), nullptr, 1, nt_,
                                      &forward_kind, FFTW_ESTIMATE);
        inverse_ = fftw_plan_many_r2r(1, n, lines, t_data_.data(), nullptr, 1, nt_, t_data_.data(), nullptr, 1, nt_,
                                      &inverse_kind, FFTW_ESTIMATE);
        if (!forward_ || !inverse_) throw std::runtime_error("DirectPoissonSolver: FFTW could not plan the transform");
    }
    update_lines();
}

DirectPoissonSolver::~DirectPoissonSolver() {
    if (forward_) fftw_destroy_plan(forward_);
    if (inverse_) fftw_destroy_plan(inverse_);
}

void DirectPoissonSolver::update_lines() {
    if (transform_axis(grid_) != t_) throw std::logic_error("DirectPoissonSolver: the transform axis is no longer uniform");
    // Row k of the D-direction operator times h_T (poisson_solver.hpp's finite-volume form divided by h_T):
    //   (p_{k+1} - p_k) / dc_{k+1} - (p_k - p_{k-1}) / dc_k + w_k lambda_m p_k = h_T^-1 V_k s_k
    // dc across a boundary face is the distance to the mirrored ghost (a Dirichlet face: ghost -p, twice the flux).
    const int d = 1 - t_;
    const Axis& D = axis_of(grid_, d);
    const bool low_dirichlet = dirichlet_[static_cast<int>(low_side(d))];
    const bool high_dirichlet = dirichlet_[static_cast<int>(high_side(d))];
    lower_.assign(nd_, 0.0);
    upper_.assign(nd_, 0.0);
    diagonal_.assign(nd_, 0.0);
    width_.assign(nd_, 0.0);
    for (int k = 0; k < nd_; ++k) {
        const double a = 1.0 / (D.centre(k) - D.centre(k - 1)), c = 1.0 / (D.centre(k + 1) - D.centre(k));
        const bool first = k == 0 && !cyclic_, last = k == nd_ - 1 && !cyclic_;
        lower_[k] = first ? 0.0 : a;
        upper_[k] = last ? 0.0 : c;
        diagonal_[k] = -((first ? (low_dirichlet ? 2.0 * a : 0.0) : a) + (last ? (high_dirichlet ? 2.0 * c : 0.0) : c));
        width_[k] = D.width(k);
    }
}

void DirectPoissonSolver::solve(const Field2D& source, Field2D& p) {
    // 1. The source, on whole lines along T, times the cell volume (h_T w_D): the finite-volume right-hand side.
    to_t_->run(source.origin(), t_data_.data());
    const int d = 1 - t_;
    const Axis& D = axis_of(grid_, d);
    const int lines = static_cast<int>(lines_t_.box.cells() / nt_);
    const int first_line = d == 0 ? lines_t_.box.i0 : lines_t_.box.j0;
    double sum = 0.0;
    for (int l = 0; l < lines; ++l) {
        double* line = t_data_.data() + static_cast<std::size_t>(l) * nt_;
        const double volume = h_ * D.width(first_line + l);
        for (int m = 0; m < nt_; ++m) {
            line[m] *= volume;
            sum += line[m];
        }
    }
    if (singular_) {  // compatibility: the Neumann problem takes only zero-sum right-hand sides
        MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_DOUBLE, MPI_SUM, grid_.comm());
        const double mean = sum / static_cast<double>(grid_.global_cells());
        for (double& v : t_data_) v -= mean;
    }

    // 2. Transform, solve each mode's tridiagonal system along D, transform back.
    if (forward_) fftw_execute(forward_);
    t_to_d_->run(t_data_.data(), d_data_.data());
    solve_lines();
    d_to_t_->run(d_data_.data(), t_data_.data());
    if (inverse_) fftw_execute(inverse_);

    // 3. Scale (the transforms' normalisation and the 1/h_T of the rows), remove the mean, back to the patch.
    const double scale = 1.0 / (h_ * normalisation_);
    double mean = 0.0;
    if (singular_) {
        double local = 0.0;
        for (double v : t_data_) local += v;
        MPI_Allreduce(&local, &mean, 1, MPI_DOUBLE, MPI_SUM, grid_.comm());
        mean /= static_cast<double>(grid_.global_cells());
    }
    for (double& v : t_data_) v = (v - mean) * scale;
    from_t_->run(t_data_.data(), p.origin());
}

void DirectPoissonSolver::solve_lines() {
    const int modes = static_cast<int>(lines_d_.box.cells() / nd_);
    const int first_mode = t_ == 0 ? lines_d_.box.i0 : lines_d_.box.j0;
    for (int l = 0; l < modes; ++l) {
        const int m = first_mode + l;
        double* x = d_data_.data() + static_cast<std::size_t>(l) * nd_;
        const double lambda = eigenvalue_[m];
        if (singular_ && m == 0) {
            // The null space: pin x_0 = 0 and solve the rows 1 .. n-1 (row 0 then holds by compatibility).
            x[0] = 0.0;
            if (nd_ > 1) {
                const double a1 = lower_[1];
                lower_[1] = 0.0;  // x_0 = 0 drops out of row 1 (and, periodic, out of row n-1: thomas ignores it)
                thomas(nd_ - 1, lower_.data() + 1, diagonal_.data() + 1, upper_.data() + 1, lambda, width_.data() + 1,
                       x + 1, scratch_.data());
                lower_[1] = a1;
            }
            continue;
        }
        if (!cyclic_ || nd_ < 3) {
            thomas(nd_, lower_.data(), diagonal_.data(), upper_.data(), lambda, width_.data(), x, scratch_.data());
            continue;
        }
        // Periodic: Sherman-Morrison on the cyclic system (Press et al., Numerical Recipes, 2.7). Corners:
        // A[0][n-1] = lower_[0] (beta), A[n-1][0] = upper_[n-1] (alpha).
        const int n = nd_;
        const double alpha = upper_[n - 1], beta = lower_[0];
        const double b0 = diagonal_[0] + lambda * width_[0];
        const double gamma = -b0;
        // The modified diagonal, b_0 - gamma and b_{n-1} - alpha beta / gamma (thomas() never reads the corners).
        std::vector<double>& z = cyclic_z_;
        const double save0 = diagonal_[0], save_last = diagonal_[n - 1];
        diagonal_[0] -= gamma;
        diagonal_[n - 1] -= alpha * beta / gamma;
        thomas(n, lower_.data(), diagonal_.data(), upper_.data(), lambda, width_.data(), x, scratch_.data());
        std::fill(z.begin(), z.end(), 0.0);
        z[0] = gamma;
        z[n - 1] = alpha;
        thomas(n, lower_.data(), diagonal_.data(), upper_.data(), lambda, width_.data(), z.data(), scratch_.data());
        diagonal_[0] = save0;
        diagonal_[n - 1] = save_last;
        const double factor = (x[0] + beta * x[n - 1] / gamma) / (1.0 + z[0] + beta * z[n - 1] / gamma);
        for (int k = 0; k < n; ++k) x[k] -= factor * z[k];
    }
}

}  // namespace chute
