#pragma once
// The mesh modifiers of a body-fitted block along one axis (Turmel & Locat 2008, sec. 3.3 and Fig. 1: the
// layers of cells that absorb the block's motion; OpenFOAM's layerAdditionRemoval): the lines around the block
// form a rigid zone that moves with it, the lines beyond are fixed (the domain's boundaries and walls stay put),
// and the one cell between the rigid zone and the fixed lines on each side (the modifier layer) stretches or
// shrinks with the motion.
//
//     fixed lines ... | lower modifier | rigid zone (the block, its clustered window) | upper modifier | ... fixed
//
// When the shrinking modifier is thinner than a third of the fixed cell beyond it (it shrinks: the block moves
// towards it), it merges with that cell (a line removed), and the growing one on the other side gets a line as far
// from its fixed line as the merged cell was wide (a line added; halfway if it is not thick enough): a layer moves
// from ahead of the block to behind it, and the cell count stays the same (no redistribution over the ranks, no
// new hypre grid). At most one change per step and axis; with far-field cells of width H the modifiers stay
// between H / 3 and 5 H / 3 and a block that turns back does not trigger the reverse change at once (a hysteresis
// of H / 3). The rigid zone is never remapped (its cells are only renumbered); the two modifiers are
// (core/grid/remap.hpp).
//
// At a domain's end (a bed, a lid), with no fixed cell left beyond the modifier, the modifier merges with the zone's
// outermost cell instead: the zone compresses towards the wall, down to the block's own side, where the modifier is
// the gap between the wall and the block. The gap then closes by stretching; contact of a body_fitted body is not
// built yet, and a block that reaches the wall stops the run with an error naming the key.
//
// The rigid zone is the block's window and its growth up to the far-field width: the lines from the innermost
// cell of width H (to 1e-9) on each side, H the width of the outermost cell on that side (`domain.<axis>.max`
// with spacing clustered gives such a grid); the modifier is the next cell out.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace chute {

class AxisLayers {
public:
    // `lines` of the axis, the block's centre on it, and the block's cells [hole_lower, hole_upper).
    // std::invalid_argument naming `key` when the grid has no fixed cells on a side.
    AxisLayers(const std::vector<double>& lines, double centre, int hole_lower, int hole_upper, const std::string& key);

    int first() const { return first_; }  // the rigid zone's lines [first, last] (global indices)
    int last() const { return last_; }
    // The block's cells [hole_lower, hole_upper) now (the rigid zone carries them, renumbered by the changes).
    int hole_lower() const { return first_ + hole_lower_; }
    int hole_upper() const { return first_ + hole_upper_; }
    // The lines with the rigid zone centred on `centre` (the modifiers stretched). RunFailure when a modifier
    // would vanish (the block moved more than a layer in one step).
    std::vector<double> stretched(const std::vector<double>& lines, double centre) const;
    // The lines after a layer moved from ahead of the block to behind it, when the shrinking modifier is under its
    // threshold (`velocity`: the block's along the axis, whose sign says which one shrinks); nullopt otherwise.
    // The rigid zone's indices follow (first(), last()). RunFailure when there is no fixed line left to remove
    // (the moving zone reached the domain's end).
    std::optional<std::vector<double>> change(const std::vector<double>& lines, double velocity);
    // Find the rigid zone again in `lines` (a restart): the lines that sit at the zone's offsets from `centre`
    // (to a quarter of the smallest cell: the lines are where the step was projected, a fraction of a step's travel
    // from the body's final place).
    void locate(const std::vector<double>& lines, double centre);
    // Where the pressure solver's multigrid hierarchy is set up for a zone centred on `centre` (a preconditioner of the
    // nearby matrices; a restart finds the same place): the centre rounded to the far-field width (a quarter of it once
    // the zone compresses against a wall), or to the next place over when the rounding would close a thin modifier
    // (near a wall the modifier is the gap, down to a third of the zone's finest cell); the centre itself if neither
    // keeps both open.
    double hierarchy_centre(const std::vector<double>& lines, double centre) const;
    int changes() const { return changes_; }
    // The zone's lines removed so far at its lower and upper end (it compresses towards a wall), and the same removal
    // again on a zone built from the case (a restart).
    std::array<int, 2> trimmed() const { return trimmed_; }
    void trim(int below, int above);
    double far_width() const { return below_ < above_ ? below_ : above_; }  // the far-field cells' (the smaller side)

private:
    std::vector<double> offsets_;          // of the rigid zone's lines from the block's centre
    int first_ = 0, last_ = 0;             // the rigid zone's lines
    int hole_lower_ = 0, hole_upper_ = 0;  // the block's cells, from first_
    double below_ = 0.0, above_ = 0.0;     // the fixed cells' width H on each side
    std::string key_;
    int changes_ = 0;
    std::array<int, 2> trimmed_{};
};

}  // namespace chute
