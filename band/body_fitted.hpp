#pragma once
// Carrier 2 (docs/design.md): the bodies are holes in the grid. Each body's rectangle covers a block of cells
// whose sides are grid lines (band/hole.hpp); the flow solver leaves those cells out and fills their faces as
// walls moving with the body (core/grid/solid_cells.hpp), so nothing needs imposing on u* here: the boundary
// condition is exact, the slip is zero. The two force measures of the record (body/body_forces.hpp):
//   (a) the momentum the step's fluxes carried across the sides (FlowSolver::solid_momentum_rate): the fluid's
//       momentum balance closes exactly with it; its torque is (b)'s (the study's blocks do not turn);
//   (b) the stress on the sides, split into pressure and viscous parts (band/hole_stress.hpp).
// They differ by the staggered grid's half cell beside each side: the normal-momentum cells end half a cell
// from the side, where (a) takes the convective and normal viscous fluxes and (b) the wall's zero.
//
// A body with prescribed translation carries the whole grid with it (ALE: the grid translates rigidly at the
// body's velocity, the convective fluxes are relative to it, and the domain's boundaries keep the conditions of
// the inertial frame: water at rest ahead of the block, an outflow behind), as the study's body-fitted
// OpenFOAM runs of a fall do. This version takes one moving body, prescribed (not free), without rotation; the
// rest is refused with an error naming the key. With k-epsilon the cells along the sides are the wall-adjacent
// cells of the log law (sample_walls), as a body-fitted mesh's first cells are.
#include <vector>

#include "carrier.hpp"
#include "solid_cells.hpp"

namespace chute {

struct BodyFittedSettings {
    double density = 1000.0, viscosity = 1e-6, depth = 1.0;  // the fluid's, and the run's span
};

class BodyFitted final : public Carrier {
public:
    // std::invalid_argument naming the key for a body or a case this carrier cannot take.
    BodyFitted(const Grid& grid, const BodyFittedSettings& settings, std::vector<Body>& bodies);

    const std::vector<Body>& bodies() const override { return bodies_; }
    double cell_size(std::size_t b) const override { return cell_size_[b]; }

    void begin_step(const Velocity&) override {}
    void place(double t) override;
    // The hole's faces are filled by the flow solver, whenever it fills the domain's boundaries.
    void impose(Velocity&, double) override {}
    Wrench hydrodynamic_wrench(std::size_t b, const Velocity& vel, double dt) override;
    std::vector<BodyForces> measure(const Velocity& vel, const Field2D& p, const WallTurbulence* turbulence) override;

    void locate_walls() override {}
    const Field2D& fluid_cells() const override { return solid_.fluid(); }
    std::vector<WallSample> sample_walls(const Velocity& vel, const Field2D& k) const override;

    const SolidCells* solid_cells() const override { return &solid_; }
    void attach(FlowSolver& flow) override;

private:
    const Grid& grid_;
    BodyFittedSettings settings_;
    std::vector<Body>& bodies_;
    SolidCells solid_;
    std::vector<double> cell_size_;
    FlowSolver* flow_ = nullptr;
    int carrying_ = -1;  // the body the grid moves with (-1: none)
    // The grid follows body `carrying_`: its velocity is the frame's and its block's.
    void follow();
};

}  // namespace chute
