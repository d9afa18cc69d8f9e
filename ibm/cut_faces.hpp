#pragma once
// The faces the bodies' surfaces cut, for a pressure problem that follows a sharp surface continuously (the ghost
// faces of ibm/sharp_forcing.hpp; FlowSolver::PressureBoundary).
//
// Each face of the staggered grid is a segment: a u face x = x_f, y in [y_j, y_j+1]; a v face y = y_f, x in
// [x_i, x_i+1]. Its aperture alpha is the fraction of it outside every body: where its ends lie on both sides of a
// surface, the crossing found by bisection on the signed distance; a point within 1e-9 of a cell of a
// surface counts as inside, so that a face lying on a surface on a grid line is shut. (The surface taken straight
// between the ends, phi_out / (phi_out - phi_in), left the face along a square's side open whole while the corner
// crossed it: alpha 1 where the open part is the corner's distance, a step each time a moving corner crossed a face
// line.) A face cut within 1e-8 of its length from an end is whole, open or shut: that close, the crossing is the
// tolerance's, in bits the round-off of the body's place decides. Two ends outside: open (a surface bulging through a
// face between its ends is not seen). The cells with an open face hold flow (the pressure problem's cells); the flux
// through a face is
//   A (alpha u + (1 - alpha) U_b),  U_b the body's velocity at the shut part's middle,
// the fluid's part through the open fraction and the body's through the rest, so that a cut cell's mass balance
// carries the body's motion across its shut part (the geometric conservation of a moving surface: Seo & Mittal
// 2011, JCP 230:7347; Cheny & Botella 2010, JCP 229:1043), and the pressure problem's coefficients A alpha / d change
// continuously as a body moves, not a whole cell at a time.
#include <vector>

#include "body.hpp"
#include "field.hpp"
#include "grid_placement.hpp"
#include "rigid_body.hpp"  // Wrench

namespace chute {

// A point this close to a surface counts as inside (h: the cell size): a face lying on a surface on a grid line is
// the body's, as a body-fitted wall's face is (CutFaces, ghost faces of SharpForcing).
inline double on_surface_tolerance(double h) { return 1e-9 * h; }
// The signed distance of a world point to a body's surface, negative inside, with the points within `tolerance` of
// the surface taken inside (at most -tolerance).
double surface_distance(const Body& body, const Vec2& point, double tolerance);

// A face cut within this fraction of its length from an end counts as whole (CutFaces::update, SharpForcing).
inline constexpr double kWholeFace = 1e-8;
// The fraction of the segment a-b outside `body`, `a` outside and `b` inside (points within `tolerance` of the surface
// inside, as surface_distance counts them).
double open_fraction(const Body& body, const Vec2& a, const Vec2& b, double tolerance);

class CutFaces {
public:
    CutFaces(const Grid& grid, const std::vector<Body>& bodies);

    // The apertures where the bodies are now; true when they were computed (the first call, and every call with a
    // moving body): static bodies are done once.
    bool update();

    // Local indices, the faces of the owned cells (u: i = 0..nx, v: j = 0..ny) and their ghosts.
    const Field2D& aperture_u() const { return aperture_u_; }
    const Field2D& aperture_v() const { return aperture_v_; }
    const Velocity& body_velocity() const { return body_velocity_; }  // U_b on the cut and shut faces, else 0
    const Field2D& open_cells() const { return open_; }               // 1: a face of the cell is open

    // The force and moment about each body's centre that a cell pressure q (kinematic, as FlowSolver holds p)
    // exerts on the bodies through the shut parts of the cut cells' faces: the surface closes a cut cell's fluid
    // part, and its share of the cell's boundary is the shut parts, sum_f (1 - alpha_f) A_f n_f (n_f the face's
    // outward normal, A_f per unit depth), so the body receives rho depth q_c (1 - alpha_f) A_f n_f from each,
    // applied at the shut part's middle. It is the dual of the flux A (1 - alpha) U_b that the body's motion
    // carries through the same parts (the work q does on the body is the work the projection's pressure does on
    // the fluid), and a cell whose faces are all shut or all open receives nothing. Owned cells, reduced over the
    // ranks; the apertures of the last update(). Collective.
    std::vector<Wrench> pressure_wrenches(const Field2D& q, double density, double depth) const;
    // The velocity U + omega x (x - centre) at the middles of the shut parts of the faces body b shuts whole or in
    // part (ghosts included), 0 elsewhere: body b's surfaces in a rigid motion, for FlowSolver::cut_response. (The
    // middle, where pressure_wrenches() applies its force too: the response's added mass is then symmetric.)
    Velocity shut_velocity(std::size_t b, const Vec2& U, double omega, const Vec2& centre) const;
    // The bodies' velocities changed after the step's projection, their surfaces where they were (ImmersedBoundary::
    // body_moved): the shut faces carry `scale` times `unit` (a shut_velocity() field) more, so that the continuity the
    // projection met still holds.
    void add_shut_velocity(const Velocity& unit, double scale);

private:
    const Grid& grid_;
    const std::vector<Body>& bodies_;
    Field2D aperture_u_, aperture_v_, open_;
    Velocity body_velocity_;
    // Per face: the body that shuts it (-1: open), and the middle of its shut part as a fraction along the face
    // from its lower end (x for a v face, y for a u face).
    Field2D owner_u_, owner_v_, shut_middle_u_, shut_middle_v_;
    Vec2 shut_point(bool is_u, int i, int j, double middle) const;  // a face's point `middle` along it
    GridPlacement placement_{grid_};
};

}  // namespace chute
