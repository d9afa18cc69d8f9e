#include "cut_poisson_preconditioner.hpp"

#include <HYPRE_struct_mv.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>

namespace chute {

CutPoissonPreconditioner::CutPoissonPreconditioner(const Grid& grid, std::array<bool, 4> dirichlet_sides, int margin)
    : grid_(grid), margin_(margin), direct_(grid, dirichlet_sides), source_(grid), correction_(grid) {
    lower_ = {grid_.lx().offset, grid_.ly().offset};
    upper_ = {grid_.lx().offset + grid_.nx() - 1, grid_.ly().offset + grid_.ny() - 1};
    const std::size_t n = static_cast<std::size_t>(grid_.nx()) * grid_.ny();
    volume_.resize(n);
    rhs_.resize(n);
    z_.resize(n);
    r_.resize(n);
    for (int j = 0; j < grid_.ny(); ++j)
        for (int i = 0; i < grid_.nx(); ++i)
            volume_[static_cast<std::size_t>(j) * grid_.nx() + i] = grid_.lx().w(i) * grid_.ly().w(j);
}

namespace {

// A row of the cut matrix that no surface changed: its coefficients the whole grid's. Not bit for bit: the
// whole grid's are computed once for a set of lines, and a grid that translates with a body (run/
// following_frame.hpp) keeps its spacings only to round-off, about 1e-16 |x| / h of each (1e-11 a hundred thousand
// cells from the origin). Compared bit for bit, every row of the followed block's window read as cut within a few
// steps, the window took more than a quarter of the grid and the solve fell back to SMG: the free fall on the window
// at 54 ms a step, 28 % of it SMG (docs/performance.md). A surface changes a coefficient by its aperture, and one
// it changes by less than this is left to the whole grid's solve: the preconditioner changes, not the problem PCG
// solves.
bool same_row(const double* cut, const double* whole) {
    const double tolerance = 1e-9 * std::abs(whole[0]);
    for (int k = 0; k < 5; ++k)
        if (std::abs(cut[k] - whole[k]) > tolerance) return false;
    return true;
}

}  // namespace

bool CutPoissonPreconditioner::set_up(const std::vector<double>& cut, const std::vector<double>& whole) {
    const int nx = grid_.nx(), ny = grid_.ny();
    const int gnx = grid_.global_nx(), gny = grid_.global_ny();
    const int ox = grid_.lx().offset, oy = grid_.ly().offset;
    const bool px = grid_.x_axis().periodic(), py = grid_.y_axis().periodic();

    // The cells whose rows the surfaces changed, from every rank; a covered cell away from the surface (its row
    // the diagonal alone, no coupling to any other cell) is solved by itself, not in the window: below a plane that
    // is half the grid.
    std::vector<long long> changed;
    std::vector<int> covered;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const std::size_t c = 5 * (static_cast<std::size_t>(j) * nx + i);
            if (same_row(cut.data() + c, whole.data() + c)) continue;
            if (std::all_of(cut.begin() + c + 1, cut.begin() + c + 5, [](double a) { return a == 0.0; }))
                covered.push_back(j * nx + i);
            else
                changed.push_back(static_cast<long long>(j + oy) * gnx + (i + ox));
        }
    const int count = static_cast<int>(changed.size());
    std::vector<int> counts(grid_.size()), offsets(grid_.size(), 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, grid_.comm());
    for (int r = 1; r < grid_.size(); ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    std::vector<long long> all(static_cast<std::size_t>(offsets.back() + counts.back()));
    MPI_Allgatherv(changed.data(), count, MPI_LONG_LONG, all.data(), counts.data(), offsets.data(), MPI_LONG_LONG,
                   grid_.comm());

    // The window: those cells and `margin` cells around them (a square of them: the coupling decays alike along
    // both axes), wrapped across periodic sides; marked in their bounding box (the whole axis if periodic), row-wise
    // then column-wise.
    if (all.empty()) return false;
    int i0 = gnx, i1 = -1, j0 = gny, j1 = -1;
    for (long long c : all) {
        const int i = static_cast<int>(c % gnx), j = static_cast<int>(c / gnx);
        i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
    }
    i0 = px ? 0 : std::max(0, i0 - margin_), i1 = px ? gnx - 1 : std::min(gnx - 1, i1 + margin_);
    j0 = py ? 0 : std::max(0, j0 - margin_), j1 = py ? gny - 1 : std::min(gny - 1, j1 + margin_);
    const int bw = i1 - i0 + 1, bh = j1 - j0 + 1;
    auto at = [&](int i, int j) { return static_cast<std::size_t>(j - j0) * bw + (i - i0); };
    auto wrap = [](int k, int n, bool periodic) { return periodic ? (k + n) % n : k; };
    std::vector<char> rows(static_cast<std::size_t>(bw) * bh, 0), marked(rows.size(), 0);
    for (long long c : all) {
        const int ci = static_cast<int>(c % gnx), j = static_cast<int>(c / gnx);
        for (int d = -margin_; d <= margin_; ++d)
            if (const int i = wrap(ci + d, gnx, px); i >= i0 && i <= i1) rows[at(i, j)] = 1;
    }
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
            if (rows[at(i, j)])
                for (int d = -margin_; d <= margin_; ++d)
                    if (const int k = wrap(j + d, gny, py); k >= j0 && k <= j1) marked[at(i, k)] = 1;
    std::vector<int> index(marked.size(), -1);  // per bounding-box cell: its place in the window, or -1
    window_.clear();
    local_.clear();
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            if (!marked[at(i, j)]) continue;
            index[at(i, j)] = static_cast<int>(window_.size());
            window_.push_back(static_cast<long long>(j) * gnx + i);
            const int li = i - ox, lj = j - oy;
            local_.push_back(li >= 0 && lj >= 0 && li < nx && lj < ny ? lj * nx + li : -1);
        }
    if (4 * window_.size() > static_cast<std::size_t>(gnx) * gny) return false;
    // The covered cells the window leaves out, solved by their diagonal.
    std::vector<char> in_window(static_cast<std::size_t>(nx) * ny, 0);
    for (int l : local_)
        if (l >= 0) in_window[static_cast<std::size_t>(l)] = 1;
    covered_.clear();
    for (int c : covered)
        if (!in_window[static_cast<std::size_t>(c)]) covered_.push_back({c, cut[5 * static_cast<std::size_t>(c)]});
    covered_rhs_.resize(covered_.size());

