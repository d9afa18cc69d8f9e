#pragma once
// What a carrier computes from where a body lies on the grid's lines (cut faces, markers, wall cells, surface
// probes), kept while it holds: a moving body needs it every time, a static one once, and again whenever the lines
// moved under it (a window that follows another body, run/following_frame.hpp; Grid::lines_version).
#include "grid.hpp"

namespace chute {

class GridPlacement {
public:
    explicit GridPlacement(const Grid& grid) : grid_(&grid) {}
    // True when it must be computed (again): never computed, `moves` (the body moves), or the lines moved since.
    bool stale(bool moves) const { return moves || lines_ != grid_->lines_version(); }
    // The lines moved since the last computation (or there was none).
    bool lines_moved() const { return lines_ != grid_->lines_version(); }
    void computed() { lines_ = grid_->lines_version(); }

private:
    const Grid* grid_;
    long long lines_ = -1;  // Grid::lines_version() at the last computation (-1: none; versions start at 0)
};

}  // namespace chute
