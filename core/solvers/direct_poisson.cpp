#include "direct_poisson.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace chute {

namespace {

// Modes solved together in the tridiagonal sweeps (their working set, nd x block doubles, stays in cache).
constexpr int kModeBlock = 32;

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
void thomas(int n, const double* a, const double* b, const double* c, double eigen_term, const double* width, double* x,
            double* cp) {
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

// A x = b for a small dense A (row-major, n x n), by Gaussian elimination with partial pivoting; b becomes x.
void solve_dense(int n, double* A, double* b) {
    for (int col = 0; col < n; ++col) {
        int pivot = col;
        for (int r = col + 1; r < n; ++r)
            if (std::abs(A[r * n + col]) > std::abs(A[pivot * n + col])) pivot = r;
        if (pivot != col) {
            for (int k = 0; k < n; ++k) std::swap(A[col * n + k], A[pivot * n + k]);
            std::swap(b[col], b[pivot]);
        }
        for (int r = col + 1; r < n; ++r) {
            const double f = A[r * n + col] / A[col * n + col];
            if (f == 0.0) continue;
            for (int k = col; k < n; ++k) A[r * n + k] -= f * A[col * n + k];
            b[r] -= f * b[col];
        }
    }
    for (int r = n - 1; r >= 0; --r) {
        double v = b[r];
        for (int k = r + 1; k < n; ++k) v -= A[r * n + k] * b[k];
        b[r] = v / A[r * n + r];
    }
}

// The largest prime factor of n: FFTW's cost per point grows with it (a length with a large prime factor falls back
// to slower algorithms; 767 = 13 x 59 took twice as long as 768 = 2^8 x 3, a prime 367 three times 368's).
int largest_prime_factor(int n) {
    int largest = 1;
    for (int p = 2; p * p <= n; ++p)
        while (n % p == 0) {
            largest = p;
            n /= p;
        }
    return n > 1 ? std::max(largest, n) : largest;
}

}  // namespace

int DirectPoissonSolver::transform_axis(const Grid& grid) {
    const bool ux = uniform_axis(grid.x_axis()), uy = uniform_axis(grid.y_axis());
    // A periodic axis carrying the tridiagonal systems needs 3 cells for Sherman-Morrison's corners.
    const bool x_systems_ok = !grid.x_axis().periodic() || grid.global_nx() >= 3;
    const bool y_systems_ok = !grid.y_axis().periodic() || grid.global_ny() >= 3;
    if (ux && uy && y_systems_ok && x_systems_ok) {
        // Both: the one whose lines the patches hold whole (the systems then partitioned where they lie, or no
        // split at all: no transpose), then a periodic one (its systems would be cyclic), then the length FFTW
        // transforms faster (the smaller largest prime factor), else x.
        const auto split = grid.ranks();
        if ((split[0] == 1) != (split[1] == 1)) return split[0] == 1 ? 0 : 1;
        if (grid.x_axis().periodic() != grid.y_axis().periodic()) return grid.y_axis().periodic() ? 1 : 0;
        return largest_prime_factor(grid.global_ny()) < largest_prime_factor(grid.global_nx()) ? 1 : 0;
    }
    if (ux && y_systems_ok) return 0;
    if (uy && x_systems_ok) return 1;
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
    h_ = T.length() / nt_;

    // The layouts. A patch holds whole lines along an axis when the decomposition does not split that axis.
    const int ranks = grid_.size(), rank = grid_.rank();
    const auto& X = grid_.lx();
    const auto& Y = grid_.ly();
    patch_ = BoxStorage{{X.offset, X.offset + X.n, Y.offset, Y.offset + Y.n}, 1, Field2D(grid_).stride()};
    const auto split = grid_.ranks();
    if (split[t_] == 1)
        transform_ = {patch_, true};
    else
        transform_ = {lines_along(t_, whole_lines(grid_, t_, rank, ranks)), false};
    // Stored x-fastest like the patch, so that the transposes copy whole runs of cells (along x the systems' sweeps
    // then run over neighbouring modes contiguously, along y over modes a row apart: independent chains either way).
    // Where the patches hold whole transform lines but split the systems' axis, the systems are solved where they
    // lie, partitioned (solve_partitioned): no transpose at all.
    partitioned_ = split[t_] == 1 && split[d] > 1;
    if (split[d] == 1 || partitioned_)
        systems_ = {patch_, true};
    else
        systems_ = {lines_along(0, whole_lines(grid_, d, rank, ranks)), false};
    if (partitioned_) {
        row0_ = d == 0 ? X.offset : Y.offset;
        rows_ = d == 0 ? X.n : Y.n;
        row_starts_.assign(ranks, 0);
        row_counts_.assign(ranks, 0);
        MPI_Allgather(&row0_, 1, MPI_INT, row_starts_.data(), 1, MPI_INT, grid_.comm());
        MPI_Allgather(&rows_, 1, MPI_INT, row_counts_.data(), 1, MPI_INT, grid_.comm());
        partition_sm_ = t_ == 0 ? 1 : rows_;
        partition_sk_ = t_ == 0 ? nt_ : 1;
    }
    if (!transform_.in_patch) {
        transform_data_.assign(static_cast<std::size_t>(transform_.storage.box.cells()), 0.0);
        patch_to_transform_ = std::make_unique<PencilTranspose>(grid_.comm(), patch_, transform_.storage);
        transform_to_patch_ = std::make_unique<PencilTranspose>(grid_.comm(), transform_.storage, patch_);
    }
    if (!(transform_.in_patch && systems_.in_patch)) {
        if (!systems_.in_patch) systems_data_.assign(static_cast<std::size_t>(systems_.storage.box.cells()), 0.0);
        transform_to_systems_ = std::make_unique<PencilTranspose>(grid_.comm(), transform_.storage, systems_.storage);
        systems_to_transform_ = std::make_unique<PencilTranspose>(grid_.comm(), systems_.storage, transform_.storage);
    }
    scratch_.resize(static_cast<std::size_t>(nd_) * kModeBlock);

    // The modes' eigenvalues along T.
    const bool low_dirichlet = dirichlet_[static_cast<int>(low_side(t_))];
    const bool high_dirichlet = dirichlet_[static_cast<int>(high_side(t_))];
    const double shift = T.periodic()                      ? 0.0
                         : low_dirichlet && high_dirichlet ? 1.0
                         : low_dirichlet || high_dirichlet ? 0.5
                                                           : 0.0;
    normalisation_ = T.periodic() ? nt_ : 2.0 * nt_;
    eigenvalue_.resize(nt_);
    for (int m = 0; m < nt_; ++m) {
        const double theta =
            T.periodic() ? 2.0 * std::numbers::pi * std::min(m, nt_ - m) / nt_ : std::numbers::pi * (m + shift) / nt_;
        const double s = std::sin(0.5 * theta);
        eigenvalue_[m] = -4.0 * s * s / (h_ * h_);
    }
    plan_transforms();
    update_lines();
}

DirectPoissonSolver::~DirectPoissonSolver() {
    if (forward_) fftw_destroy_plan(forward_);
    if (inverse_) fftw_destroy_plan(inverse_);
}

// One plan each way for all of this rank's lines along T. The forward transform reads the source and writes the
// transform's layout (out of place when that is p); the inverse works in place. FFTW_ESTIMATE, not FFTW_MEASURE:
// a measured plan depends on the timings of the moment, and another plan rounds differently (FFTW manual, 4.3.2),
// so a run restarted in a new process would no longer continue bit for bit (measuring was 12 % faster on the
// 1024^2 solve). FFTW_UNALIGNED lets the plans run on the solve's own fields.
void DirectPoissonSolver::plan_transforms() {
    const bool low_dirichlet = dirichlet_[static_cast<int>(low_side(t_))];
    const bool high_dirichlet = dirichlet_[static_cast<int>(high_side(t_))];
    fftw_r2r_kind forward_kind = FFTW_REDFT10, inverse_kind = FFTW_REDFT01;
    if (axis_of(grid_, t_).periodic()) {
        forward_kind = FFTW_R2HC;
        inverse_kind = FFTW_HC2R;
    } else if (low_dirichlet && high_dirichlet) {
        forward_kind = FFTW_RODFT10;
        inverse_kind = FFTW_RODFT01;
    } else if (high_dirichlet) {
        forward_kind = inverse_kind = FFTW_REDFT11;
    } else if (low_dirichlet) {
        forward_kind = inverse_kind = FFTW_RODFT11;
    }
    const BoxStorage& L = transform_.storage;
    const int lines = static_cast<int>(L.box.cells() / nt_);
    if (lines == 0) return;
    const int stride = static_cast<int>(t_ == 0 ? L.si : L.sj), distance = static_cast<int>(t_ == 0 ? L.sj : L.si);
    int n[1] = {nt_};
    const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED;
    if (transform_.in_patch) {
        Field2D in(grid_), out(grid_);
        forward_ = fftw_plan_many_r2r(1, n, lines, in.origin(), nullptr, stride, distance, out.origin(), nullptr,
                                      stride, distance, &forward_kind, flags | FFTW_PRESERVE_INPUT);
        inverse_ = fftw_plan_many_r2r(1, n, lines, out.origin(), nullptr, stride, distance, out.origin(), nullptr,
                                      stride, distance, &inverse_kind, flags);
    } else {
        double* data = transform_data_.data();
        forward_ = fftw_plan_many_r2r(1, n, lines, data, nullptr, stride, distance, data, nullptr, stride, distance,
                                      &forward_kind, flags);
        inverse_ = fftw_plan_many_r2r(1, n, lines, data, nullptr, stride, distance, data, nullptr, stride, distance,
                                      &inverse_kind, flags);
    }
    if (!forward_ || !inverse_) throw std::runtime_error("DirectPoissonSolver: FFTW could not plan the transforms");
}

void DirectPoissonSolver::update_lines() {
    if (transform_axis(grid_) != t_)
        throw std::logic_error("DirectPoissonSolver: the transform axis is no longer uniform");
    // Row k of the D-direction operator (poisson_solver.hpp's finite-volume form divided by h_T), for mode m:
    //   (p_{k+1} - p_k) / dc_{k+1} - (p_k - p_{k-1}) / dc_k + w_k lambda_m p_k = h_T^-1 V_k s_k = w_k s_k
    // dc across a boundary face is the distance to the mirrored ghost (a Dirichlet face: ghost -p, twice the flux).
    // The right-hand side also carries the transforms' normalisation, so the inverse transform gives p.
    const int d = 1 - t_;
    const Axis& D = axis_of(grid_, d);
    const bool low_dirichlet = dirichlet_[static_cast<int>(low_side(d))];
    const bool high_dirichlet = dirichlet_[static_cast<int>(high_side(d))];
    lower_.assign(nd_, 0.0);
    upper_.assign(nd_, 0.0);
    diagonal_.assign(nd_, 0.0);
    width_.assign(nd_, 0.0);
    rhs_scale_.assign(nd_, 0.0);
    for (int k = 0; k < nd_; ++k) {
        const double a = 1.0 / (D.centre(k) - D.centre(k - 1)), c = 1.0 / (D.centre(k + 1) - D.centre(k));
        const bool first = k == 0 && !cyclic_, last = k == nd_ - 1 && !cyclic_;
        lower_[k] = first ? 0.0 : a;
        upper_[k] = last ? 0.0 : c;
        diagonal_[k] = -((first ? (low_dirichlet ? 2.0 * a : 0.0) : a) + (last ? (high_dirichlet ? 2.0 * c : 0.0) : c));
        width_[k] = D.width(k);
        rhs_scale_[k] = width_[k] / normalisation_;
    }
    if (partitioned_)
        partition_prepare();
    else if (cyclic_)
        prepare_cyclic();
}

// Periodic systems by Sherman-Morrison (Press et al., Numerical Recipes, 2.7): A = T + u v^T with corners
// A[0][n-1] = beta = lower_0 and A[n-1][0] = alpha = upper_{n-1}; T has b_0 - gamma and b_{n-1} - alpha beta / gamma
// on its diagonal (gamma = -b_0), u = (gamma, 0, .., alpha), v = (1, 0, .., beta / gamma). Then
// x = y - z (v.y) / (1 + v.z) with T y = rhs, T z = u; z depends on the mode alone, so it is made here once.
void DirectPoissonSolver::prepare_cyclic() {
    const BoxStorage& L = systems_.storage;
    const int modes = static_cast<int>(L.box.cells() / nd_), first_mode = t_ == 0 ? L.box.i0 : L.box.j0;
    const int n = nd_;
    const double alpha = upper_[n - 1], beta = lower_[0];
    cyclic_gamma_.assign(modes, 0.0);
    cyclic_inverse_.assign(modes, 0.0);
    cyclic_z_.assign(static_cast<std::size_t>(modes) * n, 0.0);
    std::vector<double> b(diagonal_);
    for (int l = 0; l < modes; ++l) {
        const double lambda = eigenvalue_[first_mode + l];
        const double gamma = -(diagonal_[0] + lambda * width_[0]);
        b[0] = diagonal_[0] - gamma;
        b[n - 1] = diagonal_[n - 1] - alpha * beta / gamma;
        double* z = cyclic_z_.data() + static_cast<std::size_t>(l) * n;
        z[0] = gamma;
        z[n - 1] = alpha;
        thomas(n, lower_.data(), b.data(), upper_.data(), lambda, width_.data(), z, scratch_.data());
        cyclic_gamma_[l] = gamma;
        cyclic_inverse_[l] = 1.0 / (1.0 + z[0] + beta * z[n - 1] / gamma);
    }
}

void DirectPoissonSolver::solve(const Field2D& source, Field2D& p) {
    // 1. Transform the source along T (into p, or into whole lines after a transpose).
    double* lines_t = transform_.in_patch ? p.origin() : transform_data_.data();
    if (transform_.in_patch) {
        if (forward_) fftw_execute_r2r(forward_, const_cast<double*>(source.origin()), lines_t);
    } else {
        patch_to_transform_->run(source.origin(), lines_t);
        if (forward_) fftw_execute_r2r(forward_, lines_t, lines_t);
    }
    // 2. Each mode's tridiagonal system along D.
    double* lines_d = systems_.in_patch ? p.origin() : systems_data_.data();
    if (transform_to_systems_) transform_to_systems_->run(lines_t, lines_d);
    if (partitioned_)
        solve_partitioned(lines_d, t_ == 0 ? patch_.si : patch_.sj, t_ == 0 ? patch_.sj : patch_.si);
    else
        solve_modes(lines_d, systems_.storage);
    if (systems_to_transform_) systems_to_transform_->run(lines_d, lines_t);
    // 3. Back along T.
    if (inverse_) fftw_execute_r2r(inverse_, lines_t, lines_t);
    if (!transform_.in_patch) transform_to_patch_->run(lines_t, p.origin());
}

void DirectPoissonSolver::solve_modes(double* data, const BoxStorage& L) {
    const int modes = static_cast<int>(L.box.cells() / nd_), first_mode = t_ == 0 ? L.box.i0 : L.box.j0;
    const std::ptrdiff_t sm = t_ == 0 ? L.si : L.sj, sk = t_ == 0 ? L.sj : L.si;
    int l_begin = 0;
    if (singular_ && first_mode == 0 && modes > 0) {
        solve_null_mode(data, sk);
        l_begin = 1;
    }
    sweep_modes(data, sm, sk, first_mode, l_begin, modes, 0, nd_, cyclic_);
}

// Thomas' algorithm on rows [k0, k0 + n) of the modes l_begin .. modes - 1 (of those from first_mode on; data at
// mode first_mode, row k0), right-hand sides scaled by rhs_scale_ on the way. Rows outside are not coupled (the
// partitioned solve couples them afterwards); `cyclic`: the whole periodic line, by Sherman-Morrison. The modes go
// in blocks: the sweeps along k run over a block's modes in the inner loop (contiguous when modes are, so it
// vectorises; independent chains either way), its working set in cache.
void DirectPoissonSolver::sweep_modes(double* data, std::ptrdiff_t sm, std::ptrdiff_t sk, int first_mode, int l_begin,
                                      int modes, int k0, int n, bool cyclic) {
    const double* a = lower_.data() + k0;
    const double* c = upper_.data() + k0;
    const double* b = diagonal_.data() + k0;
    const double* w = width_.data() + k0;
    const double* r = rhs_scale_.data() + k0;
    for (int l0 = l_begin; l0 < modes; l0 += kModeBlock) {
        const int count = std::min(kModeBlock, modes - l0);
        const double* lambda = eigenvalue_.data() + first_mode + l0;
        double* base = data + l0 * sm;
        double* cp = scratch_.data();
        for (int k = 0; k < n; ++k) {
            double* x = base + k * sk;
            double* cpk = cp + static_cast<std::size_t>(k) * count;
            if (k == 0) {
                for (int q = 0; q < count; ++q) {
                    double den = b[0] + lambda[q] * w[0];
                    if (cyclic) den -= cyclic_gamma_[l0 + q];
                    const double inv = 1.0 / den;
                    cpk[q] = c[0] * inv;
                    x[q * sm] = x[q * sm] * r[0] * inv;
                }
                continue;
            }
            const double* xp = x - sk;
            const double* cpp = cpk - count;
            const bool last_cyclic = cyclic && k == n - 1;
            for (int q = 0; q < count; ++q) {
                double den = b[k] + lambda[q] * w[k] - a[k] * cpp[q];
                if (last_cyclic) den -= upper_[n - 1] * lower_[0] / cyclic_gamma_[l0 + q];
                const double inv = 1.0 / den;
                cpk[q] = c[k] * inv;
                x[q * sm] = (x[q * sm] * r[k] - a[k] * xp[q * sm]) * inv;
            }
        }
        for (int k = n - 2; k >= 0; --k) {
            double* x = base + k * sk;
            const double* cpk = cp + static_cast<std::size_t>(k) * count;
            for (int q = 0; q < count; ++q) x[q * sm] -= cpk[q] * x[q * sm + sk];
        }
        if (!cyclic) continue;
        const double beta = lower_[0];
        for (int q = 0; q < count; ++q) {
            const int l = l0 + q;
            double* x = base + q * sm;
            const double* z = cyclic_z_.data() + static_cast<std::size_t>(l) * n;
            const double factor = (x[0] + beta * x[(n - 1) * sk] / cyclic_gamma_[l]) * cyclic_inverse_[l];
            for (int k = 0; k < n; ++k) x[k * sk] -= factor * z[k];
        }
    }
}

// The partitioned solve (Wang 1981, ACM TOMS 7:170; the substructuring of PaScaL_TDMA, Kim et al. 2021, CPC
// 260:107722) where the patches split the systems' axis and hold whole lines along the transform: no transpose.
// Each rank solves its rows with the neighbours' unknowns taken as 0, y = A_p^-1 r; the true solution is
// x = y - (a_first x_before) g - (c_last x_after) h, with g = A_p^-1 e_first and h = A_p^-1 e_last (made once,
// partition_prepare). Each rank's first and last unknowns F_p, L_p then satisfy, per mode, a system of 2P rows
//   F_p + a_p gF_p L_{p-1} + c_p hF_p F_{p+1} = yF_p,   L_p + a_p gL_p L_{p-1} + c_p hL_p F_{p+1} = yL_p
// (indices modulo P: on a non-periodic axis the ends' couplings are 0), gathered over the ranks and solved on each.
void DirectPoissonSolver::partition_prepare() {
    const int ranks = grid_.size();
    const int n = rows_;
    partition_g_.assign(static_cast<std::size_t>(nt_) * n, 0.0);
    partition_h_.assign(static_cast<std::size_t>(nt_) * n, 0.0);
    std::vector<double> edges(4 * static_cast<std::size_t>(nt_), 0.0), line(n);
    for (int m = 0; m < nt_; ++m) {
        if (singular_ && m == 0) continue;  // solved whole (solve_null_mode)
        for (int unit = 0; unit < 2; ++unit) {
            std::fill(line.begin(), line.end(), 0.0);
            line[unit == 0 ? 0 : n - 1] = 1.0;
            thomas(n, lower_.data() + row0_, diagonal_.data() + row0_, upper_.data() + row0_, eigenvalue_[m],
                   width_.data() + row0_, line.data(), scratch_.data());
            std::vector<double>& store = unit == 0 ? partition_g_ : partition_h_;
            for (int k = 0; k < n; ++k)
                store[static_cast<std::size_t>(m) * partition_sm_ + k * partition_sk_] = line[k];
            edges[4 * m + 2 * unit] = line[0];
            edges[4 * m + 2 * unit + 1] = line[n - 1];
        }
    }
    partition_edges_.assign(4 * static_cast<std::size_t>(nt_) * ranks, 0.0);
    MPI_Allgather(edges.data(), 4 * nt_, MPI_DOUBLE, partition_edges_.data(), 4 * nt_, MPI_DOUBLE, grid_.comm());
}

void DirectPoissonSolver::solve_partitioned(double* data, std::ptrdiff_t sm, std::ptrdiff_t sk) {
    const int ranks = grid_.size(), me = grid_.rank();
    const int n = rows_;
    int m_begin = 0;
    if (singular_) {
        // Mode 0 whole on every rank: its line gathered, solved, this rank's rows kept.
        std::vector<double> mine(n), line(nd_);
        for (int k = 0; k < n; ++k) mine[k] = data[k * sk];
        MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, line.data(), row_counts_.data(), row_starts_.data(), MPI_DOUBLE,
                       grid_.comm());
        solve_null_mode(line.data(), 1);
        for (int k = 0; k < n; ++k) data[k * sk] = line[row0_ + k];
        m_begin = 1;
    }
    sweep_modes(data, sm, sk, 0, m_begin, nt_, row0_, n, false);

