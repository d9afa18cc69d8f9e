#pragma once
// A body-fitted body's hole: the block of cells its rectangle covers, found from the grid lines its sides lie
// on. The study's block is an unrotated rectangle (translation only, Turmel & Locat sec. 3.3).
#include <string>
#include <vector>

#include "body.hpp"
#include "solid_cells.hpp"

namespace chute {

// The cells of `body` as a solid block, with its velocity. std::invalid_argument naming the body when it is
// not an unrotated rectangle, or a side is not on a grid line (to 1e-6 of the cell there). A side may lie on the
// domain's boundary (a bed block on the bottom wall, or across a periodic direction).
SolidBlock hole_of(const Body& body, const Grid& grid);

// An owned fluid cell beside a side of a hole: the wall-adjacent cell of a body-fitted mesh, where the side's
// stress is taken (hole_stress) and the log law applies (BodyFitted::sample_walls).
struct SideCell {
    int i = 0, j = 0;            // local indices
    Vec2 normal = Vec2::Zero();  // out of the hole
    Vec2 middle = Vec2::Zero();  // of the side's segment beside the cell
    double distance = 0.0;       // of the cell's centre from the side: half the cell
    double length = 0.0;         // of the segment
    Vec2 slip = Vec2::Zero();    // the fluid's velocity along the side (its two tangential faces' mean) less the hole's
};

// The side cells of `hole` this rank owns: bottom and top sides, then left and right.
std::vector<SideCell> side_cells(const Grid& grid, const SolidBlock& hole, const Velocity& vel);

}  // namespace chute
