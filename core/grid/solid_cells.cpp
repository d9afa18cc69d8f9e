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

SolidCells::HoleFace SolidCells::hole_face(const SolidBlock& b, int component, int gi, int gj) const {
    const bool normal_is_x = component == 0;
    const bool sides_x = !spans_periodic(b, 0), sides_y = !spans_periodic(b, 1);
    const bool has_normal_sides = normal_is_x ? sides_x : sides_y,
               has_tangential_sides = normal_is_x ? sides_y : sides_x;
    constexpr int far = 1 << 20;
    // n_lo, n_hi are the lines of the sides the component is normal to (its faces lie on them), t_lo, t_hi those
    // of the sides it is tangential to (its faces lie on the centres between); gn counts the component's lines
    // along the normal axis, gt the centres along the other.
    const int n_lo = b.lower[normal_is_x ? 0 : 1], n_hi = b.upper[normal_is_x ? 0 : 1];
    const int t_lo = b.lower[normal_is_x ? 1 : 0], t_hi = b.upper[normal_is_x ? 1 : 0];
    const int gn = normal_is_x ? gi : gj, gt = normal_is_x ? gj : gi;
    HoleFace f;
    if ((has_normal_sides && (gn < n_lo || gn > n_hi)) || (has_tangential_sides && (gt < t_lo || gt >= t_hi))) return f;
    auto face = [&](int gn_m, int gt_m) {
        return normal_is_x ? std::array<int, 2>{gn_m, gt_m} : std::array<int, 2>{gt_m, gn_m};
    };
    // Depth in cells from the nearest side of each kind: on a normal side 0; the first tangential face inside is
    // half a cell in.
    const int dn = has_normal_sides ? std::min(gn - n_lo, n_hi - gn) : far;
    const double dt = has_tangential_sides ? std::min(gt - t_lo, t_hi - 1 - gt) + 0.5 : far;
    f.kind = HoleFace::Kind::fixed;  // on a normal side (whatever the tangential depth), or deep inside
    if (dn == 0) return f;
    if (dn <= kGhost && dn < dt) {
        // Normal component beyond a side: odd mirror about the side's value, as a domain wall's ghost.
        f.kind = HoleFace::Kind::odd_mirror;
        f.mirror = face(gn - n_lo <= n_hi - gn ? n_lo - dn : n_hi + dn, gt);
    } else if (dt < kGhost) {
        // Tangential component: the fluid face as far outside, mirrored through U on the side line.
        const Axis& T = normal_is_x ? grid_.y_axis() : grid_.x_axis();
        const bool low = gt - t_lo <= t_hi - 1 - gt;
        const int line = low ? t_lo : t_hi;
        const int gm = low ? t_lo - 1 - (gt - t_lo) : t_hi + (t_hi - 1 - gt);
        const double wall = T.line(line);
        f.kind = HoleFace::Kind::scaled_mirror;
        f.mirror = face(gn, gm);
        f.inner = std::abs(T.centre(gt) - wall);
        f.outer = std::abs(T.centre(gm) - wall);
    }
    return f;
}

void SolidCells::fill_block(const SolidBlock& b, Velocity& vel) const {
    const int ox = grid_.lx().offset, oy = grid_.ly().offset;
    const int i_lo = -kGhost, i_hi = grid_.nx() + kGhost, j_lo = -kGhost, j_hi = grid_.ny() + kGhost;
    for (int component = 0; component < 2; ++component) {
        Field2D& c = component == 0 ? vel.u : vel.v;
        const double U = b.velocity[component];
        for (int j = j_lo; j < j_hi; ++j)
            for (int i = i_lo; i < i_hi; ++i) {
                const HoleFace f = hole_face(b, component, i + ox, j + oy);
                if (f.kind == HoleFace::Kind::outside) continue;
                double value = U;
                const int il = f.mirror[0] - ox, jl = f.mirror[1] - oy;
                // A mirror that falls outside this patch's halo takes U (its owner fills it).
                const bool reachable = il >= i_lo && il < i_hi && jl >= j_lo && jl < j_hi;
                if (f.kind == HoleFace::Kind::odd_mirror && reachable)
                    value = 2.0 * U - c(il, jl);
                else if (f.kind == HoleFace::Kind::scaled_mirror && reachable)
                    value = U - (c(il, jl) - U) * f.inner / f.outer;
                c(i, j) = value;
            }
    }
}

}  // namespace chute