    // The first and last unknowns of y, every rank's, per mode.
    std::vector<double> mine(2 * static_cast<std::size_t>(nt_)), all(2 * static_cast<std::size_t>(nt_) * ranks);
    for (int m = 0; m < nt_; ++m) {
        mine[2 * m] = data[m * sm];
        mine[2 * m + 1] = data[m * sm + (n - 1) * sk];
    }
    MPI_Allgather(mine.data(), 2 * nt_, MPI_DOUBLE, all.data(), 2 * nt_, MPI_DOUBLE, grid_.comm());

    // Per mode the 2P x 2P system (Gaussian elimination with partial pivoting), then this rank's correction.
    const int size = 2 * ranks;
    std::vector<double> A(static_cast<std::size_t>(size) * size), u(size);
    std::vector<double> from_before(nt_, 0.0), from_after(nt_, 0.0);
    const int before = (me + ranks - 1) % ranks, after = (me + 1) % ranks;
    for (int m = m_begin; m < nt_; ++m) {
        std::fill(A.begin(), A.end(), 0.0);
        for (int p = 0; p < ranks; ++p) {
            const double a = lower_[row_starts_[p]], c = upper_[row_starts_[p] + row_counts_[p] - 1];
            const double* e = partition_edges_.data() + (static_cast<std::size_t>(p) * nt_ + m) * 4;  // gF gL hF hL
            const int F = 2 * p, L = 2 * p + 1;
            const int L_before = 2 * ((p + ranks - 1) % ranks) + 1, F_after = 2 * ((p + 1) % ranks);
            A[F * size + F] += 1.0;
            A[F * size + L_before] += a * e[0];
            A[F * size + F_after] += c * e[2];
            A[L * size + L] += 1.0;
            A[L * size + L_before] += a * e[1];
            A[L * size + F_after] += c * e[3];
            u[F] = all[(static_cast<std::size_t>(p) * nt_ + m) * 2];
            u[L] = all[(static_cast<std::size_t>(p) * nt_ + m) * 2 + 1];
        }
        solve_dense(size, A.data(), u.data());
        from_before[m] = lower_[row0_] * u[2 * before + 1];
        from_after[m] = upper_[row0_ + n - 1] * u[2 * after];
    }
    // x -= (a x_before) g + (c x_after) h, in the order the cells lie in memory.
    if (sm == 1) {
        for (int k = 0; k < n; ++k) {
            double* x = data + k * sk;
            const double* g = partition_g_.data() + static_cast<std::size_t>(k) * partition_sk_;
            const double* h = partition_h_.data() + static_cast<std::size_t>(k) * partition_sk_;
            for (int m = m_begin; m < nt_; ++m) x[m] -= from_before[m] * g[m] + from_after[m] * h[m];
        }
        return;
    }
    for (int m = m_begin; m < nt_; ++m) {
        double* x = data + m * sm;
        const double* g = partition_g_.data() + static_cast<std::size_t>(m) * partition_sm_;
        const double* h = partition_h_.data() + static_cast<std::size_t>(m) * partition_sm_;
        for (int k = 0; k < n; ++k)
            x[k * sk] -= from_before[m] * g[k * partition_sk_] + from_after[m] * h[k * partition_sk_];
    }
}

