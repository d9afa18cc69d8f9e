#include "trajectory.hpp"

#include "cvode_errors.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace chute {

// Flight: y = (x, z, u, w). Slide on `segment`: y = (s, v, 0, 0), s along the segment from its start, v the
// velocity along its tangent, `direction` the sign of v (the friction's is its opposite).
struct TrajectoryIntegrator::Phase {
    const TrajectoryIntegrator* self = nullptr;
    LumpedModelConfig model;  // the flight model in the medium the block is in
    bool sliding = false;
    int segment = 0;
    double direction = 1.0;
    double friction = 0.0;  // tan(friction angle)
    double spin = 0.0;      // rad/s (flight: since the last impact)
};

namespace {

constexpr double in_air = std::numeric_limits<double>::infinity();

// Along the segment: gravity and buoyancy, Coulomb friction on the buoyant weight pressing on it, drag, and the
// added mass.
double slide_acceleration(const LumpedModelConfig& m, const SlopeSegment& s, double v, double direction,
                          double friction) {
    const double buoyant = m.mass - m.fluid_density * m.volume;
    const double along = buoyant * m.gravity.dot(s.tangent);
    const double pressing = -buoyant * m.gravity.dot(s.normal);
    const double drag = 0.5 * m.fluid_density * m.drag_coefficient * m.frontal_area * std::abs(v) * v;
    return (along - direction * friction * pressing - drag) /
           (m.mass + m.added_mass_coefficient * m.fluid_density * m.volume);
}

int rhs(sunrealtype, N_Vector y, N_Vector dy, void* data) {
    const auto& p = *static_cast<const TrajectoryIntegrator::Phase*>(data);
    const sunrealtype* Y = N_VGetArrayPointer(y);
    sunrealtype* D = N_VGetArrayPointer(dy);
    if (p.sliding) {
        const SlopeSegment& s = p.self->profile().segments()[p.segment];
        D[0] = Y[1];
        D[1] = slide_acceleration(p.model, s, Y[1], p.direction, p.friction);
        D[2] = D[3] = 0.0;
        return 0;
    }
    const Vec2 a = lumped_acceleration(p.model, Vec2(Y[2], Y[3]));
    D[0] = Y[2];
    D[1] = Y[3];
    D[2] = a.x();
    D[3] = a.y();
    return 0;
}

// Flight: the ground (closing), the water level, the profile's two ends (leaving). Slide: the segment's end and
// start, the speed falling to zero, the water level.
int roots(sunrealtype, N_Vector y, sunrealtype* g, void* data) {
    const auto& p = *static_cast<const TrajectoryIntegrator::Phase*>(data);
    const SlopeProfile& profile = p.self->profile();
    const sunrealtype* Y = N_VGetArrayPointer(y);
    if (p.sliding) {
        const SlopeSegment& s = profile.segments()[p.segment];
        g[0] = Y[0] - s.length;
        g[1] = Y[0];
        g[2] = Y[1];
        g[3] = s.start.y() + Y[0] * s.tangent.y() - profile.water_level();
        return 0;
    }
    const Vec2 x(Y[0], Y[1]);
    g[0] = profile.clearance(x);
    g[1] = x.y() - profile.water_level();
    g[2] = x.x() - profile.x_min();
    g[3] = profile.x_max() - x.x();
    return 0;
}

void check(int flag, const char* what) { cvode_check(flag, what, "hazard trajectory"); }

}  // namespace

TrajectoryIntegrator::TrajectoryIntegrator(const SlopeProfile& profile, const std::vector<Material>& materials,
                                           const WaterProperties& water, const TrajectorySettings& settings)
    : profile_(profile), materials_(materials), water_(water), settings_(settings) {
    check(SUNContext_Create(nullptr, &context_), "SUNContext_Create");
    y_ = N_VNew_Serial(4, context_);
    dky_ = N_VNew_Serial(4, context_);
    N_VConst(0.0, y_);
    cvode_ = CVodeCreate(CV_ADAMS, context_);  // non-stiff
    solver_ = SUNNonlinSol_FixedPoint(y_, 0, context_);
    keep_cvode_errors(cvode_);
    check(CVodeInit(cvode_, rhs, 0.0, y_), "CVodeInit");
    check(CVodeSStolerances(cvode_, settings_.relative_tolerance, settings_.absolute_tolerance), "CVodeSStolerances");
    check(CVodeSetNonlinearSolver(cvode_, solver_), "CVodeSetNonlinearSolver");
    check(CVodeSetMaxNumSteps(cvode_, 1000000), "CVodeSetMaxNumSteps");
    check(CVodeRootInit(cvode_, 4, roots), "CVodeRootInit");
}

