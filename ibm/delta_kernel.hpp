#pragma once
// Regularised delta kernels phi(r), r the distance in grid spacings. The 2D kernel is phi(rx) phi(ry) / h^2.
//
//   roma3   (Roma, Peskin & Berger 1999, JCP 153:509), support |r| < 1.5: 3 points per direction, the
//           kernel of Uhlmann (2005) and Breugem (2012).
//   peskin4 (Peskin 2002, Acta Numerica 11:479, eq. 6.27), support |r| < 2.
//   roma3_smoothed (Yang, Zhang, Li & Balaras 2009, JCP 228:7821, their smoothed 3-point kernel), the default:
//           roma3 convolved with a top hat of one cell, support |r| < 2. Its first derivative is continuous,
//           which is what damps the force oscillations of a body moving across the grid in that paper.
// All three satisfy sum_k phi(r - k) = 1 and sum_k (r - k) phi(r - k) = 0 (exact interpolation of linear
// fields on uniform grids).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ibm_config.hpp"

namespace chute {

inline double kernel_support(DeltaKernel k) { return k == DeltaKernel::roma3 ? 1.5 : 2.0; }

// roma3 smoothed: phi(r) = integral of roma3 over [r - 1/2, r + 1/2], in closed form.
inline double roma3_smoothed(double r) {
    const double s3 = std::sqrt(3.0), pi = std::numbers::pi;
    if (r <= 1.0)
        return 17.0 / 48.0 + s3 * pi / 108.0 + r / 4.0 - r * r / 4.0 +
               (1.0 - 2.0 * r) / 16.0 * std::sqrt(-12.0 * r * r + 12.0 * r + 1.0) -
               s3 / 12.0 * std::asin(s3 / 2.0 * (2.0 * r - 1.0));
    if (r <= 2.0)
        return 55.0 / 48.0 - s3 * pi / 108.0 - 13.0 * r / 12.0 + r * r / 4.0 +
               (2.0 * r - 3.0) / 48.0 * std::sqrt(std::max(0.0, -12.0 * r * r + 36.0 * r - 23.0)) +
               s3 / 36.0 * std::asin(std::min(1.0, s3 / 2.0 * (2.0 * r - 3.0)));
    return 0.0;
}

inline double delta_kernel(DeltaKernel k, double r) {
    r = std::abs(r);
    if (k == DeltaKernel::roma3_smoothed) return roma3_smoothed(r);
    if (k == DeltaKernel::roma3) {
        if (r <= 0.5) return (1.0 + std::sqrt(1.0 - 3.0 * r * r)) / 3.0;
        if (r <= 1.5) return (5.0 - 3.0 * r - std::sqrt(1.0 - 3.0 * (1.0 - r) * (1.0 - r))) / 6.0;
        return 0.0;
    }
    if (r <= 1.0) return (3.0 - 2.0 * r + std::sqrt(1.0 + 4.0 * r - 4.0 * r * r)) / 8.0;
    if (r <= 2.0) return (5.0 - 2.0 * r - std::sqrt(-7.0 + 12.0 * r - 4.0 * r * r)) / 8.0;
    return 0.0;
}

}  // namespace chute
