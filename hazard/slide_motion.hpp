#pragma once
// A block sliding along one straight segment in one direction, in closed form. With u >= 0 its speed along the
// direction of motion,
//   du/dt = a - b u^2,
// a the acceleration of the buoyant weight along the segment less the Coulomb friction on its part pressing on
// it, over the mass with its added mass, and b = rho_f C_D A / (2 (m + C_a rho_f V)) the drag's (0 dry). Then
//   b = 0:        u = u0 + a t,                                 s = u0 t + a t^2 / 2
//   a > 0, b > 0: u = U tanh(k t + c)  (u0 < U; coth if u0 > U), U = sqrt(a / b), k = sqrt(a b),
//                 s = ln(cosh(k t + c) / cosh c) / b            (sinh for coth)
//   a = 0:        u = u0 / (1 + b u0 t),                        s = ln(1 + b u0 t) / b
//   a < 0:        u = W tan(c - k t), W = sqrt(-a / b), k = sqrt(-a b), c = atan(u0 / W),
//                 s = ln(cos(c - k t) / cos c) / b, to rest at t = c / k
// and each s(t) inverts in closed form, so a slide needs no time stepping: its events (the segment's end, the
// water level, rest) and the stations it passes are found exactly.
#include <limits>

namespace chute {

class SlideMotion {
public:
    SlideMotion(double a, double b, double u0);
    double speed(double t) const;
    double distance(double t) const;
    // Time to cover distance s (infinity if it stops short of it).
    double time_to(double s) const;
    // How far it goes before it stops (infinity if it does not).
    double stop_distance() const;
    double stop_time() const;

private:
    enum class Kind { constant, drag_accelerating, drag_decelerating_above, drag_coasting, drag_decelerating };
    Kind kind_;
    double a_, b_, u0_;
    double k_ = 0.0, c_ = 0.0, U_ = 0.0;
};

}  // namespace chute
