#include "solid_cells.hpp"

#include <algorithm>
#include <cmath>

namespace chute {

SolidCells::SolidCells(const Grid& grid) : grid_(grid), fluid_(grid, 1.0) { fluid_count_ = grid.global_cells(); }

void SolidCells::set(std::vector<SolidBlock> blocks) {
    blocks_ = std::move(blocks);
    const int ox = grid_.lx().offset, oy = grid_.ly().offset;
    long long solid = 0;
    fluid_.fill(1.0);
    for (const SolidBlock& b : blocks_) {
        solid += 1LL * (b.upper[0] - b.lower[0]) * (b.upper[1] - b.lower[1]);
        for (int j = -kGhost; j < grid_.ny() + kGhost; ++j)
            for (int i = -kGhost; i < grid_.nx() + kGhost; ++i) {
                const int gi = i + ox, gj = j + oy;
                if (gi >= b.lower[0] && gi < b.upper[0] && gj >= b.lower[1] && gj < b.upper[1]) fluid_(i, j) = 0.0;
            }
    }
    fluid_count_ = grid_.global_cells() - solid;
}

void SolidCells::fill(Velocity& vel) const {
    for (const SolidBlock& b : blocks_) fill_block(b, vel);
}

bool SolidCells::spans_periodic(const SolidBlock& b, int axis) const {
    const Axis& a = axis == 0 ? grid_.x_axis() : grid_.y_axis();
    return a.periodic() && b.lower[axis] <= 0 && b.upper[axis] >= a.cells();
}

void SolidCells::fill_block(const SolidBlock& b, Velocity& vel) const {
    const int ox = grid_.lx().offset, oy = grid_.ly().offset;
    const int i_lo = -kGhost, i_hi = grid_.nx() + kGhost, j_lo = -kGhost, j_hi = grid_.ny() + kGhost;
    const Axis& X = grid_.x_axis();
    const Axis& Y = grid_.y_axis();
    const bool sides_x = !spans_periodic(b, 0), sides_y = !spans_periodic(b, 1);
    constexpr int far = 1 << 20;

    // One component c on the faces of the block: n_lo, n_hi are the lines of the sides c is normal to (its faces
    // lie on them), t_lo, t_hi those of the sides it is tangential to (its faces lie on the centres between).
    // gn counts c's lines along the normal axis, gt the centres along the other (global indices).
    auto fill_component = [&](Field2D& c, double U, bool normal_is_x, bool has_normal_sides,
                              bool has_tangential_sides) {
        const Axis& T = normal_is_x ? Y : X;
        const int n_lo = b.lower[normal_is_x ? 0 : 1], n_hi = b.upper[normal_is_x ? 0 : 1];
        const int t_lo = b.lower[normal_is_x ? 1 : 0], t_hi = b.upper[normal_is_x ? 1 : 0];
        for (int j = j_lo; j < j_hi; ++j)
            for (int i = i_lo; i < i_hi; ++i) {
                const int gn = (normal_is_x ? i + ox : j + oy), gt = (normal_is_x ? j + oy : i + ox);
                if ((has_normal_sides && (gn < n_lo || gn > n_hi)) ||
                    (has_tangential_sides && (gt < t_lo || gt >= t_hi)))
                    continue;
                // Depth in cells from the nearest side of each kind: on a normal side 0; the first tangential
                // face inside is half a cell in.
                const int dn = has_normal_sides ? std::min(gn - n_lo, n_hi - gn) : far;
                const double dt = has_tangential_sides ? std::min(gt - t_lo, t_hi - 1 - gt) + 0.5 : far;
                auto at = [&](int gn_m, int gt_m) -> const double* {
                    const int il = (normal_is_x ? gn_m : gt_m) - ox, jl = (normal_is_x ? gt_m : gn_m) - oy;
                    if (il < i_lo || il >= i_hi || jl < j_lo || jl >= j_hi) return nullptr;
                    return &c(il, jl);
                };
                double value = U;  // deep inside: the block's velocity
                if (dn == 0) {
                    value = U;  // the side moves with the block (whatever the tangential depth)
                } else if (dn <= kGhost && dn < dt) {
                    // Normal component beyond a side: odd mirror about the side's value, as a domain wall's ghost.
                    const int gm = gn - n_lo <= n_hi - gn ? n_lo - dn : n_hi + dn;
                    if (const double* m = at(gm, gt)) value = 2.0 * U - *m;
                } else if (dt < kGhost) {
                    // Tangential component: the fluid face as far outside, mirrored through U on the side line.
                    const bool low = gt - t_lo <= t_hi - 1 - gt;
                    const int line = low ? t_lo : t_hi;
                    const int gm = low ? t_lo - 1 - (gt - t_lo) : t_hi + (t_hi - 1 - gt);
                    if (const double* m = at(gn, gm)) {
                        const double wall = T.line(line);
                        value = U - (*m - U) * std::abs(T.centre(gt) - wall) / std::abs(T.centre(gm) - wall);
                    }
                }
                c(i, j) = value;
            }
    };
    fill_component(vel.u, b.velocity[0], true, sides_x, sides_y);
    fill_component(vel.v, b.velocity[1], false, sides_y, sides_x);
}

}  // namespace chute
