// The convective operator beside a sharp immersed surface (core/operators/convection.hpp, wall_faces): the flux
// through a face between a ghost face and a fluid face is the moving wall's own momentum, whatever the scheme.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>

#include "convection.hpp"
#include "grid.hpp"

using namespace chute;

// A wall on the grid line y = 0.5 moving at V_b along its normal, fluid above, the body below; the fluid moves with
// it (v = V_b everywhere) and slides along it with u = s + g (y - 0.5) (a wall-function cell's slip s at the wall,
// a shear g), the ghost row below holding the mirror about the wall's tangential velocity 0: u_g = -u(mirror).
// Behind a receding wall (V_b < 0: the fluid comes down to it) every flux of the first fluid row but the wall's reads
// fluid faces only, on which the profile is linear, so every scheme gives the central value there (van Leer and
// Koren at r = 1): the row's convective term is exactly -(V_b u_n - V_b u_wall) / h, u_n = s + g h on the face above
// and u_wall = 0 the wall's own velocity. Ahead of an advancing wall (V_b > 0) the face above reads the ghost as its
// far-upwind value, so only central is exact there. Without the wall faces the upwind value at the wall (the
// fluid's behind it, the mirror ahead) leaves a flux V_b (u_upwind - u_wall) of the order of V_b s: the spurious
// momentum a fixed grid added to the study's falling block.
TEST(Convection, FluxBesideAWallFaceIsTheWallsMomentum) {
    const int ny = 16;
    const Grid grid(Axis(uniform_lines(0.0, 1.0, 8), true), Axis(uniform_lines(0.0, 1.0, ny), false), MPI_COMM_WORLD);
    const double h = 1.0 / ny, s = 0.3, g = 2.0, wall = 0.5;
    const int v_first = grid.ly().offset == 0 ? 1 : 0;
    const int first_fluid = ny / 2 - grid.ly().offset;  // the local row of the first fluid u faces
    const bool mine = first_fluid >= 0 && first_fluid < grid.ny();
    for (double Vb : {-1.5, 1.5}) {
        Velocity vel(grid), mask(grid), with(grid), without(grid);
        for (int j = -kGhost; j < grid.ny() + kGhost; ++j)
            for (int i = -kGhost; i < grid.nx() + kGhost; ++i) {
                const double y = grid.ly().c(j);
                vel.u(i, j) = y > wall ? s + g * (y - wall) : -(s + g * (wall - y));
                vel.v(i, j) = Vb;
                mask.u(i, j) = y < wall ? 1.0 : 0.0;
                mask.v(i, j) =
                    grid.ly().f(j) < wall - 1e-12 ? 1.0 : 0.0;  // strictly inside, as SharpForcing::wall_faces
            }
        const double exact = -Vb * (s + g * h) / h;
        for (ConvectionScheme scheme :
             {ConvectionScheme::central, ConvectionScheme::van_leer, ConvectionScheme::koren}) {
            convection(grid, scheme, vel, 0, v_first, with, nullptr, &mask);
            convection(grid, scheme, vel, 0, v_first, without, nullptr, nullptr);
            if (!mine) continue;
            const bool tvd = scheme != ConvectionScheme::central;
            for (int i = 0; i < grid.nx(); ++i) {
                if (Vb < 0.0 || !tvd) {
                    EXPECT_NEAR(with.u(i, first_fluid), exact, 1e-12) << "V_b " << Vb << " " << tvd;
                }
                // The wall's flux differs from the upwind one by V_b (u_upwind - 0) / h, |u_upwind| > s / 2 here.
                if (tvd) {
                    EXPECT_GT(std::abs(with.u(i, first_fluid) - without.u(i, first_fluid)), 0.5 * std::abs(Vb) * s / h)
                        << "V_b " << Vb;
                }
            }
        }
    }
}
