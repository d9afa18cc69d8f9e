#pragma once
// Solid cells: axis-aligned blocks of cells taken out of the fluid, whose sides lie on grid lines: the hole of
// a body-fitted body (docs/design.md, carrier 2). A block moves rigidly (translation, as in the study) with
// its velocity U. The flow solver leaves its cells out of the pressure problem (no flux across its sides, so
// the projection keeps the sides' normal velocity: a Neumann condition) and fills its faces before every
// operator reads them, as BoundaryConditions fills the ghosts of the domain's walls:
//
//   a face on a side, normal to it            u_n = U_n (the wall moves with the block)
//   the two layers of normal faces inside     u_n = 2 U_n - u_n,fluid (odd mirror about the side's value,
//   a side                                    as a domain wall's ghost)
//   the two layers of tangential faces        u_t = U_t - (u_t,fluid - U_t) d_in / d_out, the fluid face
//   inside a side                             mirrored across the side line: the diffusion stencil of the
//                                             first fluid face sees u_t = U_t on the side (no slip), the
//                                             limiters a field without a jump
//   every other face inside                   U
//
// Corners take the value of the side whose normal face they are. Blocks must not touch each other (the carrier
// checks); a side may lie on the domain's boundary, where the faces are the boundary's and the block's mirrors
// only feed its own interior. A mirror that falls outside this patch's halo takes U (its owner fills it).
#include <array>
#include <vector>

#include "field.hpp"

namespace chute {

struct SolidBlock {
    std::array<int, 2> lower{}, upper{};  // global cell indices: the block is cells [lower, upper) in x and y
    std::array<double, 2> velocity{};     // of the block (m/s)
};

class SolidCells {
public:
    explicit SolidCells(const Grid& grid);

    void set(std::vector<SolidBlock> blocks);
    const std::vector<SolidBlock>& blocks() const { return blocks_; }
    // The velocity of block b (its cells stay the same: the grid moves with it).
    void set_velocity(std::size_t b, std::array<double, 2> velocity) { blocks_.at(b).velocity = velocity; }
    bool empty() const { return blocks_.empty(); }

    // 1 in fluid cells, 0 in solid ones (local indices, ghosts included).
    const Field2D& fluid() const { return fluid_; }
    bool solid(int i, int j) const { return fluid_(i, j) == 0.0; }
    long long fluid_cell_count() const { return fluid_count_; }  // over all ranks

    // The faces of every block on this patch, ghosts included (call after the halo exchange).
    void fill(Velocity& vel) const;
    // Whether block b spans the whole of `axis` (0: x, 1: y) and that axis is periodic: it has no sides along it
    // (a bed or a lid).
    bool spans_periodic(const SolidBlock& b, int axis) const;

    // How fill() sets face (gi, gj) of block b (global indices; component 0: the u face on x line gi in row gj,
    // 1: the v face in column gi on y line gj): not at all (outside the block), to U (fixed), to 2 U - u_m
    // (odd_mirror) or to U - (u_m - U) inner / outer (scaled_mirror), u_m the fluid face `mirror` and inner,
    // outer the distances of the two faces from the side. The implicit diffusion takes its boundary rows from it.
    struct HoleFace {
        enum class Kind { outside, fixed, odd_mirror, scaled_mirror } kind = Kind::outside;
        std::array<int, 2> mirror{};
        double inner = 0.0, outer = 0.0;
    };
    HoleFace hole_face(const SolidBlock& b, int component, int gi, int gj) const;

private:
    void fill_block(const SolidBlock& b, Velocity& vel) const;

    const Grid& grid_;
    std::vector<SolidBlock> blocks_;
    Field2D fluid_;
    long long fluid_count_ = 0;
};

}  // namespace chute
