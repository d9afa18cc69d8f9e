#include "model.hpp"

#include <algorithm>
#include <stdexcept>

#include "carriers.hpp"
#include "case_settings.hpp"

namespace chute {

namespace {

std::vector<Body> bodies_of(const CaseConfig& config) {
    const Vec2 lo(config.x.start, config.y.start), hi(config.x.end, config.y.end);
    std::vector<Body> bodies;
    bodies.reserve(config.bodies.size());
    for (const BodyConfig& b : config.bodies) {
        try {
            bodies.emplace_back(b, lo, hi);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("bodies." + b.name + ": " + e.what());
        }
    }
    return bodies;
}

}  // namespace

Model::Model(const CaseConfig& config, MPI_Comm comm, const std::string& carrier)
    : config_(config),
      flow_(std::make_unique<FlowSolver>(config_, comm)),
      bodies_(bodies_of(config_)),
      carrier_(make_carrier(carrier, flow_->grid(), config_, bodies_)),
      free_(std::make_unique<FreeBodies>(free_body_settings(config_), bodies_, *carrier_)) {
    if (config_.turbulence.model == TurbulenceModelType::k_epsilon)
        turbulence_ = std::make_unique<KEpsilon>(k_epsilon_settings(config_), *flow_, *carrier_);
}

double Model::stable_dt() const { return std::min(flow_->next_dt(), free_->max_dt(config_.cfl)); }

std::optional<WallTurbulence> Model::wall_turbulence() const {
    if (!turbulence_) return std::nullopt;
    return turbulence_->at_walls();
}

}  // namespace chute
