#include "trajectory_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace chute {

TrajectorySummary::TrajectorySummary(const CaseConfig& config, const Carrier& carrier) : bodies_(carrier.bodies()) {
    const Vec2 g(config.gravity[0], config.gravity[1]);
    up_ = g.norm() > 0.0 ? Vec2(-g / g.norm()) : Vec2(Vec2::UnitY());
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        if (bodies_[b].free()) {
            Track t;
            t.index = b;
            t.name = bodies_[b].name();
            tracks_.push_back(t);
        }
}

void TrajectorySummary::observe(double t, const std::vector<BodyForces>& forces) {
    for (Track& k : tracks_) {
        const BodyState& s = bodies_[k.index].state();
        if (k.events.empty()) k.speed.emplace_back(t, s.velocity.norm());
        if (k.events.size() == 1)
            k.rebound_height = std::max(k.rebound_height, (s.centre - k.events[0].centre).dot(up_));
        k.last_centre = s.centre;
        k.peak_hydrodynamic = std::max(k.peak_hydrodynamic, forces[k.index].forcing.norm());
        k.peak_contact = std::max(k.peak_contact, forces[k.index].loads.contact.norm());
        k.peak_impulse = std::max(k.peak_impulse, forces[k.index].loads.contact_impulse.norm());
    }
}

void TrajectorySummary::impacts(const std::vector<ContactEvent>& events) {
    for (const ContactEvent& e : events)
        for (Track& k : tracks_)
            if (e.body == k.name) k.events.push_back(e);
}

std::string TrajectorySummary::text() const {
    std::string out;
    char buf[512];
    for (const Track& k : tracks_) {
        std::snprintf(buf, sizeof buf, "body %s:\n", k.name.c_str());
        out += buf;
        if (!k.speed.empty()) {
            // Speed before the first impact: its maximum and its mean over the last 0.1 s of that flight.
            const double t_last = k.speed.back().first;
            double sum = 0.0, vmax = 0.0;
            int n = 0;
            for (const auto& [t, v] : k.speed) {
                vmax = std::max(vmax, v);
                if (t >= t_last - 0.1) sum += v, ++n;
            }
            std::snprintf(buf, sizeof buf,
                          "  speed before the first impact: max %.4g m/s, mean over its last 0.1 s %.4g m/s\n", vmax,
                          n ? sum / n : 0.0);
            out += buf;
        }
        if (k.events.empty()) {
            out += "  no impact\n";
        } else {
            const ContactEvent& e = k.events.front();
            std::snprintf(buf, sizeof buf,
                          "  first impact at t = %.4g s on %s: velocity (%.4g, %.4g) m/s -> (%.4g, %.4g) m/s\n", e.time,
                          e.obstacle.c_str(), e.velocity_before.x(), e.velocity_before.y(), e.velocity_after.x(),
                          e.velocity_after.y());
            out += buf;
            std::snprintf(buf, sizeof buf, "  rebound height (centre, against gravity) %.4g m\n", k.rebound_height);
            out += buf;
            const Vec2 across = -perp(up_);
            if (k.events.size() >= 2) {
                std::snprintf(buf, sizeof buf, "  runout to the second impact (t = %.4g s): %.4g m across gravity\n",
                              k.events[1].time, (k.events[1].centre - k.events[0].centre).dot(across));
            } else {
                std::snprintf(buf, sizeof buf, "  no second impact; travelled %.4g m across gravity since the first\n",
                              (k.last_centre - k.events[0].centre).dot(across));
            }
            out += buf;
            std::snprintf(buf, sizeof buf, "  impacts: %zu\n", k.events.size());
            out += buf;
        }
        std::snprintf(buf, sizeof buf,
                      "  peak hydrodynamic force %.4g N, peak contact force %.4g N, largest impact impulse %.4g N s\n",
                      k.peak_hydrodynamic, k.peak_contact, k.peak_impulse);
        out += buf;
    }
    return out;
}

}  // namespace chute
