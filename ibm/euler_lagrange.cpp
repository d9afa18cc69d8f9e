#include "euler_lagrange.hpp"

#include <mpi.h>

#include <algorithm>

namespace chute {

namespace {

// Index of the cell whose lines bracket x (-1 below the first line, cells() at or beyond the last).
int cell_below(const Axis& axis, double x) {
    const auto& L = axis.lines();
    return static_cast<int>(std::upper_bound(L.begin(), L.end(), x) - L.begin()) - 1;
}

// Positions of one staggering along one axis: grid lines (face direction) or cell centres.
struct AxisPoints {
    const Axis& axis;
    bool on_lines;      // positions are lines (k = 0..N) rather than centres (k = 0..N-1)
    int first, last;    // global indices that carry an unknown the forcing may touch
    int offset, owned;  // this rank's first global index and owned count (local index = k - offset)

    double position(int k) const { return on_lines ? axis.line(k) : axis.centre(k); }
    // Global index of the point at or below x (may be outside [first, last]).
    int below(double x) const {
        const int cell = cell_below(axis, x);
        if (on_lines) return cell;
        return x >= axis.centre(cell) ? cell : cell - 1;
    }
    // Wrap into the stored range for a periodic axis; -1 if k is not an unknown.
    int unknown(int k) const {
        if (axis.periodic()) {
            const int n = axis.cells();
            return ((k % n) + n) % n;
        }
        return k >= first && k <= last ? k : -1;
    }
    bool is_owned(int k) const { return k >= offset && k < offset + owned; }
    // Width of the control volume around point k.
    double volume_width(int k) const { return on_lines ? axis.centre(k) - axis.centre(k - 1) : axis.width(k); }
};

AxisPoints axis_points(const Grid& grid, Staggering s, int dir) {
    const Axis& axis = dir == 0 ? grid.x_axis() : grid.y_axis();
    const LocalAxis& local = dir == 0 ? grid.lx() : grid.ly();
    const bool on_lines = (s == Staggering::u_face && dir == 0) || (s == Staggering::v_face && dir == 1);
    const int n = axis.cells();
    // Faces on the domain boundary are set by boundary conditions: not unknowns.
    return {axis, on_lines, on_lines ? 1 : 0, n - 1, local.offset, local.n};
}

Stencil build(const AxisPoints& ax, const AxisPoints& ay, const std::vector<std::pair<int, double>>& wx,
              const std::vector<std::pair<int, double>>& wy) {
    Stencil st;
    double total = 0.0;
    for (const auto& [ky, fy] : wy)
        for (const auto& [kx, fx] : wx) {
            const int gx = ax.unknown(kx), gy = ay.unknown(ky);
            if (gx < 0 || gy < 0) continue;
            const double w = fx * fy;
            total += w;
            if (w > 0.0 && ax.is_owned(gx) && ay.is_owned(gy))
                st.push_back({gx - ax.offset, gy - ay.offset, w, 1.0 / (ax.volume_width(kx) * ay.volume_width(ky))});
        }
    if (total > 0.0)
        for (auto& p : st) p.weight /= total;
    return st;
}

}  // namespace

Vec2 local_spacing(const Grid& grid, const Vec2& X) {
    auto width = [](const Axis& a, double x) { return a.width(std::clamp(cell_below(a, x), 0, a.cells() - 1)); };
    return {width(grid.x_axis(), X.x()), width(grid.y_axis(), X.y())};
}

std::vector<Stencil> delta_stencils(const Grid& grid, DeltaKernel kernel, Staggering s,
                                    const std::vector<Vec2>& points) {
    const AxisPoints ax = axis_points(grid, s, 0), ay = axis_points(grid, s, 1);
    const double support = kernel_support(kernel);
    const int reach = static_cast<int>(std::ceil(support)) + 1;
    std::vector<Stencil> out;
    out.reserve(points.size());
    std::vector<std::pair<int, double>> wx, wy;
    for (const Vec2& X : points) {
        const Vec2 h = local_spacing(grid, X);
        auto weights = [&](const AxisPoints& a, double x, double hh, std::vector<std::pair<int, double>>& w) {
            w.clear();
            const int k0 = a.below(x);
            for (int k = k0 - reach; k <= k0 + reach; ++k) {
                const double phi = delta_kernel(kernel, (a.position(k) - x) / hh);
                if (phi > 0.0) w.emplace_back(k, phi);
            }
        };
        weights(ax, X.x(), h.x(), wx);
        weights(ay, X.y(), h.y(), wy);
        out.push_back(build(ax, ay, wx, wy));
    }
    return out;
}

std::vector<Stencil> bilinear_stencils(const Grid& grid, Staggering s, const std::vector<Vec2>& points) {
    const AxisPoints ax = axis_points(grid, s, 0), ay = axis_points(grid, s, 1);
    std::vector<Stencil> out;
    out.reserve(points.size());
    auto weights = [](const AxisPoints& a, double x) {
        int k = a.below(x);
        if (!a.axis.periodic()) k = std::clamp(k, a.first, a.last - 1);  // clamp: extrapolate at the edges
        const double f = std::clamp((x - a.position(k)) / (a.position(k + 1) - a.position(k)), 0.0, 1.0);
        return std::vector<std::pair<int, double>>{{k, 1.0 - f}, {k + 1, f}};
    };
    for (const Vec2& X : points) out.push_back(build(ax, ay, weights(ax, X.x()), weights(ay, X.y())));
    return out;
}

std::vector<double> interpolate(const Grid& grid, const std::vector<Stencil>& stencils, const Field2D& f) {
    std::vector<double> values(stencils.size(), 0.0);
    for (std::size_t l = 0; l < stencils.size(); ++l)
        for (const auto& p : stencils[l]) values[l] += p.weight * f(p.i, p.j);
    if (grid.size() > 1)
        MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, grid.comm());
    return values;
}

std::vector<Vec2> interpolate_velocity(const Grid& grid, const std::vector<Stencil>& su, const std::vector<Stencil>& sv,
                                       const Velocity& vel) {
    const std::size_t n = su.size();
    std::vector<double> sums(2 * n, 0.0);
    for (std::size_t l = 0; l < n; ++l) {
        for (const auto& p : su[l]) sums[2 * l] += p.weight * vel.u(p.i, p.j);
        for (const auto& p : sv[l]) sums[2 * l + 1] += p.weight * vel.v(p.i, p.j);
    }
    if (grid.size() > 1)
        MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM, grid.comm());
    std::vector<Vec2> out(n);
    for (std::size_t l = 0; l < n; ++l) out[l] = {sums[2 * l], sums[2 * l + 1]};
    return out;
}

void spread(const std::vector<Stencil>& stencils, const std::vector<double>& amounts, Field2D& f) {
    for (std::size_t l = 0; l < stencils.size(); ++l)
        for (const auto& p : stencils[l]) f(p.i, p.j) += amounts[l] * p.weight * p.inv_volume;
}

}  // namespace chute
