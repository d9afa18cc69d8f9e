#include "remap.hpp"

#include <algorithm>
#include <stdexcept>

namespace chute {

namespace {

// The ends of control volume k along an axis (global index), for cells or for the axis's lines.
struct Span {
    double a, b;
};
Span span(const Axis& axis, int k, bool on_lines) {
    return on_lines ? Span{axis.centre(k - 1), axis.centre(k)} : Span{axis.line(k), axis.line(k + 1)};
}

}  // namespace

void remap_along_axis(const Grid& grid, int axis, const std::vector<double>& old_lines, bool on_lines, Field2D& f) {
    const Axis& now = axis == 0 ? grid.x_axis() : grid.y_axis();
    const Axis before(old_lines, now.periodic());
    const LocalAxis& local = axis == 0 ? grid.lx() : grid.ly();
    const int n_along = local.n, n_across = axis == 0 ? grid.ny() : grid.nx();
    const int cells = now.cells();
    Field2D old = f;
    auto at = [&](Field2D& g, int along, int across) -> double& {
        return axis == 0 ? g(along, across) : g(across, along);
    };
    for (int k = 0; k < n_along; ++k) {
        const int g = local.offset + k;
        if (on_lines && !now.periodic() && (g == 0 || g == cells)) continue;  // a boundary face
        const Span s = span(now, g, on_lines);
        const Span o = span(before, g, on_lines);
        if (s.a == o.a && s.b == o.b) continue;  // unchanged
        // Renumbered only (the rigid zone): the same control volume one or two indices away.
        int same = 0;
        for (int d = -kGhost; d <= kGhost && !same; ++d) {
            const Span c = span(before, g + d, on_lines);
            if (d != 0 && c.a == s.a && c.b == s.b) same = d;
        }
        if (same) {
            for (int m = 0; m < n_across; ++m) at(f, k, m) = at(old, k + same, m);
            continue;
        }
        // Overlap with the old control volumes around it.
        double weights[2 * kGhost + 1] = {};
        double covered = 0.0;
        for (int d = -kGhost; d <= kGhost; ++d) {
            const Span c = span(before, g + d, on_lines);
            const double overlap = std::min(c.b, s.b) - std::max(c.a, s.a);
            if (overlap > 0.0) {
                weights[d + kGhost] = overlap;
                covered += overlap;
            }
        }
        if (!(covered > (1.0 - 1e-9) * (s.b - s.a)))
            throw std::logic_error("remap_along_axis: the new control volume " + std::to_string(g) +
                                   " is not covered by the old ones within " + std::to_string(kGhost) +
                                   " of it (more than one line changed on a side?)");
        const double inv = 1.0 / covered;
        for (int m = 0; m < n_across; ++m) {
            double sum = 0.0;
            for (int d = -kGhost; d <= kGhost; ++d)
                if (weights[d + kGhost] > 0.0) sum += weights[d + kGhost] * at(old, k + d, m);
            at(f, k, m) = sum * inv;
        }
    }
}

}  // namespace chute
