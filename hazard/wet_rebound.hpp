#pragma once
// The wet rebound law of the hazard analysis: the dry coefficients of the ground (Rn, Rt) scaled by what the
// water takes at an impact.
//
//   e_n = Rn kappa_n exp(-beta / St),   e_t = Rt kappa_t,   St = Re rho_s / (9 rho_f) = rho_s U a / (9 mu)
//
// St is the impact Stokes number (Turmel & Locat 2008, eq. 5; U the normal impact speed, a the block's size).
// exp(-beta / St) is the viscous loss of sphere experiments: the wet restitution collapses on e / e_dry =
// exp(-35 / St) for 10 < St < 10^4 (Legendre, Zenit, Daniel & Guiraud 2006, Chem. Eng. Sci. 61:3543, fitting
// Joseph et al. 2001 and Gondret et al. 2002), and goes to 1 above St ~ 1000, which is why the study took the
// dry coefficients in water. kappa_n and kappa_t are what that law leaves out and Chute's CFD measures at the
// study's St ~ 10^5: the momentum of the water that follows the block into the impact and brakes its rebound
// (docs/validation.md, "Hazard analysis"). kappa = 1 and beta = 35 give the literature's law; `chute
// calibrate` fits kappa from CFD runs. In air (dry) the law is Rn, Rt.
//
// The wake's growth: the water that follows the block builds up over the first few block sizes of travel (the
// wake of a body started from rest grows over several body lengths; Koumoutsakos & Leonard 1995, JFM 296:1), so
// an impact after a short fall loses less to it. Chute's bed runs show it: kappa_n 0.79, 0.69, 0.63 after 2.5,
// 4.7 and 8 block sizes of fall at nearly one impact speed, and the same law holds for a 1 m block (0.3 %)
// (docs/validation.md, "Hazard analysis"). With `wake_length` L > 0 an impact after `travel` block sizes in
// water since the block's flight began (release, water entry, the last impact, the end of a slide) takes
//
//   kappa_n(travel) = kappa_n + (kappa_n_start - kappa_n) exp(-travel / L)
//
// (kappa_n the developed wake's value); L = 0 keeps kappa_n whatever the travel.
//
// On a slope the water does more. Chute's 30 degree runs (docs/validation.md, "Hazard analysis") show two things a
// bed does not: the rebound's normal part grows with the impact's obliquity (kappa_n 0.81 for an impact along the
// normal, 1.0 at 24 degrees from it, 1.25 and more at 49: the flow the block drives along the bed under it lifts
// it), and the wake pushes the block along the slope, up it the longer the fall (the vortex shed on the upslope
// side comes down over the block after the impact), which no restitution of the incoming tangential velocity can
// carry (the impacts come in with 0.03-1 m/s along the slope). The slope's law, measured on one slope angle at
// several falls, gives the rebound
//
//   v_n' = -Rn kappa_n^s(impact angle) exp(-beta / St) v_n,   v_t' = Rt kappa_t v_t + push^s(travel) |v_n|
//
// (t down the slope; push^s < 0 turns the block up it; the impact angle is atan(|v_t| / |v_n|)). kappa_n^s and
// push^s are the CFD runs' own values, interpolated linearly and held beyond the first and last (no form is known
// for either). Between the bed (angle 0: the law above, no push) and the measured slope angle both are
// interpolated linearly in the ground's angle; steeper ground takes the measured angle's values (the 45 degree
// check shows what that misses).
#include <vector>

namespace chute {

struct SlopeRebound {
    double angle = 0.0;  // rad, from the horizontal; 0: no slope measured (the bed's law everywhere)
    std::vector<double> impact_angle, kappa_n;  // kappa_n^s at increasing impact angles (rad, from the normal)
    std::vector<double> travel, push;           // push^s at increasing travels (block sizes)
    bool measured() const { return angle > 0.0 && !impact_angle.empty() && !travel.empty(); }
    // How much of the slope's law ground inclined by `slope_angle` takes: 0 on the bed, 1 from the measured angle.
    double weight(double slope_angle) const;
    double kappa_n_at(double impact_angle) const;
    double push_at(double travel) const;
};

struct WetRebound {
    double kappa_n = 1.0, kappa_t = 1.0;
    double beta = 35.0;
    double kappa_n_start = 1.0, wake_length = 0.0;  // block sizes; 0: no history
    SlopeRebound slope;
    double normal_kappa(double travel) const;  // on the bed; travel in block sizes
    // On ground inclined by `slope_angle` (rad), an impact `impact_angle` (rad) from its normal: the bed's law and
    // the slope's, interpolated in the ground's angle.
    double normal_kappa(double travel, double slope_angle, double impact_angle) const;
    double push(double travel, double slope_angle) const;  // down the slope, over the normal impact speed
};

// The incoming velocity's angle from the ground's normal (rad), from its parts along (v_t) and normal to (v_n) it.
double impact_obliquity(double vt, double vn);

// rho_s U a / (9 mu).
double impact_stokes_number(double block_density, double normal_speed, double size, double viscosity);

struct Restitution {
    double normal, tangential;
    double push = 0.0;  // the water's push down the slope, over the normal impact speed
};
// `slope_angle`: the ground's inclination at the impact (rad, 0 for a horizontal bed); `impact_angle`: the incoming
// velocity's angle from the ground's normal (rad).
Restitution wet_restitution(const WetRebound& law, double rn, double rt, double stokes, double travel,
                            double slope_angle = 0.0, double impact_angle = 0.0);

}  // namespace chute
