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
#include <HYPRE_struct_ls.h>

#include <array>
#include <vector>

#include "boundary_conditions.hpp"
#include "viscous_stress.hpp"

namespace chute {

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
    };
    void create(Component& c, bool is_u);
    void destroy(Component& c);
    template <bool is_u>
    int solve(Component& c, double nu, const EddyViscosity& eddy, double dt, Velocity& vel);

    const Grid& grid_;
    const BoundaryConditions& bc_;
    double tolerance_;
    HYPRE_StructStencil stencil_ = nullptr;
    Component u_, v_;
};

}  // namespace chute