// Mode 0 of the singular (all-Neumann or periodic) problem. Its right-hand side's sum is the source's total,
// which the problem cannot take: it is spread evenly over the cells (the mean is removed, as PoissonSolver's
// hypre path does). Then x_0 = 0 pins the constant, the rows 1 .. n-1 are solved, and the solution's mean
// removed: this mode carries p's whole mean (the others' sums over T vanish).
void DirectPoissonSolver::solve_null_mode(double* x, std::ptrdiff_t stride) {
    std::vector<double> line(nd_);
    double sum = 0.0;
    for (int k = 0; k < nd_; ++k) sum += (line[k] = x[k * stride] * rhs_scale_[k]);
    // Minus the mean right-hand side per cell, h_T^-1 sum(V s) / cells, is minus sum / nd_ on this line.
    const double mean = sum / nd_;
    for (int k = 0; k < nd_; ++k) line[k] -= mean;
    line[0] = 0.0;
    if (nd_ > 1) {
        const double a1 = lower_[1];
        lower_[1] = 0.0;  // x_0 = 0 drops out of row 1 (and, periodic, out of row n-1: thomas() ignores it)
        thomas(nd_ - 1, lower_.data() + 1, diagonal_.data() + 1, upper_.data() + 1, eigenvalue_[0], width_.data() + 1,
               line.data() + 1, scratch_.data());
        lower_[1] = a1;
    }
    double solution_mean = 0.0;
    for (double v : line) solution_mean += v;
    solution_mean /= nd_;
    for (int k = 0; k < nd_; ++k) x[k * stride] = line[k] - solution_mean;
}

}  // namespace chute