TrajectoryIntegrator::~TrajectoryIntegrator() {
    CVodeFree(&cvode_);
    SUNNonlinSolFree(solver_);
    N_VDestroy(y_);
    N_VDestroy(dky_);
    SUNContext_Free(&context_);
}

LumpedModelConfig TrajectoryIntegrator::flight_model(const HazardBlock& block, bool wet) const {
    LumpedModelConfig m;
    m.volume = std::pow(block.size, 3);
    m.mass = block.mass();
    m.frontal_area = block.size * block.size;
    m.fluid_density = wet ? water_.density : 0.0;
    m.drag_coefficient = settings_.drag_coefficient;
    m.added_mass_coefficient = settings_.added_mass_coefficient;
    m.gravity = Vec2(0.0, -settings_.gravity);
    m.relative_tolerance = settings_.relative_tolerance;
    m.absolute_tolerance = settings_.absolute_tolerance;
    return m;
}

Vec2 TrajectoryIntegrator::position(const Phase& p, const double* y) const {
    if (!p.sliding) return {y[0], y[1]};
    const SlopeSegment& s = profile_.segments()[p.segment];
    return s.start + y[0] * s.tangent;
}

Vec2 TrajectoryIntegrator::velocity(const Phase& p, const double* y) const {
    if (!p.sliding) return {y[2], y[3]};
    return y[1] * profile_.segments()[p.segment].tangent;
}

void TrajectoryIntegrator::start(const Phase& phase, double t, const double* y) {
    sunrealtype* Y = N_VGetArrayPointer(y_);
    std::copy(y, y + 4, Y);
    check(CVodeReInit(cvode_, t, y_), "CVodeReInit");
    check(CVodeSetUserData(cvode_, const_cast<Phase*>(&phase)), "CVodeSetUserData");
    check(CVodeSetStopTime(cvode_, settings_.end_time), "CVodeSetStopTime");
    // Flight: only a closing gap is an impact and only leaving the profile ends it; slide: the ends reached
    // moving towards them, the speed falling to zero from either side.
    int flight[4] = {-1, 0, -1, -1};
    int slide[4] = {1, -1, 0, 0};
    check(CVodeSetRootDirection(cvode_, phase.sliding ? slide : flight), "CVodeSetRootDirection");
}

