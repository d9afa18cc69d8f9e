#pragma once
// The momentum of the fluid inside a body's outline, per unit depth: P = integral of u dA and
// L = integral of (x - x_c) x u dA over the body.
//
// A free body's hydrodynamic force from the forcing needs its rate of change (Uhlmann 2005 eq. 23; evaluated
// on the grid as Kempe & Froehlich 2012 do, rather than as the rigid-body value A dU_c/dt, which makes the
// coupling unstable for rho_s/rho_f below about 1.2). Each face counts with the fraction of its cell inside
// the body, from the signed distance: 1 deeper than half a cell, 0 beyond half a cell out, linear between.
#include "body.hpp"
#include "field.hpp"
#include "grid.hpp"

namespace chute {

struct EnclosedMomentum {
    Vec2 linear = Vec2::Zero();  // m^3/s per m of depth
    double angular = 0.0;        // m^4/s per m of depth, about the body's centre
};

// Sums over this rank's faces and reduces over all ranks. (Ghost faces: SharpForcing::held_momentum.)
EnclosedMomentum enclosed_momentum(const Grid& grid, const Velocity& vel, const Body& body);

}  // namespace chute
