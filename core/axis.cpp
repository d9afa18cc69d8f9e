#include "axis.hpp"

#include <cmath>
#include <stdexcept>

namespace chute {

Axis::Axis(std::vector<double> lines, bool periodic) : periodic_(periodic) { set_lines(std::move(lines)); }

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

}  // namespace chute
