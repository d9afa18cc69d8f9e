#include "scalar_transport.hpp"

#include "limiter.hpp"

namespace chute {

void scalar_transport(const Grid& grid, const Velocity& vel, const Field2D& phi, const Field2D& nu_t, double nu,
                      double sigma, const Field2D& fluid, Field2D& out) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    constexpr auto S = ConvectionScheme::van_leer;
    for (int j = 0; j < grid.ny(); ++j)
        for (int i = 0; i < grid.nx(); ++i) {
            if (fluid(i, j) == 0.0) {
                out(i, j) = 0.0;
                continue;
            }
            const double p = phi(i, j);
            double sum = 0.0;  // sum over open faces of A_f [ -u_f (phi_f - phi_P) + Gamma_f (phi_N - phi_P) / dc ]
            // west face (i) and east face (i+1): the velocity points from cell i-1 to i when positive.
            for (int f = i; f <= i + 1; ++f) {
                const int n = f == i ? i - 1 : i + 1;
                if (fluid(n, j) == 0.0) continue;
                const double w1 = (X.f(f) - X.c(f - 1)) / X.dc(f);
                const double face = transported<S>(vel.u(f, j), phi(f - 2, j), phi(f - 1, j), phi(f, j), phi(f + 1, j), w1);
                const double outward = f == i ? -1.0 : 1.0;
                const double gamma = nu + 0.5 * (nu_t(i, j) + nu_t(n, j)) / sigma;
                sum += Y.w(j) * (-outward * vel.u(f, j) * (face - p) + gamma * (phi(n, j) - p) / X.dc(f));
            }
            for (int f = j; f <= j + 1; ++f) {
                const int n = f == j ? j - 1 : j + 1;
                if (fluid(i, n) == 0.0) continue;
                const double w1 = (Y.f(f) - Y.c(f - 1)) / Y.dc(f);
                const double face = transported<S>(vel.v(i, f), phi(i, f - 2), phi(i, f - 1), phi(i, f), phi(i, f + 1), w1);
                const double outward = f == j ? -1.0 : 1.0;
                const double gamma = nu + 0.5 * (nu_t(i, j) + nu_t(i, n)) / sigma;
                sum += X.w(i) * (-outward * vel.v(i, f) * (face - p) + gamma * (phi(i, n) - p) / Y.dc(f));
            }
            out(i, j) = sum / (X.w(i) * Y.w(j));
        }
}

}  // namespace chute
