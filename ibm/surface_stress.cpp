#include "surface_stress.hpp"

#include <cmath>

namespace chute {

SurfaceStress::SurfaceStress(const Grid& grid, const IbmConfig& config, const Body& body, double marker_spacing)
    : grid_(grid), body_(body), d_(config.stress_probes), markers_(body.outline().markers(marker_spacing)) {}

void SurfaceStress::place() {
    const std::size_t n = markers_.size();
    world_.resize(n);
    normal_.resize(n);
    probe1_.resize(n);
    probe2_.resize(n);
    h_.resize(n);
    for (std::size_t l = 0; l < n; ++l) {
        world_[l] = body_.to_world(markers_[l].position);
        normal_[l] = body_.direction_to_world(markers_[l].normal);
        const Vec2 h = local_spacing(grid_, world_[l]);
        h_[l] = std::sqrt(h.x() * h.y());
        probe1_[l] = world_[l] + d_[0] * h_[l] * normal_[l];
        probe2_[l] = world_[l] + d_[1] * h_[l] * normal_[l];
    }
    p1_ = bilinear_stencils(grid_, Staggering::cell, probe1_);
    p2_ = bilinear_stencils(grid_, Staggering::cell, probe2_);
    u1_ = bilinear_stencils(grid_, Staggering::u_face, probe1_);
    u2_ = bilinear_stencils(grid_, Staggering::u_face, probe2_);
    v1_ = bilinear_stencils(grid_, Staggering::v_face, probe1_);
    v2_ = bilinear_stencils(grid_, Staggering::v_face, probe2_);
    placed_ = true;
}

SurfaceForces SurfaceStress::compute(const Velocity& vel, const Field2D& p, double density, double viscosity,
                                     double depth, const WallTurbulence* turbulence) {
    if (!placed_ || body_.moves()) place();
    const Field2D* k = turbulence ? &turbulence->k : nullptr;
    const std::vector<double> P1 = interpolate(grid_, p1_, p), P2 = interpolate(grid_, p2_, p);
    const std::vector<double> K2 = k ? interpolate(grid_, p2_, *k) : std::vector<double>(markers_.size(), 0.0);
    const std::vector<Vec2> U1 = interpolate_velocity(grid_, u1_, v1_, vel);
    const std::vector<Vec2> U2 = interpolate_velocity(grid_, u2_, v2_, vel);
    SurfaceForces f;
    wall_pressure_.resize(markers_.size());
    const double d1 = d_[0], d2 = d_[1];
    for (std::size_t l = 0; l < markers_.size(); ++l) {
        const double ds = markers_[l].length * depth;
        const Vec2& n = normal_[l];
        const Vec2 t = perp(n);
        const double p_wall = density * (P1[l] - d1 * (P2[l] - P1[l]) / (d2 - d1) - 2.0 / 3.0 * K2[l]);
        wall_pressure_[l] = p_wall;
        const double h = h_[l];
        const double w1 = (U1[l] - body_.velocity_at(probe1_[l])).dot(t);
        const double w2 = (U2[l] - body_.velocity_at(probe2_[l])).dot(t);
        const double dwdn = (w1 * d2 * d2 - w2 * d1 * d1) / (h * d1 * d2 * (d2 - d1));
        const Vec2 fp = -p_wall * n * ds;
        const Vec2 fv = density * viscosity * dwdn * t * ds;
        const Vec2 r = world_[l] - body_.state().centre;
        f.pressure += fp;
        f.viscous += fv;
        f.pressure_torque += cross(r, fp);
        f.viscous_torque += cross(r, fv);
        if (k) {
            const double nu_wall = turbulence->wall_viscosity(K2[l], d2 * h);
            const Vec2 ft = density * (nu_wall * dwdn * t - 2.0 / 3.0 * K2[l] * n) * ds;
            f.turbulent += ft;
            f.turbulent_torque += cross(r, ft);
        }
    }
    return f;
}

}  // namespace chute
