#pragma once
// Implicit (backward Euler) momentum diffusion with a variable viscosity nu_e = nu + nu_t.
//
// Why: with k-epsilon the wake's eddy viscosity sets the explicit step, dt <= d h^2 / (2 nu_t): 0.75 ms
// against 2.4 ms from the CFL number for the study's block at 20 cells across (docs/performance.md).
//
// The Boussinesq stress of viscous_stress.hpp is split the way OpenFOAM splits laplacian(nuEff, U) from
// div(nuEff dev2(T(grad U))):
//   implicit  L u = d/dx(2 nu_e du/dx) + d/dy(nu_e du/dy)      (v: d/dy(2 nu_e dv/dy) + d/dx(nu_e dv/dx))
//   explicit        d/dy(nu_e dv/dx)                            (v: d/dx(nu_e du/dy)), see add_cross_stress
// The explicit cross terms have no diagonal part. On a divergence-free field they give back the normal
// stress that L counts twice, so for constant nu_e the split sums to nu_e laplacian(u). A von Neumann check
// of AB2 on the cross terms with L backward Euler gives |z| <= 1/2 as nu_e dt / h^2 grows: no step limit.
//
// Delta form: from the explicit prediction u_E (ghosts filled),
//   (I - dt L_0) du = dt L u_E,    u* = u_E + du,
// where L_0 is L with homogeneous boundary conditions: du = 0 on boundary faces, and in the ghost row beyond
// a side du mirrors the way u does (odd on wall and inflow sides, even on slip and outflow sides). Multiplied
// by the face's control volume the matrix is symmetric and diagonally dominant; hypre's Struct PCG with a
// Jacobi (diagonal) preconditioner solves it in a few iterations. First order in time for the diffusion.
//
// A body-fitted hole (core/grid/solid_cells.hpp) is a wall of the same kind: its faces are not unknowns (identity
// rows, du = 0: the fill sets them from U), a face next to one drops the coupling, and where the hole's face is
// the mirror of this very face (the tangential faces inside a side, u = U - (u_m - U) inner / outer) the mirror's
// du = -(inner / outer) du folds into the diagonal, as the odd ghost of a domain wall does.
#include <HYPRE_struct_ls.h>

#include <array>
#include <vector>

#include "boundary_conditions.hpp"
#include "solid_cells.hpp"
#include "viscous_stress.hpp"

namespace chute {

// The rate L(u) of the implicit operator above (m/s^2) at the owned u face (i, j) or v face (i, j) (local
// indices), from a velocity whose halos, ghosts and hole faces are filled. The operator is conservative: the sum
// of V L(u) over a set of faces is the viscous momentum that crossed the set's boundary.
double implicit_rate_u(const Grid& grid, double nu, const EddyViscosity& eddy, const Velocity& vel, int i, int j);
double implicit_rate_v(const Grid& grid, double nu, const EddyViscosity& eddy, const Velocity& vel, int i, int j);

class ImplicitDiffusion {
public:
    // PCG's bound per component and step: the system is diagonally dominant (1 + dt nu Laplacian), so it
    // converges in tens of iterations; reaching the bound is reported (run/health_check.hpp), not hidden.
    static constexpr int kMaxIterations = 500;

    ImplicitDiffusion(const Grid& grid, const BoundaryConditions& bc, double tolerance = 1e-6);
    ~ImplicitDiffusion();
    ImplicitDiffusion(const ImplicitDiffusion&) = delete;
    ImplicitDiffusion& operator=(const ImplicitDiffusion&) = delete;

    // Turn the explicit prediction `vel` (owned faces, halos and ghosts filled) into the backward-Euler one.
    // Returns the larger PCG iteration count of the two components.
    int apply(double nu, const EddyViscosity& eddy, double dt, Velocity& vel);
    // The cells a body-fitted hole takes (null: none); the rows along it are rebuilt at the next apply().
    void set_solid_cells(const SolidCells* solid);

private:
    struct Component {
        std::array<int, 2> lower{}, upper{};  // owned unknown faces, global indices
        int first = 0;                        // first local face index along the component's direction
        int cells = 0;
        bool set_up = false;
        HYPRE_StructGrid grid = nullptr;
        HYPRE_StructMatrix matrix = nullptr;
        HYPRE_StructVector b = nullptr, x = nullptr;
        HYPRE_StructSolver pcg = nullptr;
        std::vector<double> values, rhs, solution;
        // Along a hole, per unknown (hypre order): 1 for a hole face (identity row); for the four neighbours
        // (stencil order west, east, south, north in the component's own a/b terms: a-1, a+1, b-1, b+1) a
        // negative value keeps the coupling, 0 drops it (du = 0 there), f > 0 drops it and adds f times its
        // coefficient to the diagonal (the neighbour mirrors this face: du_m = -f du).
        std::vector<char> hole;
        std::vector<std::array<double, 4>> neighbour;
        bool holes_mapped = false;
    };
    template <bool is_u>
    void map_holes(Component& c);
    void create(Component& c, bool is_u);
    void destroy(Component& c);
    template <bool is_u>
    int solve(Component& c, double nu, const EddyViscosity& eddy, double dt, Velocity& vel);

    const Grid& grid_;
    const BoundaryConditions& bc_;
    double tolerance_;
    const SolidCells* solid_ = nullptr;
    HYPRE_StructStencil stencil_ = nullptr;
    Component u_, v_;
};

}  // namespace chute
