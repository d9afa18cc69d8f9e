#pragma once
// An immersed body: its outline (body frame), where it is and how it moves (world frame).
//
// World position of a body-frame point r:  X = x_c + R(theta) r;   its velocity U = U_c + omega perp(X - x_c).
// x_c is the centre of area of a closed outline; planes and segments are static and live in the world frame.
#include <string>

#include "body_config.hpp"
#include "outline.hpp"

namespace chute {

struct BodyState {
    Vec2 centre = Vec2::Zero();
    double angle = 0.0;
    Vec2 velocity = Vec2::Zero();
    double angular_velocity = 0.0;
    Vec2 acceleration = Vec2::Zero();
    double angular_acceleration = 0.0;
};

// Kinematics prescribed by the case file, as functions of time.
class PrescribedMotion {
public:
    PrescribedMotion() = default;
    PrescribedMotion(const MotionConfig& m, const Vec2& centre0, double angle0)
        : m_(m), centre0_(centre0), angle0_(angle0) {}
    BodyState at(double t) const;
    bool moves() const { return m_.type != MotionType::fixed; }

private:
    MotionConfig m_;
    Vec2 centre0_ = Vec2::Zero();
    double angle0_ = 0.0;
};

// The longest step over which no point of an outline of the given reach (from its centre) travels further than
// `distance`, its velocity and acceleration held: v dt + a dt^2 / 2 <= distance, with v and a the centre's plus
// the spin's times the reach (the fastest point). Infinite for a body at rest that does not accelerate.
double longest_step(const Vec2& velocity, double angular_velocity, const Vec2& acceleration,
                    double angular_acceleration, double reach, double distance);

class Body {
public:
    // Builds the outline of the case's body; `domain_min/max` clip planes to the domain.
    Body(const BodyConfig& config, const Vec2& domain_min, const Vec2& domain_max);

    const std::string& name() const { return config_.name; }
    const BodyConfig& config() const { return config_; }
    const Outline& outline() const { return outline_; }
    const BodyState& state() const { return state_; }
    bool moves() const { return motion_.moves(); }
    // A free body is moved by the forces on it (rigidbody/), through set_state().
    bool free() const { return config_.motion.type == MotionType::free; }
    // Places the body at time t (prescribed motion; a free body stays where it is).
    void move_to(double t) {
        if (!free()) set_state(motion_.at(t));
    }
    void set_state(const BodyState& s) {
        state_ = s;
        cos_ = std::cos(s.angle);
        sin_ = std::sin(s.angle);
    }

    // The turn by the body's angle, its cosine and sine kept with the state (the sharp interface asks for a body-frame
    // point for every face near a surface, several times a step: sin and cos took 6 % of a moving square's run).
    Vec2 to_world(const Vec2& r) const { return state_.centre + direction_to_world(r); }
    Vec2 direction_to_world(const Vec2& d) const { return {cos_ * d.x() - sin_ * d.y(), sin_ * d.x() + cos_ * d.y()}; }
    Vec2 velocity_at(const Vec2& X) const {
        return state_.velocity + state_.angular_velocity * perp(X - state_.centre);
    }
    // The body-frame point of a world point X (the inverse of to_world).
    Vec2 to_body(const Vec2& X) const {
        const Vec2 r = X - state_.centre;
        return {cos_ * r.x() + sin_ * r.y(), -sin_ * r.x() + cos_ * r.y()};
    }
    bool contains(const Vec2& X) const { return outline_.contains(to_body(X)); }

    double area() const { return outline_.area(); }
    double polar_moment() const { return outline_.polar_moment(); }

private:
    BodyConfig config_;
    Outline outline_;
    PrescribedMotion motion_;
    BodyState state_;
    double cos_ = 1.0, sin_ = 0.0;  // of state_.angle
};

}  // namespace chute
