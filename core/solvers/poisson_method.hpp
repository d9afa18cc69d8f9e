#pragma once

namespace chute {

// How the projection's Poisson problem is solved (numerics.poisson.solver). `automatic`: directly (a transform
// along a uniform axis, tridiagonal systems along the other: direct_poisson.hpp) where an axis is uniform and no
// cell is solid, else hypre's multigrid-preconditioned CG; `multigrid`: always hypre (the reference the direct
// solve is tested against).
enum class PoissonMethod { automatic, multigrid };

}  // namespace chute
