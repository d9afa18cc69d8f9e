#include "diffusion.hpp"

namespace chute {

void add_diffusion(const Grid& grid, double nu, const Velocity& vel, int u_first, int v_first, Velocity& out) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    const int nx = grid.nx(), ny = grid.ny();
    const Field2D& u = vel.u;
    const Field2D& v = vel.v;
    for (int j = 0; j < ny; ++j) {
        const double cn = 1.0 / (Y.dc(j + 1) * Y.w(j)), cs = 1.0 / (Y.dc(j) * Y.w(j));
        for (int i = u_first; i < nx; ++i) {
            const double ce = 1.0 / (X.w(i) * X.dc(i)), cw = 1.0 / (X.w(i - 1) * X.dc(i));
            out.u(i, j) += nu * (ce * (u(i + 1, j) - u(i, j)) - cw * (u(i, j) - u(i - 1, j)) +
                                 cn * (u(i, j + 1) - u(i, j)) - cs * (u(i, j) - u(i, j - 1)));
        }
    }
    for (int j = v_first; j < ny; ++j) {
        const double cn = 1.0 / (Y.w(j) * Y.dc(j)), cs = 1.0 / (Y.w(j - 1) * Y.dc(j));
        for (int i = 0; i < nx; ++i) {
            const double ce = 1.0 / (X.dc(i + 1) * X.w(i)), cw = 1.0 / (X.dc(i) * X.w(i));
            out.v(i, j) += nu * (ce * (v(i + 1, j) - v(i, j)) - cw * (v(i, j) - v(i - 1, j)) +
                                 cn * (v(i, j + 1) - v(i, j)) - cs * (v(i, j) - v(i, j - 1)));
        }
    }
}

}  // namespace chute
