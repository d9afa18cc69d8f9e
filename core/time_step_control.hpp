#pragma once
// Adaptive time step for the explicit (Adams-Bashforth 2) momentum update:
//   convection:  dt <= cfl / max(|u|/dx + |v|/dy)
//   diffusion:   dt <= d / (nu (1/dx^2 + 1/dy^2)); AB2 is stable for real eigenvalues down to
//                lambda dt = -1, and the 5-point Laplacian's is -4 nu (1/dx^2 + 1/dy^2), so d <= 1/4.
#include "field.hpp"
#include "grid_motion.hpp"

namespace chute {

struct TimeStepLimits {
    double convective = 0.0;
    double diffusive = 0.0;
    double stable() const { return convective < diffusive ? convective : diffusive; }
};

// Global (all ranks) max of 1/dx^2 + 1/dy^2: the diffusion limit is diffusion_number / (nu times it).
double max_inverse_square_spacing(const Grid& grid);

// Global (all ranks) limits for the current velocity.
// `lines`: the velocities of moving grid lines (a body-fitted grid, core/grid/grid_motion.hpp); the convective
// limit takes |u - w| at each face and the rate at which a stretching cell's faces approach each other.
TimeStepLimits time_step_limits(const Grid& grid, const Velocity& vel, double nu, double cfl, double diffusion_number,
                                const LineVelocities* lines = nullptr);

}  // namespace chute
