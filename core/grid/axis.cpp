#include "axis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace chute {

Axis::Axis(std::vector<double> lines, bool periodic) : periodic_(periodic) { set_lines(std::move(lines)); }

bool uniform_axis(const Axis& axis) {
    const double h = axis.length() / axis.cells();
    for (int k = 0; k < axis.cells(); ++k)
        if (std::abs(axis.width(k) - h) > 1e-10 * h) return false;
    return true;
}

void Axis::set_lines(std::vector<double> lines) {
    if (lines.size() < 2) throw std::invalid_argument("an axis needs at least one cell");
    for (std::size_t k = 1; k < lines.size(); ++k)
        if (!(lines[k] > lines[k - 1])) throw std::invalid_argument("grid lines must increase strictly");
    lines_ = std::move(lines);
}

double Axis::line(int k) const {
    const int n = cells();
    if (k >= 0 && k <= n) return lines_[k];
    if (periodic_) {
        const int wraps = (k < 0) ? -((-k + n - 1) / n) : k / n;
        return lines_[k - wraps * n] + wraps * length();
    }
    if (k < 0) return 2.0 * lines_[0] - lines_[-k];
    return 2.0 * lines_[n] - lines_[2 * n - k];
}

std::vector<double> uniform_lines(double start, double end, int cells) {
    std::vector<double> x(cells + 1);
    for (int k = 0; k <= cells; ++k) x[k] = start + (end - start) * k / cells;
    x[cells] = end;
    return x;
}

std::vector<double> tanh_lines(double start, double end, int cells, double beta) {
    std::vector<double> x(cells + 1);
    for (int k = 0; k <= cells; ++k) {
        const double s = 2.0 * k / cells - 1.0;  // in [-1, 1]
        x[k] = start + (end - start) * 0.5 * (1.0 + std::tanh(beta * s) / std::tanh(beta));
    }
    x[0] = start;
    x[cells] = end;
    return x;
}

std::vector<double> geometric_lines(double start, double end, int cells, double ratio) {
    if (std::abs(ratio - 1.0) < 1e-12) return uniform_lines(start, end, cells);
    const double first = (end - start) * (ratio - 1.0) / (std::pow(ratio, cells) - 1.0);
    std::vector<double> x(cells + 1);
    x[0] = start;
    double width = first;
    for (int k = 1; k <= cells; ++k, width *= ratio) x[k] = x[k - 1] + width;
    x[cells] = end;
    return x;
}

namespace {
// Widths growing by `ratio` from h * ratio (at most max_width, if > 0) until they span `length`, then scaled to
// span it exactly.
std::vector<double> growing_widths(double length, double h, double ratio, double max_width) {
    std::vector<double> w;
    double sum = 0.0;
    for (double width = h * ratio; sum < length * (1.0 - 1e-12); width *= ratio) {
        if (max_width > 0.0) width = std::min(width, max_width);
        w.push_back(width);
        sum += width;
    }
    // Drop a last sliver cell rather than squeeze the others.
    if (w.size() > 1 && sum - length > 0.5 * w.back()) {
        sum -= w.back();
        w.pop_back();
    }
    for (double& x : w) x *= length / sum;
    return w;
}

// Widths first r^min(k, n-1-k), k = 0..n-1: the window's clustered cells.
double window_sum(int n, double first, double r) {
    double sum = 0.0;
    for (int k = 0; k < n; ++k) sum += first * std::pow(r, std::min(k, n - 1 - k));
    return sum;
}
}  // namespace

double window_ratio(double length, int cells, double first) {
    if (!(cells * first < length))
        throw std::invalid_argument("cells of width " + std::to_string(first) + " at the window's ends cannot be " +
                                    "clustered: " + std::to_string(cells) + " of them already span " +
                                    std::to_string(cells * first) + " >= the window's " + std::to_string(length));
    double lo = 1.0, hi = 2.0;
    while (window_sum(cells, first, hi) < length) hi *= 2.0;
    for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        (window_sum(cells, first, mid) < length ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

std::vector<double> clustered_lines(double start, double end, double core_start, double core_end, int core_cells,
                                    double ratio, double first, double max_width) {
    const double length = core_end - core_start;
    std::vector<double> window(core_cells, length / core_cells);
    if (first > 0.0) {
        const double r = window_ratio(length, core_cells, first);
        for (int k = 0; k < core_cells; ++k) window[k] = first * std::pow(r, std::min(k, core_cells - 1 - k));
    }
    const double h = first > 0.0 ? first : length / core_cells;  // the window's outermost cells
    std::vector<double> x;
    const auto below =
        core_start > start ? growing_widths(core_start - start, h, ratio, max_width) : std::vector<double>{};
    const auto above = end > core_end ? growing_widths(end - core_end, h, ratio, max_width) : std::vector<double>{};
    double pos = start;
    x.push_back(pos);
    for (auto it = below.rbegin(); it != below.rend(); ++it) x.push_back(pos += *it);
    x.back() = core_start;
    if (first > 0.0) {
        for (int k = 0; k < core_cells; ++k) x.push_back(x.back() + window[k]);
    } else {
        for (int k = 1; k <= core_cells; ++k) x.push_back(core_start + h * k);
    }
    x.back() = core_end;
    pos = core_end;
    for (double w : above) x.push_back(pos += w);
    x.back() = end;
    return x;
}

double clustered_cell_count(double start, double end, double core_start, double core_end, int core_cells, double ratio,
                            double first, double max_width) {
    const double h = first > 0.0 ? first : (core_end - core_start) / core_cells;
    // Widths h r, h r^2, ..., h r^n span L when h r (r^n - 1) / (r - 1) >= L: n = log(1 + L (r - 1) / (h r)) / log r.
    const auto grow = [&](double length) {
        if (!(length > 0.0)) return 0.0;
        if (ratio - 1.0 < 1e-12) return std::ceil(length / h);
        return std::ceil(std::log1p(length * (ratio - 1.0) / (h * ratio)) / std::log(ratio));
    };
    const auto side = [&](double length) {
        if (!(max_width > h) || ratio - 1.0 < 1e-12) return grow(length);
        // Up to the cap, then cells of max_width.
        const double n = std::ceil(std::log(max_width / h) / std::log(ratio));
        const double spanned = h * ratio * (std::pow(ratio, n) - 1.0) / (ratio - 1.0);
        return spanned >= length ? grow(length) : n + std::ceil((length - spanned) / max_width);
    };
    return core_cells + side(core_start - start) + side(end - core_end);
}

NearestLine nearest_line(const Axis& axis, double x) {
    const auto& L = axis.lines();
    const auto it = std::lower_bound(L.begin(), L.end(), x);
    const int above =
        static_cast<int>(std::min<std::ptrdiff_t>(it - L.begin(), static_cast<std::ptrdiff_t>(L.size()) - 1));
    const int below = std::max(above - 1, 0);
    const int k = std::abs(L[above] - x) < std::abs(L[below] - x) ? above : below;
    const double cell = std::min(axis.width(std::min(k, axis.cells() - 1)), axis.width(std::max(k - 1, 0)));
    return {below, above, k, std::abs(L[k] - x) / cell};
}

}  // namespace chute
