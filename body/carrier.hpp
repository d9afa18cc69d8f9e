#pragma once
// The seam between the time step and whatever carries the bodies through the flow (docs/design.md, "the carrier
// seam"). Carrier 1 is the immersed boundary (ibm/immersed_boundary.hpp); carrier 2 will be the body-fitted
// band. The step (run/step.cpp) calls it in the order of docs/design.md's data flow:
//
//   begin_step(u^n)                       keep what the wrench needs from the start of the step
//   place(t^{n+1})                        prescribed bodies to their place (free bodies: rigidbody/free_bodies)
//   impose(u*, dt)                        the bodies on the predicted velocity (forcing, or boundary values)
//   (pressure projection)
//   hydrodynamic_wrench(b, u^{n+1}, dt)   on free body b, at its predicted place: what moves it
//   [body_moved(b, dt)]                   after the free body's update, where the carrier answers to its motion
//                                         exactly (added_mass): the flow brought to the body's final motion
//   [impose(u^{n+1}, dt), (projection), hydrodynamic_wrench(...)]   again, in a strongly coupled step
//                                         (rigidbody/free_bodies.hpp): the momentum imposed on the flow is
//                                         summed over the step's passes, from zero at begin_step
//   measure(u^{n+1}, p, turbulence)       the force record of every body, both measures (body_forces.hpp)
//
// and the turbulence model asks it where the walls are: fluid_cells(), and sample_walls(u, k) at the cells
// beside the bodies' surfaces, after locate_walls() (the log law itself is the model's, turbulence/). A carrier
// that cuts its bodies out of the grid hands the flow solver the cells it took: solid_cells().
// Free-body dynamics, turbulence, outputs and summaries hold a Carrier&, never a concrete carrier.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "body.hpp"
#include "body_forces.hpp"
#include "field.hpp"
#include "flow_solver.hpp"
#include "rigid_body.hpp"
#include "solid_cells.hpp"

namespace chute {

// One cell beside a body's surface, as a wall-function model needs it: where the flow was sampled and what.
struct WallSample {
    int i = 0, j = 0;             // local indices of an owned cell
    double distance = 0.0;        // of the cell centre from the surface (m); negative inside the body
    double size = 0.0;            // cell size h (m)
    double image_distance = 0.0;  // distance from the surface of the point sampled (m)
    double slip_speed = 0.0;      // |tangential velocity relative to the body| there (m/s)
    double k = 0.0;               // turbulence energy there (m^2/s^2)
    bool wall_function = false;   // the cell is the wall-adjacent one (0 <= distance < h)
};

// What the surface forces need of a turbulence model (null: laminar): k, and the wall eddy viscosity its wall
// law gives at distance y from a wall for energy k (the turbulent part of the surface stress).
struct WallTurbulence {
    const Field2D& k;
    std::function<double(double k, double y)> wall_viscosity;
};

class Carrier {
public:
    virtual ~Carrier() = default;

    virtual const std::vector<Body>& bodies() const = 0;
    // The grid length along body b's surface: a free body moves at most `cfl` of it in one step.
    virtual double cell_size(std::size_t b) const = 0;

    virtual void begin_step(const Velocity& start) = 0;
    virtual void place(double t) = 0;
    virtual void impose(Velocity& predicted, double dt) = 0;
    virtual Wrench hydrodynamic_wrench(std::size_t b, const Velocity& vel, double dt) = 0;
    // Strong coupling without passes: a carrier whose wrench is linear in free body b's velocity at the end of
    // the step gives the slope as the body's added mass M over the step (x, y and rotation about the centre: kg,
    // kg m and kg m^2; the wrench changes by -M da when the body's accelerations over the step change by da; zero
    // rows and columns for a motion it does not couple), and after the body's update
    // body_moved(b, dt) moves the flow and the grid to the body's final motion, so that the update solved with M
    // is the converged one (rigidbody/free_bodies.hpp). Null: the carrier does not (the diffuse immersed boundary,
    // whose free bodies take a virtual mass and passes instead).
    virtual std::optional<Eigen::Matrix3d> added_mass(std::size_t) const { return std::nullopt; }
    virtual void body_moved(std::size_t, double) {}
    // Whether measure()'s force (a) on body b holds the water's impulse of an impact step (the wrench of the step,
    // as the immersed boundary's is), which the record then takes out (run/step.cpp, measure_forces); false for a
    // carrier that measures after body_moved() brought the water to the body's final velocity (body-fitted).
    virtual bool measure_holds_impulse(std::size_t) const { return true; }
    // p is the kinematic pressure (p / rho) the flow solver holds.
    virtual std::vector<BodyForces> measure(const Velocity& vel, const Field2D& p,
                                            const WallTurbulence* turbulence) = 0;

    // Walls for a turbulence model. locate_walls() after the bodies moved (collective).
    virtual void locate_walls() = 0;
    virtual const Field2D& fluid_cells() const = 0;  // 1 in fluid cells, 0 inside a body; ghosts included
    virtual std::vector<WallSample> sample_walls(const Velocity& vel, const Field2D& k) const = 0;
    // True when each surface lies between fluid and solid cells with the fluid cells' own equations up to it (a
    // sharp interface with ghost faces): the wall law then acts through the corners between fluid and solid cells,
    // as on a body-fitted hole's sides; false: through a band of cells around a diffuse surface (immersed_wall.hpp).
    virtual bool walls_between_cells() const { return false; }

    // The cells the bodies take out of the fluid (a body-fitted hole, core/grid/solid_cells.hpp); null when the
    // bodies are forced on the whole grid (the immersed boundary). The flow solver is handed it once.
    virtual const SolidCells* solid_cells() const { return nullptr; }
    // The flow the bodies are carried through, handed once after both are built (after the solver took the
    // solid cells): a carrier that reads the solver's fluxes, or moves its grid with a body, keeps it.
    virtual void attach(FlowSolver&) {}
    // The turbulence model's k and wall law, handed once after the model is built (laminar runs: never): a carrier
    // whose momentum equations put the wall law at the surface (the sharp immersed boundary's cut momentum) keeps it.
    // k must outlive the carrier.
    virtual void attach_turbulence(const WallTurbulence&) {}
    // What a carrier needs in a checkpoint to continue bit for bit (small arrays, by name), and after a checkpoint
    // restored the grid's lines, the flow and the bodies' states (run/restart_state.cpp), before place(): those
    // arrays back, and a carrier whose cells follow the lines (a body-fitted grid with modifier layers) finds them.
    using NamedArrays = std::map<std::string, std::vector<double>>;
    virtual NamedArrays checkpoint_arrays() const { return {}; }
    virtual void restored(const NamedArrays&) {}
};

}  // namespace chute
