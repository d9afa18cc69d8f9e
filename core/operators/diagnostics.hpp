#pragma once
// Global quantities and derived fields for outputs: kinetic energy, divergence, cell-centred velocity,
// vorticity, probes. All reductions are over every rank.
#include <array>
#include <vector>

#include "field.hpp"

namespace chute {

// 0.5 * sum over cells of |u_c|^2 V (per unit depth and density), u_c the cell-centred velocity. `fluid`
// (1 fluid, 0 solid; null: every cell) leaves the solid cells of a body-fitted hole out, here and below.
double kinetic_energy(const Grid& grid, const Velocity& vel, const Field2D* fluid = nullptr);
// max over cells of |div u| (1/s).
double max_divergence(const Grid& grid, const Velocity& vel, const Field2D* fluid = nullptr);
// Cell-centred velocity components (mean of the two faces).
void cell_centred_velocity(const Grid& grid, const Velocity& vel, Field2D& uc, Field2D& vc);
// Vorticity dv/dx - du/dy at cell centres (mean of the four corner values).
void vorticity(const Grid& grid, const Velocity& vel, Field2D& omega);

// Point probes: bilinear interpolation of cell-centred values at fixed points.
class Probes {
public:
    Probes(const Grid& grid, std::vector<std::array<double, 2>> points);
    // Values of the cell-centred field at every probe (on every rank).
    std::vector<double> sample(const Field2D& cell_field) const;
    std::size_t size() const { return points_.size(); }

private:
    struct Stencil {
        bool local = false;
        int i = 0, j = 0;  // lower-left cell centre
        double fx = 0, fy = 0;
    };
    const Grid& grid_;
    std::vector<std::array<double, 2>> points_;
    std::vector<Stencil> stencils_;
};

}  // namespace chute
