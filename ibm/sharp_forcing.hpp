#pragma once
// Sharp-interface direct forcing on the staggered grid (Fadlun, Verzicco, Orlandi & Mohd-Yusof 2000, JCP 161:35;
// Balaras 2004, Comput. Fluids 33:375, reconstruction along the normal; Yang & Balaras 2006, JCP 215:12, moving
// bodies): the surface enters the discrete equations where it lies, not spread over a kernel.
//
// Each velocity component on its own faces. With phi(x) the signed distance to the nearest body surface
// (negative inside) and X_s, n the nearest surface point and the outward normal there (Outline::nearest):
//   solid faces    phi < 0:  u* = U_b(x), the body's rigid velocity (the enclosed fluid moves with it)
//   forcing faces  phi >= 0 with a face of the same component inside a body at i +- 1 or j +- 1: the velocity
//                  reconstructed along the normal from the body's velocity at the surface and the flow at image
//                  points X_s + L n (bilinear interpolation of the same component), with L =
//                  turbulence.image_distance cells along the normal (2 by default, past every forcing face of a
//                  smooth surface):
//                    linear     u* = U_b(X_s) + (phi / L) (u(X_s + L n) - U_b(X_s)), with a wall-function
//                               model: L is where it samples the flow (immersed_wall.hpp), so the shear
//                               (nu + nu_w)(u_image - U_b) / L this profile sets is the wall law's;
//                    wall_law   with a wall-function model: the tangential velocity relative to the body
//                               follows the model's law of the wall from the image point down to the face
//                               (u_t(y) = u_tau u+(y u_tau / nu), u_tau from u_t at L), the normal part falls
//                               linearly: the near-wall fluid moves as the log layer says, as the first cells
//                               of a body-fitted grid with wall functions do;
//                    quadratic  through U_b at 0, u at L and at L + h (laminar runs): the linear profile's
//                               error at the face, b phi (L - phi) for u = a y + b y^2, is O(h^2) and makes the
//                               wall shear first order (DFG 2D-1's viscous drag: docs/validation.md); the
//                               quadratic is exact for that profile, which leaves O(h^3) at the face;
//                    mirror     (ghost faces) linear through the wall from the face's mirror image, L = |phi| (at
//                               least half a cell): u* = 2 U_b - u(X_s + |phi| n), Tseng & Ferziger's image. Where
//                               the surface lies on grid lines the image is the first fluid face, u* its reflection,
//                               and the flux across the wall is that of a body-fitted wall; with a wall-function model
//                               the eddy viscosity on the corners between the two (turbulence/k_epsilon.cpp) makes it
//                               the wall law's shear, as on a body-fitted hole's sides.
//                  Image stencils that read other forcing faces are resolved by repeating the reconstruction
//                  (numerics.ibm.sharp_sweeps times).
//   fluid faces    untouched.
// With numerics.ibm.sharp_faces: ghost (Tseng & Ferziger 2003, JCP 192:593) the profile sets the faces inside the body
// that have a neighbour outside instead (phi < 0: the profile carried through the wall; the mirror with a
// wall-function model, the law of the wall having no value there), and every fluid face keeps its own momentum
// equation: the flow beside the wall may then reverse under a separated layer, which a profile from the wall to an
// image point cannot give the forcing faces (docs/validation.md, "Sharp interface"). A face on the surface (|phi|
// below 1e-9 of a cell: a wall on a grid line) counts as inside, so that it takes the body's velocity as a
// body-fitted wall's face does. With forcing faces it counts as outside (a forcing face, set to the wall's velocity,
// the next face free, as beside a body-fitted wall): either way the same on every side of a body, whatever the
// round-off of its distance (decided by that round-off before, a square held in a stream along its diagonal, its
// sides on grid lines, read a lateral force of 5 % of its drag on a grid symmetric about the diagonal).
// Cut momentum (numerics.ibm.cut_momentum, ghost faces): a face is classified by its open fraction alpha (the
// part of its segment outside the body, as CutFaces measures it) instead of its centre. Every face with alpha > 0
// keeps its own momentum equation, its value the flow's across its open part, which the continuity equation and the
// projection already take it for (A alpha u); a ghost is a face the surface shuts whole (alpha = 0) that has such a
// neighbour. Classified by their centres, the faces along a side switched between fluid and ghost as the side crossed
// their middles, and the force jumped there (by 25 % on the blocked channel at 8 cells per gap; docs/validation.md,
// "Sharp interface", eleventh step). The viscous term of a face beside the surface then takes the wall where it lies
// on each grid line (Shortley & Weller 1938): from the face's point (the middle of its open part; its centre when
// whole) to each neighbour along x and y, the distance to the neighbour's point, or to the surface and the body's
// velocity there where the neighbour is shut,
//   nu [ (u_+ - u) / d_+ - (u - u_-) / d_- ] / ((d_+ + d_-) / 2)      per direction,
// in place of the uniform stencil the flow solver applied (taken out with the velocity it was applied to: u^n, or u*
// with implicit diffusion), the wall parts implicit (a face a sliver of a cell from the surface is held to its
// velocity, not made unstable by it). Each part takes the flow solver's coefficient (nu, or with the stress form
// 2 (nu + nu_t) on a normal stress and nu + nu_t on a shear); a wall part across which the flux is a shear takes,
// with a turbulence model, nu + nu_w(k, d), the wall law's eddy viscosity at the wall's distance d along the line
// (turbulence/wall_function.hpp, k the face's cells'), so that the wall shear is the law's from a sliver to a cell. A
// cut face's value tends to the body's as its open part closes, and its neighbour's stencil to the wall's: nothing
// jumps as a face opens or closes. The convection is transported by the cut fluxes, and the faces shut whole carry the
// body's velocity in it, not their mirror (FlowSolver::PressureBoundary::cut_transport): without the first a cut face
// whose centre is inside received the mirrored normal velocity of the ghosts across its shut side; without the
// second a face a sliver from the surface (held to U_b) and the same face shut (a mirror) differed in what the
// convection read, and a k-epsilon block held in a stream lost 5 % of its drag as its front and back neared a grid
// line. The momentum the wall terms give the fluid is the forcing's (measure (a)).
// A face in the reach of several bodies belongs to the one it is inside, else to the nearest surface; with cut
// momentum a face is cut, as CutFaces counts it, by the body its inside end is in, and each wall part of its stencil
// meets the first surface along its line, of whichever body (a block resting on a slope: the faces of the gap).
// The pressure: with forcing faces it is solved on the whole grid (the fast solvers stay); the projection then moves
// the forced faces by dt grad(phi): measure_slip() reports it (0.5 % of U_max on DFG 2D-1 at D/h 40, up to 10 % of U
// at the front corners of a square moving across the grid). With ghost faces the cells inside the bodies leave the
// pressure problem (ImmersedBoundary, FlowSolver::set_pressure_cells): the mirrored ghost values leave a divergence
// in the first cells inside, which a whole-grid projection pushes through the wall (26 % of U on the Lyn square).
// A face that leaves a moving body is next to the surface in that step (a body moves less than a cell per step), so
// with forcing faces it gets the reconstructed value: no face enters the fluid with a solid's history. With ghost
// faces it would enter with the mirror's value (the flow reflected through the wall): in the step it leaves the body
// it is set as a forcing face is, from the profile between the surface and an image point turbulence.image_distance
// cells out (linear where the ghost faces mirror), and is free from the next step on.
// Momentum given to the fluid per unit density, depth and time, for the force measure (a):
//   sum over the forced faces of V (u_forced - u*) / dt,   and its moment about the body's centre.
#include <functional>
#include <unordered_set>
#include <vector>

