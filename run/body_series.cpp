#include "body_series.hpp"

namespace chute {

namespace {

using Row = std::vector<std::pair<std::string, double>>;

// One row of a body's series, named column by column, so that the header and the values cannot disagree.
// q is the force scale of the coefficients, N.
Row row(double t, const BodyState& s, const BodyForces& f, double q) {
    Row r;
    auto add = [&](const std::string& name, double value) { r.emplace_back(name, value); };
    // A vector and a torque as three columns: <x><name>, <y><name>, <m><name> (f: forces, j: impulses).
    auto triple = [&](const std::string& kind, const std::string& name, const Vec2& v, double torque) {
        add(kind + "x_" + name, v.x());
        add(kind + "y_" + name, v.y());
        add((kind == "f" ? "m_" : kind + "m_") + name, torque);
    };
    auto pair = [&](const std::string& x, const std::string& y, const Vec2& v) {
        add(x, v.x());
        add(y, v.y());
    };
    const SurfaceForces& sf = f.surface;
    const BodyLoads& loads = f.loads;
    add("t", t);
    pair("x", "y", s.centre);
    add("angle", s.angle);
    pair("u", "v", s.velocity);
    add("omega", s.angular_velocity);
    pair("ax", "ay", s.acceleration);
    add("alpha", s.angular_acceleration);
    triple("f", "forcing", f.forcing, f.forcing_torque);
    triple("f", "pressure", sf.pressure, sf.pressure_torque);
    triple("f", "viscous", sf.viscous, sf.viscous_torque);
    triple("f", "turbulent", sf.turbulent, sf.turbulent_torque);
    triple("f", "surface", sf.total(), sf.total_torque());
    for (const auto& [name, force] : {std::pair<std::string, Vec2>{"forcing", f.forcing},
                                      {"pressure", sf.pressure},
                                      {"viscous", sf.viscous},
                                      {"turbulent", sf.turbulent},
                                      {"surface", sf.total()}})
        pair("cx_" + name, "cy_" + name, force / q);
    add("max_slip", f.max_slip);
    add("rms_slip", f.rms_slip);
    pair("fx_gravity", "fy_gravity", loads.gravity);
    pair("fx_buoyancy", "fy_buoyancy", loads.buoyancy);
    triple("f", "contact", loads.contact, loads.contact_torque);
    triple("j", "contact", loads.contact_impulse, loads.contact_angular_impulse);
    triple("j", "water", loads.water_impulse, loads.water_angular_impulse);
    triple("f", "total", f.total(), f.total_torque());
    return r;
}

}  // namespace

std::vector<std::string> BodySeries::columns() {
    std::vector<std::string> names;
    for (const auto& [name, value] : row(0.0, BodyState{}, BodyForces{}, 1.0)) names.push_back(name);
    return names;
}

BodySeries::BodySeries(const Grid& grid, const std::filesystem::path& out_dir, const Carrier& carrier,
                       const CaseConfig& config, double restart_time)
    : bodies_(carrier.bodies()), density_(config.density), depth_(config.depth) {
    for (const Body& b : bodies_)
        series_.push_back(std::make_unique<TimeSeries>(grid, out_dir, columns(), restart_time, "body_" + b.name()));
}

void BodySeries::append(double t, const std::vector<BodyForces>& forces) {
    for (std::size_t k = 0; k < series_.size(); ++k) {
        const Body& body = bodies_[k];
        const double U = body.config().reference_velocity, L = body.config().reference_length;
        const double q = 0.5 * density_ * U * U * L * depth_;  // force scale, N
        std::vector<double> values;
        for (const auto& [name, value] : row(t, body.state(), forces[k], q)) values.push_back(value);
        series_[k]->append(values);
    }
}

void BodySeries::write_hdf5() {
    for (auto& s : series_) s->write_hdf5();
}

}  // namespace chute
