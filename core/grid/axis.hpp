#pragma once
// One coordinate direction of the rectilinear grid: the positions of its grid lines.
//
// Line coordinates are data: they may be uniform, stretched, or edited while a run goes on (the
// body-fitted band moves and inserts lines). Everything derived from them (centres, widths) is computed
// from the lines on demand or by Grid::update_geometry(), never assumed constant.
#include <vector>

namespace chute {

class Axis {
public:
    Axis() = default;
    Axis(std::vector<double> lines, bool periodic);

    int cells() const { return static_cast<int>(lines_.size()) - 1; }
    bool periodic() const { return periodic_; }
    double start() const { return lines_.front(); }
    double end() const { return lines_.back(); }
    double length() const { return end() - start(); }
    const std::vector<double>& lines() const { return lines_; }

    // Line k for any k, also outside [0, cells]: beyond a boundary the lines are the mirror images of the
    // interior ones (so a ghost cell mirrors its interior partner and the wall lies midway between their
    // centres), or the periodic images.
    double line(int k) const;
    double centre(int k) const { return 0.5 * (line(k) + line(k + 1)); }
    double width(int k) const { return line(k + 1) - line(k); }

    void set_lines(std::vector<double> lines);

private:
    std::vector<double> lines_;
    bool periodic_ = false;
};

// Where a coordinate x lies among an axis's lines: the lines bracketing it (`below`, `above`, clamped to the axis),
// the nearer of the two, and x's distance from that one in cells (of the narrower cell beside it). A body's side
// "on a grid line" is one within 1e-6 of a cell (band/hole.cpp; run/plausibility.cpp).
struct NearestLine {
    int below, above, index;
    double cells;
};
NearestLine nearest_line(const Axis& axis, double x);

// All cells of the axis equally wide (to 1e-10 relative): a transform can run along it (core/solvers/direct_poisson),
// a window can move along it by whole cells (run/following_frame).
bool uniform_axis(const Axis& axis);

// Line generators for the case file's `spacing` choices.
std::vector<double> uniform_lines(double start, double end, int cells);
// Lines clustered towards both ends (tanh stretching of strength beta > 0; beta -> 0 is uniform).
std::vector<double> tanh_lines(double start, double end, int cells, double beta);
// Lines growing geometrically from the start by `ratio` per cell.
std::vector<double> geometric_lines(double start, double end, int cells, double ratio);
// Uniform cells of width (core_end - core_start) / core_cells on [core_start, core_end], growing by `ratio`
// per cell from there to start and to end (the outer cells scaled slightly to fit): a fine window around a
// body, coarse far away. A body-fitted mesh's form, with `first` > 0: the window's cells are clustered towards
// both its ends, `first` wide there and growing geometrically towards its middle, and the outer cells grow from
// `first`; `max_width` > 0 caps the outer cells' growth (the domain's own spacing far out). std::invalid_argument
// if `first` cannot be clustered (core_cells * first >= the window).
std::vector<double> clustered_lines(double start, double end, double core_start, double core_end, int core_cells,
                                    double ratio, double first = 0.0, double max_width = 0.0);
// The number of cells clustered_lines() makes, to within one on each side of the window, without making them
// (a case may ask for more than memory holds: ratio 1 across a long domain).
double clustered_cell_count(double start, double end, double core_start, double core_end, int core_cells, double ratio,
                            double first = 0.0, double max_width = 0.0);
// The growth ratio of the window's clustered cells (widths first r^k from both ends), 1 for uniform.
double window_ratio(double length, int cells, double first);

}  // namespace chute
