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

// The carrier the case's bodies ask for (bodies.<body>.carrier); one run carries all its bodies one way.
std::string carrier_of(const CaseConfig& config) {
    auto name = [](CarrierKind k) { return k == CarrierKind::body_fitted ? "body_fitted" : "immersed"; };
    if (config.bodies.empty()) return "immersed";
    const BodyConfig& first = config.bodies.front();
    for (const BodyConfig& b : config.bodies)
        if (b.carrier != first.carrier)
            throw std::invalid_argument("bodies." + b.name + ".carrier: `" + name(b.carrier) + "`, but bodies." +
                                        first.name + ".carrier is `" + name(first.carrier) +
                                        "`: one run carries all its bodies the same way");
    return name(first.carrier);
}

}  // namespace

Model::Model(const CaseConfig& config, MPI_Comm comm, const std::string& carrier)
    : config_(config),
      flow_(std::make_unique<FlowSolver>(config_, comm)),
      bodies_(bodies_of(config_)),
      carrier_(make_carrier(carrier.empty() ? carrier_of(config_) : carrier, flow_->grid(), config_, bodies_)),
      free_(std::make_unique<FreeBodies>(free_body_settings(config_), bodies_, *carrier_)),
      frame_(FollowingFrame::of(config_)) {
    if (const SolidCells* solid = carrier_->solid_cells()) flow_->set_solid_cells(solid);
    carrier_->attach(*flow_);
    if (config_.turbulence.model == TurbulenceModelType::k_epsilon) {
        turbulence_ = std::make_unique<KEpsilon>(k_epsilon_settings(config_), *flow_, *carrier_);
        carrier_->attach_turbulence(turbulence_->at_walls());
    }
    // A translating grid moves with the body from the first step's limit on (run/following_frame.hpp).
    window_after_step();
}

void Model::window_before_step() {
    if (frame_) frame_->before_step(*flow_, turbulence_.get(), bodies_[frame_->body()]);
}

void Model::window_to_placed_body() {
    if (frame_) frame_->place(*flow_, bodies_[frame_->body()]);
}

void Model::window_after_step() {
    if (frame_) frame_->after_step(*flow_, bodies_[frame_->body()]);
}

double Model::stable_dt() const {
    double dt = std::min(flow_->next_dt(), free_->max_dt(config_.cfl));
    // With dt auto a prescribed body moves numerics.cfl cells per step at most, as a free one does: started
    // impulsively in still water it sets the first steps alone (the flow's CFL sees water at rest). A fixed dt is
    // the user's, for the prescribed motion as for the flow.
    if (config_.fixed_dt) return dt;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const Body& body = bodies_[b];
        if (!body.moves() || body.free()) continue;
        const BodyState& s = body.state();
        dt = std::min(dt, longest_step(s.velocity, s.angular_velocity, s.acceleration, s.angular_acceleration,
                                       body.outline().reach(), config_.cfl * carrier_->cell_size(b)));
    }
    return dt;
}

std::optional<WallTurbulence> Model::wall_turbulence() const {
    if (!turbulence_) return std::nullopt;
    return turbulence_->at_walls();
}

}  // namespace chute
