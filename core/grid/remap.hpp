#pragma once
// Conservative remap of a field after the lines of one axis changed (a modifier layer added or removed: band/
// layers.hpp; same line count). Each owned value becomes the mean, over its new control volume along the axis,
// of the old field taken constant on the old control volumes: the integral over any union of control volumes
// whose ends did not move is kept to round-off (mass, momentum, k, epsilon), and a value whose control volume
// did not change (the rigid zone, only renumbered) is copied bit for bit. The other axis is untouched (its lines
// did not change), so the columns are remapped one by one.
//
// Control volumes along the axis: cells (line k to line k+1) for a field centred along it, and for a field on
// the axis's lines (u for x, v for y, a corner field for either) the span from the centre of cell k-1 to that of
// cell k (the staggered grid's momentum cells). Faces on the domain's boundaries keep their values.
#include <vector>

#include "field.hpp"

namespace chute {

// `f` holds the old values with its halo exchanged (its ghosts are read); the grid already has the new lines.
// Only control volumes that changed, and at most kGhost old ones away, are read: a change of one line each
// side renumbers by one. std::logic_error otherwise.
void remap_along_axis(const Grid& grid, int axis, const std::vector<double>& old_lines, bool on_lines, Field2D& f);

}  // namespace chute
