#include "surface_stress.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

namespace chute {

std::vector<double> fit_weights(const std::vector<double>& d, const std::vector<int>& powers) {
    // Least squares: min_c sum_k (sum_m c_m d_k^(powers_m) - f_k)^2; c_0 = w^T f with w^T the first row of the
    // pseudo-inverse (V^T V)^-1 V^T. V is at most 6 x 2 here, well conditioned for distances of a few cells.
    const int n = static_cast<int>(d.size()), m = static_cast<int>(powers.size());
    if (m < 1 || n < m) throw std::invalid_argument("fit_weights: need at least as many probes as unknowns");
    Eigen::MatrixXd V(n, m);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < m; ++j) V(k, j) = std::pow(d[k], powers[j]);
    const Eigen::MatrixXd pinv = (V.transpose() * V).ldlt().solve(V.transpose());
    std::vector<double> w(n);
    for (int k = 0; k < n; ++k) w[k] = pinv(0, k);
    return w;
}

SurfaceStress::SurfaceStress(const Grid& grid, const IbmConfig& config, const Body& body, double marker_spacing)
    : grid_(grid),
      body_(body),
      d_(config.stress_probes),
      markers_(body.outline().markers(marker_spacing)),
      pressure_weights_(fit_weights(d_, {0, 2})),
      shear_weights_(fit_weights(d_, {1, 2})) {}

void SurfaceStress::place() {
    const std::size_t n = markers_.size();
    world_.resize(n);
    normal_.resize(n);
    h_.resize(n);
    probes_.assign(d_.size(), std::vector<Vec2>(n));
    for (std::size_t l = 0; l < n; ++l) {
        world_[l] = body_.to_world(markers_[l].position);
        normal_[l] = body_.direction_to_world(markers_[l].normal);
        const Vec2 h = local_spacing(grid_, world_[l]);
        h_[l] = std::sqrt(h.x() * h.y());
        for (std::size_t k = 0; k < d_.size(); ++k) probes_[k][l] = world_[l] + d_[k] * h_[l] * normal_[l];
    }
    sp_.clear(), su_.clear(), sv_.clear();
    for (const std::vector<Vec2>& at : probes_) {
        sp_.push_back(bilinear_stencils(grid_, Staggering::cell, at));
        su_.push_back(bilinear_stencils(grid_, Staggering::u_face, at));
        sv_.push_back(bilinear_stencils(grid_, Staggering::v_face, at));
    }
    placement_.computed();
}

std::vector<double> SurfaceStress::along_outline(const std::vector<double>& f) const {
    // Central differences between the neighbouring markers on the same smooth stretch of outline (normals
    // within 25 degrees: not across a corner), one-sided at a corner or an open end, 0 on a lone marker.
    const std::size_t n = f.size();
    const bool closed = body_.outline().closed();
    std::vector<double> g(n, 0.0);
    for (std::size_t l = 0; l < n; ++l) {
        std::size_t a = l, b = l;
        auto smooth = [&](std::size_t m) { return normal_[m].dot(normal_[l]) > 0.9; };
        if ((l > 0 || closed) && smooth((l + n - 1) % n)) a = (l + n - 1) % n;
        if ((l + 1 < n || closed) && smooth((l + 1) % n)) b = (l + 1) % n;
        if (a == b) continue;
        const double ds = (world_[b] - world_[a]).dot(perp(normal_[l]));
        if (ds != 0.0) g[l] = (f[b] - f[a]) / ds;
    }
    return g;
}

SurfaceForces SurfaceStress::compute(const Velocity& vel, const Field2D& p, double density, double viscosity,
                                     double depth, const WallTurbulence* turbulence) {
    if (placement_.stale(body_.moves())) place();
    const std::size_t n = markers_.size(), np = d_.size(), outer = np - 1;
    std::vector<std::vector<double>> P(np), W(np);
    for (std::size_t k = 0; k < np; ++k) {
        P[k] = interpolate(grid_, sp_[k], p);
        const std::vector<Vec2> U = interpolate_velocity(grid_, su_[k], sv_[k], vel);
        W[k].resize(n);
        for (std::size_t l = 0; l < n; ++l) W[k][l] = (U[l] - body_.velocity_at(probes_[k][l])).dot(perp(normal_[l]));
    }
    const std::vector<double> K =
        turbulence ? interpolate(grid_, sp_[outer], turbulence->k) : std::vector<double>(n, 0.0);
    // Shear rate at the wall: w = a y + b y^2 through the probes, no slip at y = 0.
    std::vector<double> shear(n, 0.0);
    for (std::size_t l = 0; l < n; ++l)
        for (std::size_t k = 0; k < np; ++k) shear[l] += shear_weights_[k] * W[k][l] / h_[l];
    // The pressure's normal gradient at a no-slip wall, from the momentum equation there (Gresho & Sani 1987,
    // IJNMF 7:1111, eq. 8): dp/dn = -a_wall . n + nu n . lap(u) = -a_wall . n - nu d(gamma)/ds (kinematic;
    // gamma = dw/dn the wall shear rate, the wall vorticity). The pressure is then fitted as p0 + (dp/dn) y + c y^2.
    const std::vector<double> dshear_ds = along_outline(shear);
    const BodyState& s = body_.state();
    SurfaceForces f;
    wall_pressure_.resize(n);
    for (std::size_t l = 0; l < n; ++l) {
        const double ds = markers_[l].length * depth;
        const Vec2& nl = normal_[l];
        const Vec2 t = perp(nl);
        const Vec2 r = world_[l] - s.centre;
        const Vec2 a_wall =
            s.acceleration + s.angular_acceleration * perp(r) - s.angular_velocity * s.angular_velocity * r;
        const double dpdn = -a_wall.dot(nl) - viscosity * dshear_ds[l];
        double p_fit = 0.0;
        for (std::size_t k = 0; k < np; ++k) p_fit += pressure_weights_[k] * (P[k][l] - dpdn * d_[k] * h_[l]);
        const double p_wall = density * (p_fit - 2.0 / 3.0 * K[l]);
        wall_pressure_[l] = p_wall;
        const Vec2 fp = -p_wall * nl * ds;
        const Vec2 fv = density * viscosity * shear[l] * t * ds;
        f.pressure += fp;
        f.viscous += fv;
        f.pressure_torque += cross(r, fp);
        f.viscous_torque += cross(r, fv);
        if (turbulence) {
            const double nu_wall = turbulence->wall_viscosity(K[l], d_[outer] * h_[l]);
            const Vec2 ft = density * (nu_wall * shear[l] * t - 2.0 / 3.0 * K[l] * nl) * ds;
            f.turbulent += ft;
            f.turbulent_torque += cross(r, ft);
        }
    }
    return f;
}

}  // namespace chute
