#pragma once
// A body-fitted body's hole: the block of cells its rectangle covers, found from the grid lines its sides lie
// on. The study's block is an unrotated rectangle (translation only, Turmel & Locat sec. 3.3).
#include <string>

#include "body.hpp"
#include "solid_cells.hpp"

namespace chute {

// The cells of `body` as a solid block, with its velocity. std::invalid_argument naming the body when it is
// not an unrotated rectangle, or a side is not on a grid line (to 1e-6 of the cell there). A side may lie on the
// domain's boundary (a bed block on the bottom wall, or across a periodic direction).
SolidBlock hole_of(const Body& body, const Grid& grid);

}  // namespace chute
