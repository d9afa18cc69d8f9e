#pragma once
// What a rockfall run is read for, per free body (Turmel & Locat 2008, sec. 4): the fall speed before the
// first impact, the impact velocity, the rebound height, the runout to the next impact, the peak forces.
// Fed every recorded step; text() is appended to the run's summary.
#include <string>
#include <vector>

#include "carrier.hpp"
#include "case_config.hpp"
#include "rebound.hpp"

namespace chute {

class TrajectorySummary {
public:
    TrajectorySummary(const CaseConfig& config, const Carrier& carrier);
    void observe(double t, const std::vector<BodyForces>& forces);
    void impacts(const std::vector<ContactEvent>& events);
    std::string text() const;

private:
    struct Track {
        std::size_t index = 0;
        std::string name;
        std::vector<std::pair<double, double>> speed;  // (t, |v|) before the first impact
        double peak_hydrodynamic = 0.0, peak_contact = 0.0, peak_impulse = 0.0;
        std::vector<ContactEvent> events;
        double rebound_height = 0.0;  // highest rise of the centre after the first impact, before the second
        Vec2 last_centre = Vec2::Zero();
    };
    const std::vector<Body>& bodies_;
    Vec2 up_;  // against gravity
    std::vector<Track> tracks_;
};

}  // namespace chute