#include "body.hpp"
#include "carrier.hpp"  // WallTurbulence
#include "enclosed_momentum.hpp"
#include "euler_lagrange.hpp"
#include "grid_placement.hpp"
#include "ibm_config.hpp"
#include "immersed_forcing.hpp"
#include "viscous_stress.hpp"  // EddyViscosity

namespace chute {

// Bilinear stencils (euler_lagrange.hpp) of every rank's points, `mine` being this rank's: every rank holds its part
// of every point's stencil, so interpolate() is collective over the gathered list; this rank's points start at
// `first` in it. Collective.
std::vector<Stencil> gathered_stencils(const Grid& grid, Staggering s, const std::vector<Vec2>& mine,
                                       std::size_t& first);

// The profile between the surface and the flow beside it (above).
enum class SharpProfile { linear, quadratic, wall_law, mirror };
// The law of the wall (turbulence/): the tangential speed at distance y from a wall, given the speed at distance L.
using WallProfile = std::function<double(double speed, double L, double y)>;

class SharpForcing final : public ImmersedForcing {
public:
    // image_cells: L in cells (turbulence.image_distance).
    // viscosity: the fluid's kinematic viscosity (the cut ghost faces' own momentum, open_flux()).
    SharpForcing(const Grid& grid, const IbmConfig& config, const std::vector<Body>& bodies, double image_cells,
                 SharpProfile profile, double viscosity, WallProfile wall_profile = {});