TrajectoryResult TrajectoryIntegrator::run(const HazardBlock& block, const Vec2& start_position,
                                           const Vec2& start_velocity, const std::vector<double>& stations,
                                           std::mt19937_64& rng, bool record_path) {
    TrajectoryResult out;
    out.stations.assign(stations.size(), {});
    const double g = settings_.gravity, radius = 0.5 * block.size, mass = block.mass();
    const double inertia = block.moment_of_inertia();
    const LumpedModelConfig wet = flight_model(block, true), dry = flight_model(block, false);
    Phase phase;
    phase.self = this;
    sunrealtype* Y = N_VGetArrayPointer(y_);
    double t = 0.0;

    // A flight from x; at the water level (`crossing`) the medium is the one the block is going into.
    const auto fly = [&](const Vec2& x, const Vec2& v, double spin, bool crossing = false) {
        phase.sliding = false;
        phase.model = (crossing ? v.y() < 0.0 : profile_.wet(x.y())) ? wet : dry;
        phase.spin = spin;
        const double y[4] = {x.x(), x.y(), v.x(), v.y()};
        start(phase, t, y);
    };
    // Returns false if the block stops (it was at rest and the friction holds it).
    const auto slide = [&](int k, double s, double v, bool new_friction, bool crossing = false) {
        const SlopeSegment& seg = profile_.segments()[k];
        const Material& m = materials_[seg.material];
        if (new_friction || k != phase.segment)
            phase.friction = std::tan(m.friction_angle.sample(rng) * std::numbers::pi / 180.0);
        phase.sliding = true;
        phase.segment = k;
        const Vec2 x = seg.start + s * seg.tangent;
        phase.model = (crossing ? v * seg.tangent.y() < 0.0 : profile_.wet(x.y())) ? wet : dry;
        if (v == 0.0) {
            const double along = -g * seg.tangent.y(), pressing = g * seg.normal.y();
            if (std::abs(along) <= phase.friction * pressing) {
                Y[0] = s, Y[1] = 0.0;  // where it rests
                return false;
            }
            phase.direction = along > 0.0 ? 1.0 : -1.0;
        } else {
            phase.direction = v > 0.0 ? 1.0 : -1.0;
        }
        phase.spin = std::abs(v) / radius;
        const double y[4] = {s, v, 0.0, 0.0};
        start(phase, t, y);
        return true;
    };
    const auto finish = [&](TrajectoryEnd end) {
        out.end = end;
        out.t = t;
        out.position = position(phase, Y);
        out.velocity = velocity(phase, Y);
    };
    // The state at time tau inside the last step (CVODE's interpolant).
    const auto state_at = [&](double tau, Vec2& x, Vec2& v) {
        check(CVodeGetDky(cvode_, tau, 0, dky_), "CVodeGetDky");
        const sunrealtype* D = N_VGetArrayPointer(dky_);
        x = position(phase, D);
        v = velocity(phase, D);
    };
    const auto record_crossings = [&](double t0, double x0, double t1, double x1) {
        if (x0 == x1) return;
        const double lo = std::min(x0, x1), hi = std::max(x0, x1);
        auto it = std::upper_bound(stations.begin(), stations.end(), lo);
        for (; it != stations.end() && *it <= hi; ++it) {
            // The crossing time by secant on x(t) through the interpolant (x is nearly linear within a step).
            double ta = t0, xa = x0, tb = t1, xb = x1, tau = t1;
            Vec2 x, v;
            for (int iter = 0; iter < 20; ++iter) {
                tau = ta + (*it - xa) * (tb - ta) / (xb - xa);
                state_at(tau, x, v);
                if (std::abs(x.x() - *it) < 1e-9 * (1.0 + std::abs(*it))) break;
                if ((x.x() - *it) * (xa - *it) > 0.0)
                    ta = tau, xa = x.x();
                else
                    tb = tau, xb = x.x();
            }
            StationCrossing& c = out.stations[it - stations.begin()];
            const double speed = v.norm(), spin = phase.sliding ? speed / radius : phase.spin;
            c.crossings += 1;
            c.speed = std::max(c.speed, speed);
            c.kinetic_energy = std::max(c.kinetic_energy, 0.5 * mass * speed * speed);
            c.rotational_energy = std::max(c.rotational_energy, 0.5 * inertia * spin * spin);
            c.height = std::max(c.height, phase.sliding ? 0.0 : std::max(0.0, profile_.clearance(x)));
        }
    };

    if (profile_.clearance(start_position) < 0.0)
        throw std::invalid_argument("the release point lies below the ground");
    // Released on the ground and not leaving it: a slide from the start (the velocity along the ground).
    if (const int k = profile_.segment_at(start_position.x());
        profile_.clearance(start_position) <= 1e-12 * (1.0 + start_position.norm()) &&
        start_velocity.dot(profile_.segments()[k].normal) <= 0.0) {
        const SlopeSegment& seg = profile_.segments()[k];
        phase.segment = -1;
        if (!slide(k, (start_position - seg.start).dot(seg.tangent), start_velocity.dot(seg.tangent), true)) {
            finish(TrajectoryEnd::rest);
            return out;
        }
    } else {
        fly(start_position, start_velocity, 0.0);
    }
    out.max_speed = start_velocity.norm();
    std::vector<int> found(4);
    for (;;) {
        const double t_before = t;
        const Vec2 x_before = position(phase, Y);
        const int flag = CVode(cvode_, settings_.end_time, y_, &t, CV_ONE_STEP);
        check(flag, "CVode");
        const Vec2 x = position(phase, Y), v = velocity(phase, Y);
        record_crossings(t_before, x_before.x(), t, x.x());
        out.max_speed = std::max(out.max_speed, v.norm());
        if (record_path) out.path.push_back({t, x, v, phase.sliding});
        if (flag == CV_TSTOP_RETURN || t >= settings_.end_time) {
            finish(TrajectoryEnd::time_limit);
            return out;
        }
        if (flag != CV_ROOT_RETURN) continue;
        check(CVodeGetRootInfo(cvode_, found.data()), "CVodeGetRootInfo");
        if (!phase.sliding) {
            if (found[2] || found[3]) {
                finish(found[3] ? TrajectoryEnd::past_end : TrajectoryEnd::past_start);
                return out;
            }
            if (found[0]) {  // an impact
                const int k = profile_.segment_at(x.x());
                const SlopeSegment& seg = profile_.segments()[k];
                const Material& m = materials_[seg.material];
                Vec2 n = seg.normal;
                if (m.roughness > 0.0) {  // the segment's angle perturbed, still facing the block
                    std::normal_distribution<double> rough(0.0, m.roughness * std::numbers::pi / 180.0);
                    for (int tries = 0; tries < 10; ++tries) {
                        const double a = rough(rng);
                        const Vec2 nr(std::cos(a) * n.x() - std::sin(a) * n.y(),
                                      std::sin(a) * n.x() + std::cos(a) * n.y());
                        if (v.dot(nr) < 0.0) {
                            n = nr;
                            break;
                        }
                    }
                }
                const Vec2 tangent(n.y(), -n.x());
                const double vn = v.dot(n), vt = v.dot(tangent);
                const double rn = m.normal_restitution.sample(rng), rt = m.tangential_restitution.sample(rng);
                Impact e;
                e.t = t;
                e.position = x;
                e.velocity_before = v;
                e.wet = profile_.wet(x.y());
                e.stokes = e.wet ? impact_stokes_number(block.density, std::abs(vn), block.size, water_.viscosity)
                                 : in_air;
                const Restitution r = e.wet ? wet_restitution(settings_.wet_rebound, rn, rt, e.stokes)
                                            : Restitution{rn, rt};
                e.normal_restitution = r.normal;
                e.tangential_restitution = r.tangential;
                e.velocity_after = -r.normal * vn * n + r.tangential * vt * tangent;
                out.impacts.push_back(e);
                const Vec2 after = e.velocity_after;
                if (after.dot(seg.normal) < settings_.sliding_speed ||
                    static_cast<int>(out.impacts.size()) >= settings_.max_impacts) {
                    if (!slide(k, (x - seg.start).dot(seg.tangent), after.dot(seg.tangent), true)) {
                        finish(TrajectoryEnd::rest);
                        return out;
                    }
                } else {
                    fly(x, after, after.dot(seg.tangent) / radius);
                }
                continue;
            }
            if (found[1]) fly(x, v, phase.spin, true);  // into or out of the water
            continue;
        }
        // Sliding.
        const int k = phase.segment;
        const SlopeSegment& seg = profile_.segments()[k];
        const double vs = Y[1];
        if (found[0] || found[1]) {  // off the segment's end or start
            const bool forward = found[0] != 0;
            const int next = k + (forward ? 1 : -1);
            if (next < 0 || next >= static_cast<int>(profile_.segments().size())) {
                finish(forward ? TrajectoryEnd::past_end : TrajectoryEnd::past_start);
                return out;
            }
            const SlopeSegment& ns = profile_.segments()[next];
            const Vec2 vel = vs * seg.tangent;
            if (vel.dot(ns.normal) > 0.0) {  // a convex vertex: the ground falls away, the block takes off
                fly(forward ? seg.end : seg.start, vel, phase.spin);
            } else if (!slide(next, forward ? 0.0 : ns.length, vel.dot(ns.tangent), false)) {
                finish(TrajectoryEnd::rest);
                return out;
            }
            continue;
        }
        if (found[2]) {  // stopped: the friction holds it, or it slides back
            if (!slide(k, Y[0], 0.0, false)) {
                finish(TrajectoryEnd::rest);
                return out;
            }
            continue;
        }
        if (found[3]) slide(k, Y[0], vs, false, true);  // into or out of the water (the same slide, a new medium)
    }
}

}  // namespace chute
