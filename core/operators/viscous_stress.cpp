#include "viscous_stress.hpp"

namespace chute {

void add_viscous_stress(const Grid& grid, double nu, const EddyViscosity& eddy, const Velocity& vel, int u_first,
                        int v_first, Velocity& out) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    const int nx = grid.nx(), ny = grid.ny();
    const Field2D& u = vel.u;
    const Field2D& v = vel.v;
    const Field2D& nc = eddy.cell;
    const Field2D& nk = eddy.corner;
    // u at face (i, j): normal stress in cells i-1 and i, shear stress at corners (i, j) and (i, j+1).
    for (int j = 0; j < ny; ++j)
        for (int i = u_first; i < nx; ++i) {
            const double east = 2.0 * (nu + nc(i, j)) * (u(i + 1, j) - u(i, j)) / X.w(i);
            const double west = 2.0 * (nu + nc(i - 1, j)) * (u(i, j) - u(i - 1, j)) / X.w(i - 1);
            const double north = (nu + nk(i, j + 1)) *
                                 ((u(i, j + 1) - u(i, j)) / Y.dc(j + 1) + (v(i, j + 1) - v(i - 1, j + 1)) / X.dc(i));
            const double south =
                (nu + nk(i, j)) * ((u(i, j) - u(i, j - 1)) / Y.dc(j) + (v(i, j) - v(i - 1, j)) / X.dc(i));
            out.u(i, j) += (east - west) / X.dc(i) + (north - south) / Y.w(j);
        }
    // v at face (i, j): normal stress in cells j-1 and j, shear stress at corners (i, j) and (i+1, j).
    for (int j = v_first; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double north = 2.0 * (nu + nc(i, j)) * (v(i, j + 1) - v(i, j)) / Y.w(j);
            const double south = 2.0 * (nu + nc(i, j - 1)) * (v(i, j) - v(i, j - 1)) / Y.w(j - 1);
            const double east = (nu + nk(i + 1, j)) *
                                ((v(i + 1, j) - v(i, j)) / X.dc(i + 1) + (u(i + 1, j) - u(i + 1, j - 1)) / Y.dc(j));
            const double west =
                (nu + nk(i, j)) * ((v(i, j) - v(i - 1, j)) / X.dc(i) + (u(i, j) - u(i, j - 1)) / Y.dc(j));
            out.v(i, j) += (north - south) / Y.dc(j) + (east - west) / X.w(i);
        }
}

void add_cross_stress(const Grid& grid, double nu, const EddyViscosity& eddy, const Velocity& vel, int u_first,
                      int v_first, Velocity& out) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    const int nx = grid.nx(), ny = grid.ny();
    const Field2D& u = vel.u;
    const Field2D& v = vel.v;
    const Field2D& nk = eddy.corner;
    for (int j = 0; j < ny; ++j)
        for (int i = u_first; i < nx; ++i) {
            const double north = (nu + nk(i, j + 1)) * (v(i, j + 1) - v(i - 1, j + 1)) / X.dc(i);
            const double south = (nu + nk(i, j)) * (v(i, j) - v(i - 1, j)) / X.dc(i);
            out.u(i, j) += (north - south) / Y.w(j);
        }
    for (int j = v_first; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double east = (nu + nk(i + 1, j)) * (u(i + 1, j) - u(i + 1, j - 1)) / Y.dc(j);
            const double west = (nu + nk(i, j)) * (u(i, j) - u(i, j - 1)) / Y.dc(j);
            out.v(i, j) += (east - west) / X.w(i);
        }
}

}  // namespace chute
