#include "hazard_outputs.hpp"

#include <algorithm>
#include <cstdio>
#include <numbers>

#include "calibration_range.hpp"
#include "hdf5_file.hpp"
#include "text_file.hpp"

namespace chute {

namespace {

const char* end_name(TrajectoryEnd e) {
    switch (e) {
        case TrajectoryEnd::rest:
            return "rest";
        case TrajectoryEnd::past_end:
            return "past_end";
        case TrajectoryEnd::past_start:
            return "past_start";
        case TrajectoryEnd::time_limit:
            return "time_limit";
    }
    return "?";
}

}  // namespace

std::string format_hazard_summary(const HazardCase& c, const HazardSummary& s, double seconds, int ranks) {
    const SlopeProfile profile = c.profile();
    std::string t = printf_text(
        "hazard '%s': %ld trajectories over %zu segments in %.2f s on %d rank(s) (%.0f per s)\n", c.name.c_str(),
        s.trajectories, profile.segments().size(), seconds, ranks, s.trajectories / std::max(seconds, 1e-9));
    const WetRebound& law = c.settings.wet_rebound;
    t += printf_text(
        "  water level %s; model C_D %.4g, C_a %.4g, kappa_n %.4g%s, kappa_t %.4g, beta %.4g%s\n",
        c.water_level > -1e29 ? printf_text("%.6g m", c.water_level).c_str() : "none (dry)",
        c.settings.drag_coefficient, c.settings.added_mass_coefficient, law.kappa_n,
        law.wake_length > 0.0
            ? printf_text(" (%.4g with no wake, over %.3g block sizes)", law.kappa_n_start, law.wake_length).c_str()
            : "",
        law.kappa_t, law.beta, c.calibration.empty() ? "" : (" (" + c.calibration + ")").c_str());
    if (const SlopeRebound& slope = law.slope; slope.measured()) {
        const auto [kappa_low, kappa_high] = std::minmax_element(slope.kappa_n.begin(), slope.kappa_n.end());
        const auto [push_low, push_high] = std::minmax_element(slope.push.begin(), slope.push.end());
        t += printf_text(
            "  slope law measured at %.3g degrees: kappa_n %.3g to %.3g over impact angles %.3g-%.3g degrees, "
            "push %+.3g to %+.3g of the normal impact speed over travels %.3g-%.3g block sizes\n",
            slope.angle * 180.0 / std::numbers::pi, *kappa_low, *kappa_high,
            slope.impact_angle.front() * 180.0 / std::numbers::pi, slope.impact_angle.back() * 180.0 / std::numbers::pi,
            *push_low, *push_high, slope.travel.front(), slope.travel.back());
    }
    for (const std::string& w : calibration_range_warnings(c)) t += "  warning: " + w + "\n";
    if (const GroundEffect& g = c.settings.ground_effect; g.active())
        t += printf_text(
            "  ground effect: the normal drag times %.3g at the ground, falling by e every %.3g block sizes\n",
            g.strength, g.decay);
    t += printf_text("  ends: %ld at rest, %ld past the profile's end, %ld past its start, %ld still moving at %g s\n",
                     s.ends[0], s.ends[1], s.ends[2], s.ends[3], c.settings.end_time);
    t += printf_text("  stopping x: p50 %.6g, p90 %.6g, p95 %.6g, p99 %.6g, max %.6g m\n", s.stop_p50, s.stop_p90,
                     s.stop_p95, s.stop_p99, s.stop_max);
    for (const CollectorSummary& k : s.collectors)
        t += printf_text("  collector %s (x %.6g m, height %.3g m): %ld pass, %ld hit (probability %.4g)%s\n",
                         k.collector.name.c_str(), k.collector.x, k.collector.height, k.passing, k.hits,
                         k.hit_probability,
                         k.hits ? printf_text("; hit energy mean %.4g J, p50 %.4g, p95 %.4g, max %.4g", k.energy_mean,
                                              k.energy_p50, k.energy_p95, k.energy_max)
                                      .c_str()
                                : "");
    return t;
}

void write_hazard_outputs(const HazardCase& c, const HazardResults& r, const HazardSummary& s,
                          const std::string& case_text, int ranks, const std::filesystem::path& out) {
    std::filesystem::create_directories(out);
    write_text_atomically(out / "case.yaml", case_text);
    write_text_atomically(out / "summary.txt", format_hazard_summary(c, s, r.seconds, ranks));

    std::string t =
        "index,size,density,release_x,release_z,release_u,release_w,end,time,stop_x,stop_z,max_speed,"
        "impacts\n";
    for (std::size_t i = 0; i < r.outcomes.size(); ++i) {
        const TrajectoryOutcome& o = r.outcomes[i];
        t += printf_text("%zu,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%s,%.9g,%.9g,%.9g,%.9g,%d\n", i, o.size, o.density,
                         o.release.x(), o.release.y(), o.release_velocity.x(), o.release_velocity.y(), end_name(o.end),
                         o.time, o.stop.x(), o.stop.y(), o.max_speed, o.impacts);
    }
    write_text_atomically(out / "trajectories.csv", t);

    t = "x,ground_z,reach_probability,passing_fraction,speed_mean,speed_p95,kinetic_mean,kinetic_p95,rotational_mean,"
        "rotational_p95,height_mean,height_p95\n";
    for (const StationSummary& st : s.stations)
        t +=
            printf_text("%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", st.x, st.ground, st.reach,
                        st.passing_fraction, st.speed.mean, st.speed.p95, st.kinetic_energy.mean, st.kinetic_energy.p95,
                        st.rotational_energy.mean, st.rotational_energy.p95, st.height.mean, st.height.p95);
    write_text_atomically(out / "stations.csv", t);

    t = "name,x,height,passing,hits,hit_probability,energy_mean,energy_p50,energy_p95,energy_max\n";
    for (const CollectorSummary& k : s.collectors)
        t += printf_text("%s,%.9g,%.9g,%ld,%ld,%.9g,%.9g,%.9g,%.9g,%.9g\n", k.collector.name.c_str(), k.collector.x,
                         k.collector.height, k.passing, k.hits, k.hit_probability, k.energy_mean, k.energy_p50,
                         k.energy_p95, k.energy_max);
    write_text_atomically(out / "collectors.csv", t);

    t = "trajectory,t,x,z,speed,sliding\n";
    for (const auto& p : r.paths)
        t += printf_text("%.0f,%.9g,%.9g,%.9g,%.9g,%.0f\n", p[0], p[1], p[2], p[3], p[4], p[5]);
    write_text_atomically(out / "paths.csv", t);

    write_atomically(out / "hazard.h5", [&](const std::filesystem::path& tmp) {
        Hdf5File h = Hdf5File::create(tmp);
        const std::size_t N = r.outcomes.size(), S = r.stations.size(), C = c.collectors.size();
        const auto column = [&](auto get) {
            std::vector<double> v(N);
            for (std::size_t i = 0; i < N; ++i) v[i] = get(r.outcomes[i]);
            return v;
        };
        h.write("trajectories/size", column([](const auto& o) { return o.size; }));
        h.write("trajectories/density", column([](const auto& o) { return o.density; }));
        h.write("trajectories/release_x", column([](const auto& o) { return o.release.x(); }));
        h.write("trajectories/release_z", column([](const auto& o) { return o.release.y(); }));
        h.write("trajectories/end", column([](const auto& o) { return static_cast<double>(o.end); }));
        h.write("trajectories/time", column([](const auto& o) { return o.time; }));
        h.write("trajectories/stop_x", column([](const auto& o) { return o.stop.x(); }));
        h.write("trajectories/stop_z", column([](const auto& o) { return o.stop.y(); }));
        h.write("trajectories/max_speed", column([](const auto& o) { return o.max_speed; }));
        h.write("trajectories/impacts", column([](const auto& o) { return static_cast<double>(o.impacts); }));
        h.set_string_attribute("trajectories/end", "meaning", "0 rest, 1 past the end, 2 past the start, 3 moving");
        h.write("stations/x", r.stations);
        if (N > 0 && S > 0) {
            h.write("stations/speed", r.speed, N, S);
            h.write("stations/kinetic_energy", r.kinetic_energy, N, S);
            h.write("stations/rotational_energy", r.rotational_energy, N, S);
            h.write("stations/height", r.height, N, S);
        }
        std::vector<double> reach, ground;
        for (const StationSummary& st : s.stations) reach.push_back(st.reach), ground.push_back(st.ground);
        h.write("stations/reach_probability", reach);
        h.write("stations/ground_z", ground);
        if (N > 0 && C > 0) {
            h.write("collectors/speed", r.collector_speed, N, C);
            h.write("collectors/energy", r.collector_energy, N, C);
            h.write("collectors/height", r.collector_height, N, C);
        }
        std::vector<double> px, pz;
        for (const Vec2& p : c.profile_points) px.push_back(p.x()), pz.push_back(p.y());
        h.write("profile/x", px);
        h.write("profile/z", pz);
        h.write_double("profile/water_level", c.water_level);
        h.write_int("seed", static_cast<long long>(c.seed));
        h.write_double("seconds", r.seconds);
        h.set_string_attribute("/", "case", case_text);
        h.close();
    });
}

}  // namespace chute