    // Where the bodies are at the start of the step (a free body's update moved it since apply()): the forced faces
    // and the covered cells of extend_pressure(). Static bodies are classified once. Collective.
    void begin_step() override;
    void apply(Velocity& star, double dt) override;
    const std::vector<BodyForcing>& forcing() const override { return result_; }
    void measure_slip(const Velocity& vel) override;
    double cell_size(std::size_t b) const override { return cell_size_[b]; }
    double marker_spacing(std::size_t b) const override { return config_.marker_spacing * cell_size_[b]; }

    // The pressure of a cell whose four faces are all forced is no one's: the projection's only use of it is to
    // move forced faces, which the next forcing overwrites, so it drifts (tens of times the flow's dynamic
    // pressure beside the DFG cylinder). It matters once the cell is uncovered by a moving body (Yang & Balaras
    // 2006's field extension) and to the surface-stress probes, so it is replaced by the pressure at the image
    // point X_s + L_p n of its centre (L_p = 2.5 cells along n): a zero normal gradient across the surface,
    // interpolated from the other cells only (weights renormalised), so that it is a function of the fluid's
    // pressure alone (a restart recomputes it bit for bit). Cells deeper than 3 cells inside are left: no body
    // uncovers them within a step. Call after begin_step(); the caller refreshes the halos. Collective.
    void extend_pressure(Field2D& p) const;

    // Ghost faces: the momentum per unit density and depth that each closed body's region holds in `vel`, as the last
    // classification placed the bodies (begin_step(): at the start of the step; apply(): at its end), and its moment
    // about the body's centre:
    //   Q = sum over the faces the body forces (ghost and solid) of V (u - (1 - beta) u_o)
    //     + sum over the fluid faces of beta V u,
    // beta the fraction of the face's control volume V inside the body (that part's area, Outline::part_in_box: over
    // the volumes of a component beta V adds up to the body's area wherever it lies, and the moment takes each part's
    // momentum at its centroid; w below is the volume's extent along the normal) and u_o the mean over the volume's
    // outer part of the profile the ghost holds (carried through the wall from U_b over L = max(|phi|, w / 2): U_b +
    // (U_b - u) (w / 2 + phi) / (2 L)). The flow holds M = sum V u over every face; M - Q is the fluid's part of each
    // face's volume, at the face's velocity or, beside a forced face, the profile's. The body's force over a step is
    // then -(forcing + projection) + (Q^{n+1} - Q^n) / dt, the momentum the fluid gained, to round-off over any number
    // of steps (Q is a function of the state). The set of faces whose centres are inside, taken at the step's end from
    // u^n and u^{n+1} alike, was not: each face a moving surface crossed left its change out, and the drag of a circle
    // moved through still water read 15 % under the same circle held in the same stream, a square 1 %
    // (docs/validation.md, "Sharp interface", fifteenth step). beta moves continuously with the body, and a face
    // changes between forced and fluid where its value is the body's (cut momentum: a face shuts as its open part
    // closes, held to the wall's velocity), so Q does not jump. In the step a body starts or stops at once, the outer
    // parts' momentum answers too: a layer of cells (the first step's added mass +11 % at 16 cells across, +5 % at 32;
    // tests/unit/test_sharp_coupling.cpp). Collective.
    std::vector<EnclosedMomentum> held_momentum(const Velocity& vel) const;

