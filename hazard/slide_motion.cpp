#include "slide_motion.hpp"

#include <cmath>

namespace chute {

namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();
}

SlideMotion::SlideMotion(double a, double b, double u0) : a_(a), b_(b), u0_(u0) {
    if (b <= 0.0) {
        kind_ = Kind::constant;
    } else if (a > 0.0) {
        U_ = std::sqrt(a / b), k_ = std::sqrt(a * b);
        if (u0 < U_) {
            kind_ = Kind::drag_accelerating;
            c_ = std::atanh(u0 / U_);
        } else {  // at or above the terminal speed: slows towards it (u0 = U stays: coth(inf) = 1)
            kind_ = Kind::drag_decelerating_above;
            c_ = u0 > U_ ? std::atanh(U_ / u0) : infinity;  // acoth(u0 / U)
        }
    } else if (a == 0.0) {
        kind_ = Kind::drag_coasting;
    } else {
        kind_ = Kind::drag_decelerating;
        U_ = std::sqrt(-a / b), k_ = std::sqrt(-a * b);
        c_ = std::atan(u0 / U_);
    }
}

double SlideMotion::speed(double t) const {
    switch (kind_) {
        case Kind::constant:
            return std::max(0.0, u0_ + a_ * t);
        case Kind::drag_accelerating:
            return U_ * std::tanh(k_ * t + c_);
        case Kind::drag_decelerating_above:
            return std::isinf(c_) ? U_ : U_ / std::tanh(k_ * t + c_);
        case Kind::drag_coasting:
            return u0_ / (1.0 + b_ * u0_ * t);
        case Kind::drag_decelerating:
            return t >= c_ / k_ ? 0.0 : U_ * std::tan(c_ - k_ * t);
    }
    return 0.0;
}

double SlideMotion::distance(double t) const {
    switch (kind_) {
        case Kind::constant:
            if (a_ < 0.0 && t > -u0_ / a_) t = -u0_ / a_;
            return u0_ * t + 0.5 * a_ * t * t;
        case Kind::drag_accelerating:
            // ln(cosh(x) / cosh(c)) without overflow: x - c + ln((1 + e^-2x) / (1 + e^-2c)).
            return (k_ * t + std::log1p(std::exp(-2.0 * (k_ * t + c_))) - std::log1p(std::exp(-2.0 * c_))) / b_;
        case Kind::drag_decelerating_above:
            if (std::isinf(c_)) return U_ * t;
            return (k_ * t + std::log(-std::expm1(-2.0 * (k_ * t + c_))) - std::log(-std::expm1(-2.0 * c_))) / b_;
        case Kind::drag_coasting:
            return std::log1p(b_ * u0_ * t) / b_;
        case Kind::drag_decelerating:
            if (t > c_ / k_) t = c_ / k_;
            return std::log(std::cos(c_ - k_ * t) / std::cos(c_)) / b_;
    }
    return 0.0;
}

double SlideMotion::stop_distance() const {
    switch (kind_) {
        case Kind::constant:
            return a_ < 0.0 ? u0_ * u0_ / (-2.0 * a_) : (u0_ == 0.0 && a_ == 0.0 ? 0.0 : infinity);
        case Kind::drag_decelerating:
            return -std::log(std::cos(c_)) / b_;
        default:
            return u0_ == 0.0 && kind_ == Kind::drag_coasting ? 0.0 : infinity;
    }
}

double SlideMotion::stop_time() const {
    switch (kind_) {
        case Kind::constant:
            return a_ < 0.0 ? u0_ / -a_ : (u0_ == 0.0 && a_ == 0.0 ? 0.0 : infinity);
        case Kind::drag_decelerating:
            return c_ / k_;
        default:
            return u0_ == 0.0 && kind_ == Kind::drag_coasting ? 0.0 : infinity;
    }
}

double SlideMotion::time_to(double s) const {
    if (s <= 0.0) return 0.0;
    if (s > stop_distance()) return s <= stop_distance() * (1.0 + 1e-12) ? stop_time() : infinity;
    switch (kind_) {
        case Kind::constant:
            if (a_ == 0.0) return s / u0_;
            // u0 t + a t^2 / 2 = s, the first root, in the form that keeps its digits.
            return 2.0 * s / (u0_ + std::sqrt(std::max(0.0, u0_ * u0_ + 2.0 * a_ * s)));
        case Kind::drag_accelerating: {
            // cosh(k t + c) = cosh(c) e^{b s}, in logarithms (long segments would overflow): ln cosh x =
            // x + ln(1 + e^-2x) - ln 2, and acosh(y) = ln(2 y) to round-off once y > e^20.
            const double log_y = c_ + std::log1p(std::exp(-2.0 * c_)) - std::log(2.0) + b_ * s;
            return ((log_y > 20.0 ? log_y + std::log(2.0) : std::acosh(std::exp(log_y))) - c_) / k_;
        }
        case Kind::drag_decelerating_above: {
            if (std::isinf(c_)) return s / U_;
            const double log_y = c_ + std::log(-std::expm1(-2.0 * c_)) - std::log(2.0) + b_ * s;  // ln(sinh(c) e^{bs})
            return ((log_y > 20.0 ? log_y + std::log(2.0) : std::asinh(std::exp(log_y))) - c_) / k_;
        }
        case Kind::drag_coasting:
            return std::expm1(b_ * s) / (b_ * u0_);
        case Kind::drag_decelerating:
            return (c_ - std::acos(std::min(1.0, std::cos(c_) * std::exp(b_ * s)))) / k_;
    }
    return infinity;
}

}  // namespace chute