    // The window's rows of the cut matrix, neighbours outside it dropped (zero there).
    std::vector<double> owned(5 * window_.size(), 0.0);
    for (std::size_t k = 0; k < window_.size(); ++k)
        if (local_[k] >= 0)
            std::copy_n(cut.begin() + 5 * static_cast<std::size_t>(local_[k]), 5, owned.begin() + 5 * k);
    MPI_Allreduce(MPI_IN_PLACE, owned.data(), static_cast<int>(owned.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
    std::vector<Eigen::Triplet<double>> entries;
    ring_.clear();
    const int steps[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};  // west, east, south, north
    for (std::size_t k = 0; k < window_.size(); ++k) {
        const int ci = static_cast<int>(window_[k] % gnx), cj = static_cast<int>(window_[k] / gnx);
        entries.emplace_back(static_cast<int>(k), static_cast<int>(k), owned[5 * k]);
        for (int e = 0; e < 4; ++e) {
            const double a = owned[5 * k + 1 + e];
            if (a == 0.0) continue;
            int i = ci + steps[e][0], j = cj + steps[e][1];
            if (px) i = (i + gnx) % gnx;
            if (py) j = (j + gny) % gny;
            if (i < 0 || j < 0 || i >= gnx || j >= gny) continue;
            const int m = i < i0 || j < j0 || i > i1 || j > j1 ? -1 : index[at(i, j)];
            if (m >= 0) {
                entries.emplace_back(static_cast<int>(k), m, a);
            } else if (const int li = i - ox, lj = j - oy; li >= 0 && lj >= 0 && li < nx && lj < ny) {
                ring_.push_back({static_cast<int>(k), lj * nx + li, a});  // the matrix is symmetric
            }
        }
    }
    block_.resize(static_cast<Eigen::Index>(window_.size()), static_cast<Eigen::Index>(window_.size()));
    block_.setFromTriplets(entries.begin(), entries.end());
    factor_.compute(block_);
    return factor_.info() == Eigen::Success;
}

const std::vector<double>& CutPoissonPreconditioner::window_values(const std::vector<double>& owned) {
    std::vector<double>& values = window_buffer_;
    values.assign(window_.size(), 0.0);
    for (std::size_t k = 0; k < window_.size(); ++k)
        if (local_[k] >= 0) values[k] = owned[static_cast<std::size_t>(local_[k])];
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
    return values;
}

const Eigen::VectorXd& CutPoissonPreconditioner::window_solve(const Eigen::VectorXd& rw) {
    window_solution_ = factor_.solve(rw);
    return window_solution_;
}

void CutPoissonPreconditioner::add_window_correction(std::vector<double>& z) {
    // The window's rows of A z: the block's from z in the window, and the ring's, each rank adding those of its own
    // cells (the matrix is symmetric: a ring coupling is the window row's too); gathered in one reduction.
    const std::size_t n = window_.size();
    std::vector<double>& gathered = window_buffer_;
    gathered.assign(2 * n, 0.0);
    for (std::size_t k = 0; k < n; ++k)
        if (local_[k] >= 0) gathered[k] = z[static_cast<std::size_t>(local_[k])];
    for (const RingCoupling& c : ring_)
        gathered[n + static_cast<std::size_t>(c.window_cell)] += c.coefficient * z[static_cast<std::size_t>(c.cell)];
    MPI_Allreduce(MPI_IN_PLACE, gathered.data(), static_cast<int>(gathered.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
    const auto size = static_cast<Eigen::Index>(n);
    const Eigen::Map<const Eigen::VectorXd> zw(gathered.data(), size), ring(gathered.data() + n, size);
    window_residual_ = window_rhs_ - block_ * zw - ring;
    const Eigen::VectorXd& dz = window_solve(window_residual_);
    for (std::size_t k = 0; k < n; ++k)
        if (local_[k] >= 0) z[static_cast<std::size_t>(local_[k])] += dz[static_cast<Eigen::Index>(k)];
}

void CutPoissonPreconditioner::apply(HYPRE_StructVector b, HYPRE_StructVector x) {
    const int nx = grid_.nx(), ny = grid_.ny();
    std::vector<double>&rhs = rhs_, &z = z_, &r = r_;
    std::fill(z.begin(), z.end(), 0.0);
    HYPRE_StructVectorGetBoxValues(b, lower_.data(), upper_.data(), rhs.data());
    // The covered cells outside the window are coupled to nothing (A is block diagonal): set aside, solved last.
    for (std::size_t k = 0; k < covered_.size(); ++k) {
        const std::size_t c = static_cast<std::size_t>(covered_[k].cell);
        covered_rhs_[k] = rhs[c];
        rhs[c] = 0.0;
    }
    // The window's solve leaves no residual inside the window; outside, its cells' values reach the next cells only.
    const std::vector<double>& rhs_window = window_values(rhs);
    window_rhs_ = Eigen::Map<const Eigen::VectorXd>(rhs_window.data(), static_cast<Eigen::Index>(rhs_window.size()));
    const Eigen::VectorXd& zw = window_solve(window_rhs_);
    for (std::size_t k = 0; k < window_.size(); ++k)
        if (local_[k] >= 0) z[static_cast<std::size_t>(local_[k])] = zw[static_cast<Eigen::Index>(k)];
    r = rhs;
    for (std::size_t k = 0; k < window_.size(); ++k)
        if (local_[k] >= 0) r[static_cast<std::size_t>(local_[k])] = 0.0;
    for (const RingCoupling& c : ring_) r[static_cast<std::size_t>(c.cell)] -= c.coefficient * zw[c.window_cell];
    // The whole grid: L^-1 of the residual. The matrix is -V laplacian, so the direct solve's source is -r / V.
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const std::size_t c = static_cast<std::size_t>(j) * nx + i;
            source_(i, j) = -r[c] / volume_[c];
        }
    direct_.solve(source_, correction_);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) z[static_cast<std::size_t>(j) * nx + i] += correction_(i, j);
    for (const Covered& c : covered_) z[static_cast<std::size_t>(c.cell)] = 0.0;  // the whole grid's on the fluid only
    add_window_correction(z);
    for (std::size_t k = 0; k < covered_.size(); ++k)
        z[static_cast<std::size_t>(covered_[k].cell)] = covered_rhs_[k] / covered_[k].diagonal;
    HYPRE_StructVectorSetBoxValues(x, lower_.data(), upper_.data(), z.data());
    HYPRE_StructVectorAssemble(x);
}

}  // namespace chute
