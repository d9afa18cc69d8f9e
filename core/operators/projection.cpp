#include "projection.hpp"

namespace chute {

void divergence(const Grid& grid, const Velocity& vel, double scale, Field2D& out) {
    for (int j = 0; j < grid.ny(); ++j)
        for (int i = 0; i < grid.nx(); ++i) out(i, j) = scale * cell_divergence(grid, vel, i, j);
}

void subtract_pressure_gradient(const Grid& grid, const BoundaryConditions& bc, const Field2D& p, double dt,
                                Velocity& vel, const Field2D* aperture_u, const Field2D* aperture_v) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    const int nx = grid.nx(), ny = grid.ny();
    // Boundary faces with p = 0 prescribed (zero-stress outflow) are corrected like interior faces.
    const int i_begin = bc.corrects_face(Side::left) ? 0 : bc.u_first();
    const int i_end = bc.corrects_face(Side::right) ? nx + 1 : nx;
    const int j_begin = bc.corrects_face(Side::bottom) ? 0 : bc.v_first();
    const int j_end = bc.corrects_face(Side::top) ? ny + 1 : ny;
    if (!aperture_u) {
        for (int j = 0; j < ny; ++j)
            for (int i = i_begin; i < i_end; ++i) vel.u(i, j) -= dt * (p(i, j) - p(i - 1, j)) / X.dc(i);
        for (int j = j_begin; j < j_end; ++j)
            for (int i = 0; i < nx; ++i) vel.v(i, j) -= dt * (p(i, j) - p(i, j - 1)) / Y.dc(j);
        return;
    }
    const Field2D &au = *aperture_u, &av = *aperture_v;
    for (int j = 0; j < ny; ++j)
        for (int i = i_begin; i < i_end; ++i)
            if (au(i, j) > 0.0) vel.u(i, j) -= dt * (p(i, j) - p(i - 1, j)) / X.dc(i);
    for (int j = j_begin; j < j_end; ++j)
        for (int i = 0; i < nx; ++i)
            if (av(i, j) > 0.0) vel.v(i, j) -= dt * (p(i, j) - p(i, j - 1)) / Y.dc(j);
}

}  // namespace chute
