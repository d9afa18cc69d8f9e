#include "body_series.hpp"

namespace chute {

std::vector<std::string> BodySeries::columns() {
    return {"t",
            "x",
            "y",
            "angle",
            "u",
            "v",
            "omega",
            "ax",
            "ay",
            "alpha",
            "fx_forcing",
            "fy_forcing",
            "m_forcing",
            "fx_pressure",
            "fy_pressure",
            "m_pressure",
            "fx_viscous",
            "fy_viscous",
            "m_viscous",
            "fx_turbulent",
            "fy_turbulent",
            "m_turbulent",
            "fx_surface",
            "fy_surface",
            "m_surface",
            "cx_forcing",
            "cy_forcing",
            "cx_pressure",
            "cy_pressure",
            "cx_viscous",
            "cy_viscous",
            "cx_turbulent",
            "cy_turbulent",
            "cx_surface",
            "cy_surface",
            "max_slip",
            "rms_slip",
            "fx_gravity",
            "fy_gravity",
            "fx_buoyancy",
            "fy_buoyancy",
            "fx_contact",
            "fy_contact",
            "m_contact",
            "jx_contact",
            "jy_contact",
            "jm_contact",
            "jx_water",
            "jy_water",
            "jm_water",
            "fx_total",
            "fy_total",
            "m_total"};
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
        const BodyState& s = body.state();
        const BodyForces& f = forces[k];
        const SurfaceForces& sf = f.surface;
        const Vec2 surface = sf.total();
        const Vec2 total = f.total();
        const BodyLoads& loads = f.loads;
        const double U = body.config().reference_velocity, L = body.config().reference_length;
        const double q = 0.5 * density_ * U * U * L * depth_;  // force scale, N
        series_[k]->append({t,
                            s.centre.x(),
                            s.centre.y(),
                            s.angle,
                            s.velocity.x(),
                            s.velocity.y(),
                            s.angular_velocity,
                            s.acceleration.x(),
                            s.acceleration.y(),
                            s.angular_acceleration,
                            f.forcing.x(),
                            f.forcing.y(),
                            f.forcing_torque,
                            sf.pressure.x(),
                            sf.pressure.y(),
                            sf.pressure_torque,
                            sf.viscous.x(),
                            sf.viscous.y(),
                            sf.viscous_torque,
                            sf.turbulent.x(),
                            sf.turbulent.y(),
                            sf.turbulent_torque,
                            surface.x(),
                            surface.y(),
                            sf.total_torque(),
                            f.forcing.x() / q,
                            f.forcing.y() / q,
                            sf.pressure.x() / q,
                            sf.pressure.y() / q,
                            sf.viscous.x() / q,
                            sf.viscous.y() / q,
                            sf.turbulent.x() / q,
                            sf.turbulent.y() / q,
                            surface.x() / q,
                            surface.y() / q,
                            f.max_slip,
                            f.rms_slip,
                            loads.gravity.x(),
                            loads.gravity.y(),
                            loads.buoyancy.x(),
                            loads.buoyancy.y(),
                            loads.contact.x(),
                            loads.contact.y(),
                            loads.contact_torque,
                            loads.contact_impulse.x(),
                            loads.contact_impulse.y(),
                            loads.contact_angular_impulse,
                            loads.water_impulse.x(),
                            loads.water_impulse.y(),
                            loads.water_angular_impulse,
                            total.x(),
                            total.y(),
                            f.total_torque()});
    }
}

void BodySeries::write_hdf5() {
    for (auto& s : series_) s->write_hdf5();
}

}  // namespace chute