    // The faces of this rank the last apply() forced (for tests and diagnostics).
    std::size_t solid_faces() const;
    std::size_t forcing_faces() const;
    std::size_t covered_cells() const { return covered_.size(); }

    // Ghost faces: a ghost face a surface cuts carries the fluid's flux through its open part (FlowSolver's pressure
    // boundary, ibm/cut_faces.hpp) with a velocity of its own, alpha (u + offset), u the mirrored value the
    // neighbours' stencils read. What the open part carries:
    //   - on a static body, the profile's value at the middle of the open part (its distance from the surface half
    //     the outer end's): the flow the fluid there has, with nothing carried from step to step. (A flux that
    //     followed the face's own momentum, damped only by its viscous term, drifted where the wall law leaves that
    //     term small: the study's block held a quarter cell off the grid lines read +33 % drag; docs/validation.md,
    //     "Sharp interface", fifth step.)
    //   - on a moving body, a face that a surface advancing along its normal has just covered carries on the flux
    //     of its own prediction as a fluid face (none jumps from the fluid's value to the mirror's as its centre
    //     crosses the surface: the moving ripple, third step); from then on that offset relaxes towards the
    //     profile's at the rate the body crosses the face, |U_x| / h_x + |U_y| / h_y, and the face's viscous rate
    //     (nu + nu_t)(2 / dx^2 + 2 / dy^2). A face a receding surface uncovers, or one on a side's line that a
    //     corner slides past, starts from the profile's (their own prediction put the moving block's drag 2 % low).
    // 0 on every other face. Set by apply().
    const Velocity& open_flux() const { return open_flux_; }
    // The flow solver's viscous operator in this step (set before apply()): its eddy viscosity (null: none; the cut
    // ghost faces' own viscous term adds it), whether it is the stress divergence with 2 (nu + nu_t) on the normal
    // stresses (core/operators/viscous_stress.hpp: with an eddy viscosity or implicit diffusion) or nu laplacian(u)
    // (diffusion.hpp), and the velocity it was applied to (u^n with explicit diffusion, u* as the implicit solve left
    // it): cut momentum takes it out where the wall stencils replace it. What it points to must outlive the step.
    struct ViscousOperator {
        const EddyViscosity* eddy = nullptr;
        bool stress_form = false;
        const Velocity* applied_to = nullptr;
    };
    void set_viscous_operator(const ViscousOperator& op) { viscous_ = op; }
    // The turbulence model's k and wall law (null: laminar): cut momentum's wall shear is the law's (below).
    void set_wall_turbulence(const WallTurbulence* turbulence) { wall_turbulence_ = turbulence; }
    bool cut_momentum() const { return cut_momentum_; }
    // Ghost faces: 1 on the faces strictly inside a body whose values the forcing sets (the ghost faces' mirror, the
    // body's velocity deeper in) as classified at the start of the step, 0 elsewhere (the faces a body left since are
    // fluid faces; a face on the surface holds the wall's own velocity, as a body-fitted wall's face); owned faces. The
    // convection takes the wall's flux beside them (FlowSolver::set_wall_faces). Not set with cut momentum, whose
    // convection reads the cut fluxes (FlowSolver::PressureBoundary::cut_transport).
    const Velocity& wall_faces() const { return wall_faces_; }
    // The offsets, for a checkpoint: a restart continues bit for bit. Collective (gathered over the ranks).
    std::vector<double> open_flux_state() const;
    void restore_open_flux(const std::vector<double>& state);

private:
    struct ForcedFace {
        int i, j;
        int body;
        double volume;                // the face's control volume per unit depth
        Vec2 position;                // of the face
        double phi;                   // signed distance to the body's surface (negative inside)
        Vec2 surface;                 // X_s, the nearest surface point (world)
        Vec2 normal;                  // the outward normal there (world)
        bool reconstructed = false;   // set from the profile (a forcing or ghost face), else to the body's velocity
        bool fresh = false;           // ghost faces: a face the body left since the last classification
        double weight = 0.0;          // of (u_1 - U_s), u_1 at the first image point (forcing faces)
        double weight2 = 0.0;         // of (u_2 - U_s), u_2 at the second (quadratic profile)
        double image_distance = 0.0;  // L (m)
        bool cut = false;             // ghost faces: a surface crosses it (an end outside, one inside)
        double open_phi = 0.0;        // cut faces: the distance of the open part's midpoint to the surface
        double open_weight = 0.0, open_weight2 = 0.0;  // the profile's weights there
    };
    // One component's forced faces: the solid ones, then the forcing ones with their image points' stencils.
    struct Component {
        std::vector<ForcedFace> solid, forcing;
        std::vector<Stencil> images;        // of every rank's image points, this rank's part of each
        std::size_t first_image = 0;        // this rank's first image point among them
        std::vector<Stencil> images2;       // the second image points (quadratic profile), in the same order
        std::vector<Stencil> images_other;  // the other component at the image points (wall-law profile)
        std::vector<double> self;           // the weight of each forcing face in its own image's stencil
        std::vector<char> inside;           // ghost faces, per face key: 1 inside a body at the last classification
    };
    // Cut momentum: a face's open fraction against body b and the point its value stands for (the middle of its open
    // part; its centre when whole or shut).
    struct FaceCut {
        double alpha;
        Vec2 point;
        int body = -1;  // face_cut_any(): the body that shuts it whole or in part (-1: open whole)
    };
    FaceCut face_cut(std::size_t b, bool is_u, int i, int j) const;
    // Against every body, as CutFaces counts it: cut by the body its inside end is in (kept per face until the next
    // classification).
    FaceCut face_cut_any(bool is_u, int i, int j) const;
    FaceCut face_cut_across_bodies(bool is_u, int i, int j) const;
    mutable std::vector<FaceCut> face_cuts_[2];  // face_cut_any()'s, per component and face key (alpha < 0: not yet)
    // The owned faces of one component within body b's reach and two cells (every owned face for a plane).
    struct FaceRange {
        int i0, i1, j0, j1;
    };
    FaceRange faces_in_reach(std::size_t b, bool is_u) const;
    // The viscous stencil of a face with an open part beside the surface, per direction (x, y): the distances to its
    // neighbours' points or to the surface (minus, plus), whether that side is the wall, and the wall's point.
    struct WallStencil {
        int i = 0, j = 0, body = 0;
        bool is_u = true;
        bool active[2] = {false, false};  // the direction's stencil differs from the uniform one
        double distance[2][2] = {{0, 0}, {0, 0}}, uniform[2][2] = {{0, 0}, {0, 0}};
        double width[2] = {0, 0}, uniform_width[2] = {0, 0};
        bool wall[2][2] = {{false, false}, {false, false}};
        int wall_body[2][2] = {{0, 0}, {0, 0}};  // the body whose surface the wall part meets
        Vec2 wall_point[2][2] = {{Vec2(0, 0), Vec2(0, 0)}, {Vec2(0, 0), Vec2(0, 0)}};
    };
    void find_wall_stencils();
    // The coefficient K of a wall stencil's flux K (u_side - u) / distance on one side: the flow solver's (nu, or with
    // the stress form 2 (nu + nu_t) of the cell between on a normal stress, nu + nu_t of the corner on a shear); on a
    // wall side across which the flux is a shear, with a turbulence model, nu + nu_w, the wall law's eddy viscosity
    // at the wall's distance along the line for the face's k (face_k(), `k`).
    double stencil_coefficient(const WallStencil& w, int d, int side, bool at_wall, double k) const;
    double face_k(const WallStencil& w) const;  // k at a face: its fluid cells' mean (their neighbours' if none)
    // The wall terms on the predicted velocity (backward Euler in the face's own value); `account` receives each
    // face's change by body (the body, the part of the change).
    void apply_wall_stencils(Velocity& star, double dt,
                             const std::function<void(const WallStencil&, int, double)>& account);
    bool any_moves() const;
    // Classified where the bodies are now: none moves and the grid did not move under them since.
    bool classified() const;
    void classify();
    void find_covered_cells();
    double on_surface(std::size_t b) const;  // phi below which a face counts as inside body b (+-1e-9 of a cell)
    long long face_key(int i, int j) const;  // a face's key among one component's faces (local indices)
    std::size_t face_keys() const;           // the number of keys of faces i in [0, nx], j in [0, ny]
    // The signed distances to body b of a face's two ends (below on_surface(): negative, as CutFaces counts them).
    std::pair<double, double> end_distances(std::size_t b, bool is_u, int i, int j) const;
    // Ghost faces: the open flux's offsets of the step's cut faces, from their predicted values (before the forcing).
    // profile: the profile's value at the middle of each forcing face's open part (reconstruction(..., open)).
    void carry_open_flux(const Component& c, bool is_u, const std::vector<double>& predicted, const Field2D& forced,
                         const std::vector<double>& profile, double dt);
    bool inside_any(const Vec2& X) const;
    bool forced(bool is_u, int i, int j) const;  // forcing faces: inside, or beside a face inside
    void classify_component(bool is_u, Component& out) const;
    // The forcing faces' values from the image points (sweeps of the reconstruction); collective.
    void reconstruct(Component& c, bool is_u, Field2D& f, const Field2D& other, int sweeps) const;
    // What the forcing faces' profile gives them from `field` as it is (collective).
    std::vector<double> reconstruction(const Component& c, bool is_u, const Field2D& field, const Field2D& other,
                                       bool open = false) const;
    double target(const ForcedFace& f, bool is_u, const Vec2& at) const;

