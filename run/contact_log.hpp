#pragma once
// The contact-event log of a run: out_dir/contacts.csv, one row per impact, rewritten atomically (write to a
// temporary file, then rename) after each impact, so a run that stops keeps every event written so far.
//   t, body, obstacle, x, y (contact point), x_centre, y_centre, u_before, v_before, omega_before, u_after, v_after,
//   omega_after, normal_restitution, tangential_restitution (effective, at the contact point), rests (1: came to rest)
#include <filesystem>
#include <string>
#include <vector>

#include "rebound.hpp"

namespace chute {

class ContactLog {
public:
    // An empty path (ranks other than 0) records nothing. restart_time >= 0: a restarted run keeps the
    // events of an existing log up to that time.
    ContactLog(std::filesystem::path file, double restart_time);
    void record(const std::vector<ContactEvent>& events);

private:
    std::filesystem::path file_;
    std::string text_;
};

}  // namespace chute
