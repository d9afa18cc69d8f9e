#include "grid_motion.hpp"

#include "grid.hpp"

namespace chute {

namespace {

// The velocity of local line k of a patch: the global line's, a periodic axis's ghost lines wrapped around.
double local_line_velocity(const Axis& axis, const LocalAxis& local, const AxisMotion& m, int k) {
    int line = local.offset + k;
    if (axis.periodic()) {
        const int n = axis.cells();
        line = ((line % n) + n) % n;
    }
    return m.at(line);
}

}  // namespace

LineVelocities::LineVelocities(const Grid& grid, const GridMotion& motion) : offset_(kGhost) {
    const auto fill = [&](const Axis& axis, const LocalAxis& local, const AxisMotion& m, std::vector<double>& out) {
        out.resize(local.n + 2 * kGhost + 1);
        for (int k = -kGhost; k <= local.n + kGhost; ++k) out[k + kGhost] = local_line_velocity(axis, local, m, k);
    };
    fill(grid.x_axis(), grid.lx(), motion.axis[0], x_);
    fill(grid.y_axis(), grid.ly(), motion.axis[1], y_);
    bool any = false;
    for (const auto* v : {&x_, &y_})
        for (double w : *v) any = any || w != 0.0;
    zero_ = !any;
    // Stretching anywhere on the grid, not only on this patch: the flags steer collective work alike on all ranks.
    const auto moves_part = [](const Axis& axis, const AxisMotion& m) {
        return m.velocity != 0.0 && m.last >= m.first && (m.first > 0 || m.last < axis.cells());
    };
    stretching_ = moves_part(grid.x_axis(), motion.axis[0]) || moves_part(grid.y_axis(), motion.axis[1]);
}

}  // namespace chute
