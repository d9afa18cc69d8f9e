#include "contact_log.hpp"

#include <cstdio>
#include <fstream>
#include <string>

#include "hdf5_file.hpp"

namespace chute {

ContactLog::ContactLog(std::filesystem::path file, double restart_time) : file_(std::move(file)) {
    text_ =
        "t,body,obstacle,x,y,x_centre,y_centre,u_before,v_before,omega_before,u_after,v_after,omega_after,normal_"
        "restitution,"
        "tangential_restitution,rests,u_wet,v_wet,omega_wet,wet_normal_restitution,wet_tangential_restitution\n";
    if (file_.empty()) return;
    if (restart_time >= 0.0 && std::filesystem::exists(file_)) {
        std::ifstream in(file_);
        std::string line;
        std::getline(in, line);  // header
        while (std::getline(in, line))
            if (!line.empty() && std::stod(line.substr(0, line.find(','))) <= restart_time) text_ += line + "\n";
    }
    write_text_atomically(file_, text_);
}

void ContactLog::record(const std::vector<ContactEvent>& events) {
    if (file_.empty()) return;
    char row[1024];
    for (const ContactEvent& e : events) {
        std::snprintf(row, sizeof row,
                      "%.12g,%s,%s,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.6g,%.6g,%d,%.12g,%."
                      "12g,%.12g,%.6g,"
                      "%.6g\n",
                      e.time, e.body.c_str(), e.obstacle.c_str(), e.point.x(), e.point.y(), e.centre.x(), e.centre.y(),
                      e.velocity_before.x(), e.velocity_before.y(), e.angular_velocity_before, e.velocity_after.x(),
                      e.velocity_after.y(), e.angular_velocity_after, e.normal_restitution, e.tangential_restitution,
                      e.rests ? 1 : 0, e.velocity_wet.x(), e.velocity_wet.y(), e.angular_velocity_wet,
                      e.wet_normal_restitution, e.wet_tangential_restitution);
        text_ += row;
    }
    write_text_atomically(file_, text_);
}

}  // namespace chute
