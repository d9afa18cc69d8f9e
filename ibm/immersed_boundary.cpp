#include "immersed_boundary.hpp"

#include <stdexcept>

namespace chute {

ImmersedBoundary::ImmersedBoundary(const Grid& grid, const CaseConfig& config) : grid_(grid), config_(config) {
    const Vec2 lo(config.x.start, config.y.start), hi(config.x.end, config.y.end);
    bodies_.reserve(config.bodies.size());
    for (const BodyConfig& b : config.bodies) {
        try {
            bodies_.emplace_back(b, lo, hi);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("bodies." + b.name + ": " + e.what());
        }
    }
    forcing_ = std::make_unique<DirectForcing>(grid, config.ibm, bodies_);
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        stress_.push_back(std::make_unique<SurfaceStress>(grid, config.ibm, bodies_[b], forcing_->marker_spacing(b)));
}

void ImmersedBoundary::move_to(double t) {
    for (Body& b : bodies_) b.move_to(t);
}

std::vector<BodyForces> ImmersedBoundary::forces(const Velocity& vel, const Field2D& p, const Field2D* k) const {
    std::vector<BodyForces> out(bodies_.size());
    const double rho = config_.density, depth = config_.depth;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const Body& body = bodies_[b];
        const BodyForcing& f = forcing_->forcing()[b];
        BodyForces& r = out[b];
        r.forcing = rho * depth * (-f.momentum_rate + body.area() * body.state().acceleration);
        r.forcing_torque = rho * depth * (-f.torque_rate + body.polar_moment() * body.state().angular_acceleration);
        r.max_slip = f.max_slip;
        r.rms_slip = f.rms_slip;
        r.surface = stress_[b]->compute(vel, p, rho, config_.viscosity, depth, k);
    }
    return out;
}

}  // namespace chute
