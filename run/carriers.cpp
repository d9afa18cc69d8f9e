#include "carriers.hpp"

#include <map>
#include <stdexcept>

#include "body_fitted.hpp"
#include "case_settings.hpp"
#include "immersed_boundary.hpp"

namespace chute {

namespace {

std::map<std::string, CarrierFactory>& registry() {
    static std::map<std::string, CarrierFactory> r = {
        {"immersed",
         [](const Grid& grid, const CaseConfig& config, std::vector<Body>& bodies) {
             return std::make_unique<ImmersedBoundary>(grid, immersed_boundary_settings(config), bodies);
         }},
        {"body_fitted", [](const Grid& grid, const CaseConfig& config, std::vector<Body>& bodies) {
             return std::make_unique<BodyFitted>(grid, body_fitted_settings(config), bodies);
         }}};
    return r;
}

}  // namespace

void register_carrier(const std::string& name, CarrierFactory factory) { registry()[name] = std::move(factory); }

std::unique_ptr<Carrier> make_carrier(const std::string& name, const Grid& grid, const CaseConfig& config,
                                      std::vector<Body>& bodies) {
    const auto it = registry().find(name);
    if (it == registry().end()) {
        std::string known;
        for (const auto& [n, f] : registry()) known += (known.empty() ? "" : ", ") + n;
        throw std::invalid_argument("unknown carrier `" + name + "` (known: " + known + ")");
    }
    return it->second(grid, config, bodies);
}

}  // namespace chute
