#include "scalar_transport.hpp"

#include <stdexcept>

#include "limiter.hpp"

namespace chute {

namespace {

constexpr auto kScheme = ConvectionScheme::van_leer;
constexpr int kMaxScalars = 4;

// What one face carries for each scalar: the convective flux A u phi_f, and the diffusive flux
// A Gamma (phi_ahead - phi_behind) / dc; `volume` is A u (for the advective-form correction).
struct FaceFlux {
    double convective[kMaxScalars], diffusive[kMaxScalars], volume;
    bool open;
};

}  // namespace

void scalar_transport(const Grid& grid, const Velocity& vel, const Field2D& nu_t, double nu, const Field2D& fluid,
                      const std::vector<TransportedScalar>& scalars, const LineVelocities* lines) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    const int nx = grid.nx(), ny = grid.ny();
    const std::size_t ns = scalars.size();
    if (ns > kMaxScalars) throw std::invalid_argument("scalar_transport: at most 4 scalars at once");
    // Face between cells (behind) and (ahead) along one direction; q(k) reads a scalar k cells ahead
    // of `behind` along that direction (k = -1, 0, 1, 2).
    auto face = [&](double u, double area, double w1, double dc, bool open, double nu_t_mean, auto&& q) {
        FaceFlux f{};
        f.open = open;
        if (!open) return f;
        f.volume = area * u;
        for (std::size_t s = 0; s < ns; ++s) {
            const Field2D& p = *scalars[s].phi;
            const double value = transported<kScheme>(u, q(p, -1), q(p, 0), q(p, 1), q(p, 2), w1);
            f.convective[s] = f.volume * value;
            f.diffusive[s] = area * (nu + nu_t_mean / scalars[s].sigma) * (q(p, 1) - q(p, 0)) / dc;
        }
        return f;
    };
    std::vector<FaceFlux> south(nx), north(nx), west(nx + 1);
    auto y_face = [&](int i, int j) {  // face j of column i: between cells (i, j-1) and (i, j)
        return face(vel.v(i, j) - (lines ? lines->y(j) : 0.0), X.w(i), (Y.f(j) - Y.c(j - 1)) / Y.dc(j), Y.dc(j),
                    fluid(i, j - 1) != 0.0 && fluid(i, j) != 0.0, 0.5 * (nu_t(i, j - 1) + nu_t(i, j)),
                    [&](const Field2D& p, int k) { return p(i, j - 1 + k); });
    };
    for (int i = 0; i < nx; ++i) south[i] = y_face(i, 0);
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i <= nx; ++i)  // face i of row j: between cells (i-1, j) and (i, j)
            west[i] = face(vel.u(i, j) - (lines ? lines->x(i) : 0.0), Y.w(j), (X.f(i) - X.c(i - 1)) / X.dc(i), X.dc(i),
                           fluid(i - 1, j) != 0.0 && fluid(i, j) != 0.0, 0.5 * (nu_t(i - 1, j) + nu_t(i, j)),
                           [&](const Field2D& p, int k) { return p(i - 1 + k, j); });
        for (int i = 0; i < nx; ++i) north[i] = y_face(i, j + 1);
        for (int i = 0; i < nx; ++i) {
            if (fluid(i, j) == 0.0) {
                for (std::size_t s = 0; s < ns; ++s) (*scalars[s].out)(i, j) = 0.0;
                continue;
            }
            const FaceFlux& w = west[i];
            const FaceFlux& e = west[i + 1];
            const FaceFlux& so = south[i];
            const FaceFlux& no = north[i];
            // Net outflow of volume through the open faces: the advective form adds phi_P times it.
            const double net_volume = (e.open ? e.volume : 0.0) - (w.open ? w.volume : 0.0) +
                                      (no.open ? no.volume : 0.0) - (so.open ? so.volume : 0.0);
            const double inv_v = 1.0 / (X.w(i) * Y.w(j));
            for (std::size_t s = 0; s < ns; ++s) {
                const double conv = w.convective[s] - e.convective[s] + so.convective[s] - no.convective[s];
                const double diff = e.diffusive[s] - w.diffusive[s] + no.diffusive[s] - so.diffusive[s];
                (*scalars[s].out)(i, j) = (conv + (*scalars[s].phi)(i, j) * net_volume + diff) * inv_v;
            }
        }
        std::swap(south, north);
    }
}

}  // namespace chute
