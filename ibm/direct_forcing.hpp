#pragma once
// Direct forcing (Uhlmann 2005, JCP 209:448) with multi-direct forcing iterations (Breugem 2012, JCP
// 231:4469; Luo et al. 2007), applied to the predicted velocity u* of the projection step:
//
//   repeat forcing_iterations times:
//     U_l = I[u*](X_l)                      interpolate to every marker (regularised delta, euler_lagrange)
//     F_l = (U_body(X_l) - U_l) / dt        the force per unit mass that gives the body velocity there
//     u* += dt S[F_l dV_l]                  spread back; dV_l = marker length x local grid spacing
//   the pressure projection follows (FlowSolver::project).
//
// Before that, the fluid inside a closed body is forced towards the rigid-body velocity: a volume forcing that
// accelerates the enclosed fluid with the body within the step. Without it the enclosed fluid is accelerated
// only through the pressure of earlier steps, and the response of an accelerating body lags by tens of steps
// (the added mass of a square accelerated from rest came out ~60 % low after 10 steps; docs/validation.md).
// A face d below the surface is forced with the share a(d): u* += a (U_body - u*) + (1 - a) dU_body, dU_body
// the body's change of velocity over the step there (dt times its acceleration, less what an earlier pass of
// the step followed). a rises linearly from 0 where the kernel stops reaching from the markers,
// (support + retraction) h, to 1 `volume_ramp` cells deeper (default 2; 0: a switch there). A switch gains
// and loses whole rows of faces as the body crosses the grid, the front and the back at different moments,
// and carried most of the force ripple at the cell-crossing frequency (Lee et al. 2011, JCP 230:2677;
// docs/validation.md, "Cell-crossing ripple": 5.1 % of the falling block's force, 1.4 % with the ramp). The
// lattice sum of a linear ramp of whole-cell width is the same at every offset of the body against the grid;
// a partly forced face still follows the body's acceleration in full, so the enclosed fluid stays rigid
// against an accelerating body (without that, the accelerated square's added mass rose by 10 %).
//
// The body is at its place at t^{n+1} when the forcing is applied. Each iteration shrinks the slip error
// |U_l - U_body| left by the overlap of neighbouring kernels; the error after the last iteration is reported.
// Momentum given to the fluid per unit density and depth per unit time: sum_l F_l dV_l (summed over the
// iterations) plus the volume forcing's sum over faces of its change of u* times V / dt.
#include <vector>

#include "body.hpp"
#include "euler_lagrange.hpp"
#include "grid_placement.hpp"
#include "immersed_forcing.hpp"

namespace chute {

class DirectForcing final : public ImmersedForcing {
public:
    DirectForcing(const Grid& grid, const IbmConfig& config, const std::vector<Body>& bodies);

    // A new step: the volume forcing follows the bodies' accelerations from zero again.
    void begin_step() override;
    // Force u* (owned faces) towards the bodies' velocities at their present place.
    void apply(Velocity& star, double dt) override;
    const std::vector<BodyForcing>& forcing() const override { return result_; }

    // Marker spacing used for body b (m).
    double marker_spacing(std::size_t b) const override { return config_.marker_spacing * cell_size_[b]; }
    double cell_size(std::size_t b) const override { return cell_size_[b]; }  // smallest grid spacing along the outline

private:
    void place_markers();
    void find_interior_faces();
    // Moves u* on the interior faces towards the body velocity; adds the momentum it took to the body's forcing.
    void force_interior(Velocity& star, double dt);

    const Grid& grid_;
    IbmConfig config_;
    const std::vector<Body>& bodies_;
    std::vector<double> cell_size_;    // smallest grid spacing along each body's outline
    std::vector<std::size_t> ranges_;  // markers of body b: [ranges_[b], ranges_[b+1])
    std::vector<Marker> body_frame_;   // all markers, body frame (retraction applied)
    std::vector<Vec2> world_;          // all markers, world frame
    std::vector<double> volume_;       // dV_l
    std::vector<Stencil> su_, sv_;
    struct InteriorFace {
        int i, j;       // local indices of an owned face
        bool is_u;      // u face or v face
        double volume;  // its control volume (per unit depth)
        Vec2 position;
        double share;  // a(d): the share of the way to the body velocity it is moved, (0, 1]
    };
    std::vector<std::vector<InteriorFace>> interior_;  // per body
    GridPlacement placement_{grid_};                   // of the markers
    std::vector<BodyForcing> result_;
    std::vector<BodyState> followed_;  // the accelerations the volume forcing followed so far in this step
};

// The smallest grid spacing met along a body's outline (markers are spaced relative to it).
double min_spacing_along(const Grid& grid, const Body& body);

}  // namespace chute
