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
namespace chute {

struct WetRebound {
    double kappa_n = 1.0, kappa_t = 1.0;
    double beta = 35.0;
};

// rho_s U a / (9 mu).
double impact_stokes_number(double block_density, double normal_speed, double size, double viscosity);

struct Restitution {
    double normal, tangential;
};
Restitution wet_restitution(const WetRebound& law, double rn, double rt, double stokes);

}  // namespace chute