    const Grid& grid_;
    IbmConfig config_;
    const std::vector<Body>& bodies_;
    double image_cells_;
    SharpProfile profile_;
    double viscosity_;
    ViscousOperator viscous_;                          // set_viscous_operator()
    const WallTurbulence* wall_turbulence_ = nullptr;  // set_wall_turbulence()
    bool ghost_;                                       // numerics.ibm.sharp_faces: ghost
    bool cut_momentum_;                                // numerics.ibm.cut_momentum
    std::vector<WallStencil> wall_stencils_;
    WallProfile wall_profile_;
    std::vector<double> cell_size_;
    Component u_, v_;
    struct CoveredCell {
        int i, j;
    };
    std::vector<CoveredCell> covered_;  // cells whose four faces are all forced, down to 3 cells inside
    std::vector<Stencil> covered_images_;
    std::size_t first_covered_ = 0;
    Field2D uncovered_;  // 0 in covered_ cells, 1 elsewhere (owned cells)
    bool placed_ = false;
    GridPlacement placement_{grid_};  // of the classification
    std::vector<BodyForcing> result_;
    std::vector<int> forced_by_u_, forced_by_v_;  // per face key: the body forcing it (ghost or solid), else -1
    Velocity open_flux_;                          // open_flux(): nonzero only on the faces listed below
    Velocity wall_faces_;                         // wall_faces()
    struct OffsetFace {
        int i, j;
    };
    std::vector<OffsetFace> offset_u_, offset_v_;
};

}  // namespace chute
