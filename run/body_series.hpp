#pragma once
// One time series per immersed body: out_dir/body_<name>.csv and .h5 (written like timeseries.csv).
//
// Columns (SI units; angles in rad; forces on the body in N for the case's depth, torques in N m about
// the body's centre; coefficients C = F / (0.5 rho U^2 L depth) with the body's reference U and L):
//   t, x, y, angle, u, v, omega, ax, ay, alpha                      kinematics of the centre
//   fx_forcing, fy_forcing, m_forcing                                (a) from the forcing sum (body-fitted: the
//                                                                    momentum the fluxes carried across the sides;
//                                                                    its torque is (b)'s)
//   fx_pressure, fy_pressure, m_pressure, fx_viscous, fy_viscous, m_viscous,
//   fx_turbulent, fy_turbulent, m_turbulent (k-epsilon: Reynolds stress; 0 laminar),
//   fx_surface, fy_surface, m_surface                                (b) surface stress, by kind and total
//   cx_forcing, cy_forcing, cx_pressure, cy_pressure, cx_viscous, cy_viscous, cx_turbulent, cy_turbulent,
//   cx_surface, cy_surface
//   max_slip, rms_slip                                               no-slip error at the markers (m/s;
//                                                                    0 body-fitted: the no-slip is exact there)
//   fx_gravity, fy_gravity, fx_buoyancy, fy_buoyancy,               free bodies (zero otherwise): gravity,
//   fx_contact, fy_contact, m_contact,                               buoyancy, contact between impacts
//   jx_contact, jy_contact, jm_contact, jx_water, jy_water, jm_water  an impact's impulses (N s, N m s)
//   fx_total, fy_total, m_total                                      total
// For a free body (a) is the hydrodynamic force that moved it (body/body_forces.hpp).
#include <memory>
#include <vector>

#include "carrier.hpp"
#include "case_config.hpp"
#include "timeseries.hpp"

namespace chute {

class BodySeries {
public:
    BodySeries(const Grid& grid, const std::filesystem::path& out_dir, const Carrier& carrier, const CaseConfig& config,
               double restart_time);
    void append(double t, const std::vector<BodyForces>& forces);
    void write_hdf5();

    static std::vector<std::string> columns();

private:
    const std::vector<Body>& bodies_;
    double density_, depth_;
    std::vector<std::unique_ptr<TimeSeries>> series_;
};

}  // namespace chute
