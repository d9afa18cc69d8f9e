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
// A body that moves carries the grid with it. With grid_motion `layers` (band/layers.hpp) only the lines of a rigid
// zone around it move, the lines beyond stay and the layer between stretches, a layer moving from ahead of the
// block to behind it when the one ahead gets too thin: the domain and its walls stay put. With `translate`
// it carries the whole grid (ALE: the grid translates rigidly at the body's velocity,
// the convective fluxes are relative to it, and the domain's boundaries keep the conditions of the inertial
// frame: water at rest ahead of the block, an outflow behind), as the study's body-fitted OpenFOAM runs of a fall
// do. So the boundaries across an axis the body moves along cannot be walls (they would move with it); the
// constructor refuses them, naming the key. One body moves, and only translates.
//
// A free body is coupled strongly, without passes and without a relaxation parameter. Within a step the flow is
// linear in the body's velocity at its end, which enters the projection only through the sides' normal faces
// (FlowSolver::hole_response): the body's added mass over the step is the force of that response, and the
// update (m + M) a = F(a*) + W + M a* (rigidbody/free_bodies.cpp) is the converged coupled solution. body_moved()
// then adds the response to the flow for the body's final velocity and puts the grid at its final place. The
// response depends on the spacings alone (the grid only translates): two Poisson solves at the start.
// With k-epsilon the cells along the sides are the wall-adjacent cells of the log law (sample_walls), as a
// body-fitted mesh's first cells are.
#include <array>
#include <optional>
#include <vector>

#include "carrier.hpp"
#include "layers.hpp"
#include "solid_cells.hpp"

namespace chute {

struct BodyFittedSettings {
    double density = 1000.0, viscosity = 1e-6, depth = 1.0;  // the fluid's, and the run's span
    std::array<BoundaryType, 4> boundaries{};                // left, right, bottom, top
    double contact_distance = 0.0;                           // contact.distance (m)
};

class BodyFitted final : public Carrier {
public:
    // std::invalid_argument naming the key for a body or a case this carrier cannot take.
    BodyFitted(const Grid& grid, const BodyFittedSettings& settings, std::vector<Body>& bodies);

    const std::vector<Body>& bodies() const override { return bodies_; }
    double cell_size(std::size_t b) const override { return cell_size_[b]; }

    // With modifier layers: a layer moved from ahead of the block to behind it where a modifier reached its
    // threshold (band/layers.hpp), the flow remapped and projected once.
    void begin_step(const Velocity&) override;
    void place(double t) override;
    // The hole's faces are filled by the flow solver, whenever it fills the domain's boundaries.
    void impose(Velocity&, double) override {}
    Wrench hydrodynamic_wrench(std::size_t b, const Velocity& vel, double dt) override;
    std::optional<Eigen::Matrix3d> added_mass(std::size_t b) const override;
    void body_moved(std::size_t b, double dt) override;
    bool measure_holds_impulse(std::size_t) const override { return false; }
    std::vector<BodyForces> measure(const Velocity& vel, const Field2D& p, const WallTurbulence* turbulence) override;

    void locate_walls() override {}
    const Field2D& fluid_cells() const override { return solid_.fluid(); }
    std::vector<WallSample> sample_walls(const Velocity& vel, const Field2D& k) const override;

    const SolidCells* solid_cells() const override { return &solid_; }
    void attach(FlowSolver& flow) override;
    NamedArrays checkpoint_arrays() const override;
    void restored(const NamedArrays& arrays) override;

    // The layer changes so far along x and y, and the kinetic energy of the flow before and after the projection
    // that followed the last one (m^4/s^2 per unit density and depth).
    std::array<int, 2> layer_changes() const;
    // The zone's lines removed at its lower and upper end as it compressed towards a wall, along x and y.
    std::array<std::array<int, 2>, 2> zone_trimmed() const {
        return {layers_[0] ? layers_[0]->trimmed() : std::array<int, 2>{},
                layers_[1] ? layers_[1]->trimmed() : std::array<int, 2>{}};
    }
    std::array<double, 2> last_change_energy() const { return change_energy_; }

private:
    const Grid& grid_;
    BodyFittedSettings settings_;
    std::vector<Body>& bodies_;
    SolidCells solid_;
    std::vector<double> cell_size_;
    FlowSolver* flow_ = nullptr;
    int carrying_ = -1;  // the body the grid moves with (-1: none)
    // A free carrying body: the flow's response to its velocity, and its added mass from it (kg).
    std::optional<FlowSolver::BodyResponse> response_;
    Eigen::Matrix2d added_mass_ = Eigen::Matrix2d::Zero();
    // The grid follows body `carrying_`: its velocity is the frame's and its block's, and its block sits where the
    // body is.
    void follow();
    void refuse_walls_across_motion(const Body& body) const;
    bool moves_along(const Body& body, int axis) const;
    void refuse_contact_it_cannot_take(const Body& body, int axis) const;
    // The modifier layers along the axes the carrying body moves along (grid_motion: layers).
    std::array<std::optional<AxisLayers>, 2> layers_;
    std::array<double, 2> change_energy_{};
    bool lines_restored_ = false;  // restored(): the next follow() keeps the checkpoint's lines
    // With layers: where the rigid zones were centred last (the lines' place), and where they were when the free
    // body's response was computed (at the last layer change; a restart recomputes it there, bit for bit).
    std::array<double, 2> zone_centre_{}, response_centre_{};
    // The pressure solver's multigrid hierarchy is set up on the zone at a quantized place (AxisLayers::
    // hierarchy_centre), again when the zone passes to the next one or the cells changed: a restart finds it.
    std::array<double, 2> hierarchy_centre_{};
    bool hierarchy_dirty_ = true;
    void refresh_hierarchy();
    void compute_response(bool warm = false);  // warm: the solves start from the last response
    void holes_found_again();  // after the lines changed: the blocks' cells, the solver's and the response
};

}  // namespace chute
