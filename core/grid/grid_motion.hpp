#pragma once
// How the grid's lines move (arbitrary Lagrangian-Eulerian form, Donea et al. 2004): along each axis one range
// of lines [first, last] (global indices) moves at a common velocity, the other lines are at rest. A grid that
// translates rigidly with a body-fitted block is the range of all lines; a block with modifier layers
// (band/layers.hpp) moves the lines of its rigid zone only, and the one cell between that zone and the fixed
// lines on each side stretches or shrinks (the layer that absorbs the motion, Turmel & Locat 2008, sec. 3.3).
//
// The fluxes see the velocity relative to the moving faces, u - w_f; a cell whose faces move apart grows, and the
// advective form keeps a uniform field uniform (the geometric conservation law, Thomas & Lombard 1979): its
// rate is -(1/V) [sum_f phi_f (u_f - w_f) A_f + phi_P sum_f w_f A_f] (core/operators/convection.hpp).
#include <array>
#include <climits>
#include <vector>

namespace chute {

class Grid;

struct AxisMotion {
    int first = 0, last = -1;  // the moving lines (global indices, inclusive); none when last < first
    double velocity = 0.0;     // m/s, along the axis
    double at(int line) const { return line >= first && line <= last ? velocity : 0.0; }
    // Every line, including the ghost lines beyond the domain's ends: the whole grid translates.
    static AxisMotion whole(double velocity) { return {INT_MIN / 2, INT_MAX / 2, velocity}; }
};

struct GridMotion {
    std::array<AxisMotion, 2> axis;  // x, y
    bool moving() const { return axis[0].velocity != 0.0 || axis[1].velocity != 0.0; }
};

// The velocities of one patch's lines (local indices from -kGhost, as the grid's geometry) and of its cell
// centres (the mean of the two lines around them: a cell stretches linearly).
class LineVelocities {
public:
    LineVelocities() = default;
    LineVelocities(const Grid& grid, const GridMotion& motion);

    double x(int i) const { return x_[i + offset_]; }           // line i (the left face of cell i)
    double y(int j) const { return y_[j + offset_]; }           // line j (the bottom face of cell j)
    double xc(int i) const { return 0.5 * (x(i) + x(i + 1)); }  // centre of cell i
    double yc(int j) const { return 0.5 * (y(j) + y(j + 1)); }
    bool zero() const { return zero_; }
    // Some lines move and some do not: cells change size (the geometric conservation law's term is needed).
    bool stretching() const { return stretching_; }

private:
    std::vector<double> x_, y_;
    int offset_ = 0;
    bool zero_ = true, stretching_ = false;
};

}  // namespace chute
