#include "trajectory.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "cvode_errors.hpp"
#include "slide_motion.hpp"

namespace chute {

// A flight: y = (x, z, u, w) under `model` (the medium the block is in), spinning at `spin` since its last impact.
struct TrajectoryIntegrator::Flight {
    const TrajectoryIntegrator* self = nullptr;
    LumpedModelConfig model;
    GroundEffect ground;
    double block_size = 0.0;
    double spin = 0.0;
};

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double kValleyRestSpeed = 1e-3;  // m/s
constexpr long kMaxSlideEvents = 100000;

int rhs(sunrealtype, N_Vector y, N_Vector dy, void* data) {
    const auto& f = *static_cast<const TrajectoryIntegrator::Flight*>(data);
    const sunrealtype* Y = N_VGetArrayPointer(y);
    sunrealtype* D = N_VGetArrayPointer(dy);
    const Vec2 v(Y[2], Y[3]);
    Vec2 a = lumped_acceleration(f.model, v);
    if (f.model.fluid_density > 0.0 && f.ground.active()) {  // the squeezed water (ground_effect.hpp)
        const SlopeProfile& profile = f.self->profile();
        const Vec2 x(Y[0], Y[1]);
        const SlopeSegment& under = profile.segments()[profile.segment_at(x.x())];
        const Vec2& n = under.normal;
        const LumpedModelConfig& m = f.model;
        const double vn = v.dot(n), effective_mass = m.mass + m.added_mass_coefficient * m.fluid_density * m.volume;
        a -= 0.5 * m.fluid_density * m.drag_coefficient * m.frontal_area *
             f.ground.factor(n.dot(x - under.start), f.block_size) * std::abs(vn) * vn / effective_mass * n;
    }
    D[0] = Y[2];
    D[1] = Y[3];
    D[2] = a.x();
    D[3] = a.y();
    return 0;
}

// The ground (closing), the water level, the profile's two ends (leaving), and the apex of a bounce (the
// velocity normal to the ground under the block turning from rising to falling).
int roots(sunrealtype, N_Vector y, sunrealtype* g, void* data) {
    const SlopeProfile& profile = static_cast<const TrajectoryIntegrator::Flight*>(data)->self->profile();
    const sunrealtype* Y = N_VGetArrayPointer(y);
    const Vec2 x(Y[0], Y[1]);
    g[0] = profile.clearance(x);
    g[1] = x.y() - profile.water_level();
    g[2] = x.x() - profile.x_min();
    g[3] = profile.x_max() - x.x();
    g[4] = Vec2(Y[2], Y[3]).dot(profile.segments()[profile.segment_at(x.x())].normal);
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
    check(CVodeRootInit(cvode_, 5, roots), "CVodeRootInit");
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

void TrajectoryIntegrator::start(const Flight& flight, double t, const Vec2& x, const Vec2& v) {
    sunrealtype* Y = N_VGetArrayPointer(y_);
    Y[0] = x.x(), Y[1] = x.y(), Y[2] = v.x(), Y[3] = v.y();
    check(CVodeReInit(cvode_, t, y_), "CVodeReInit");
    check(CVodeSetUserData(cvode_, const_cast<Flight*>(&flight)), "CVodeSetUserData");
    check(CVodeSetStopTime(cvode_, settings_.end_time), "CVodeSetStopTime");
    int directions[5] = {-1, 0, -1, -1, -1};  // only a closing gap is an impact, only leaving the profile ends it
    check(CVodeSetRootDirection(cvode_, directions), "CVodeSetRootDirection");
}

// One trajectory as it runs: its block, its random numbers, the clock, the flight CVODE integrates, and the result
// as it builds up.
struct TrajectoryIntegrator::Run {
    const HazardBlock& block;
    const std::vector<double>& stations;
    std::mt19937_64& rng;
    bool record_path;
    LumpedModelConfig wet, dry;
    double radius, mass, inertia;
    Flight flight;
    double t = 0.0;
    double friction = 0.0;             // tan of the friction angle, drawn when a slide starts or meets a new material
    Vec2 flight_start = Vec2::Zero();  // where the flight began (its wake with it): the wet rebound's travel
    TrajectoryResult out;

    void finish(TrajectoryEnd end, const Vec2& x, const Vec2& v) {
        out.end = end;
        out.t = t;
        out.position = x;
        out.velocity = v;
    }
    // The block crosses station j: its largest speed, energies and height there are kept.
    void cross(std::size_t j, double speed, double spin, double height) {
        StationCrossing& c = out.stations[j];
        c.crossings += 1;
        c.speed = std::max(c.speed, speed);
        c.kinetic_energy = std::max(c.kinetic_energy, 0.5 * mass * speed * speed);
        c.rotational_energy = std::max(c.rotational_energy, 0.5 * inertia * spin * spin);
        c.height = std::max(c.height, height);
    }
    // The stations strictly after x0 up to x1 (in either direction), in the order the block meets them.
    template <class Visit>
    void stations_between(double x0, double x1, Visit visit) const {
        if (x0 == x1) return;
        auto it = std::upper_bound(stations.begin(), stations.end(), std::min(x0, x1));
        const auto last = std::upper_bound(stations.begin(), stations.end(), std::max(x0, x1));
        if (x1 > x0) {
            for (; it != last; ++it) visit(static_cast<std::size_t>(it - stations.begin()));
        } else {
            for (auto r = last; r != it;) visit(static_cast<std::size_t>(--r - stations.begin()));
        }
    }
};

TrajectoryResult TrajectoryIntegrator::run(const HazardBlock& block, const Vec2& start_position,
                                           const Vec2& start_velocity, const std::vector<double>& stations,
                                           std::mt19937_64& rng, bool record_path) {
    Run run{block,
            stations,
            rng,
            record_path,
            flight_model(block, true),
            flight_model(block, false),
            0.5 * block.size,
            block.mass(),
            block.moment_of_inertia(),
            {},
            0.0,
            0.0,
            Vec2::Zero(),
            {}};
    run.flight.self = this;
    run.flight.ground = settings_.ground_effect;
    run.flight.block_size = block.size;
    TrajectoryResult& out = run.out;
    out.stations.assign(stations.size(), {});
    out.max_speed = start_velocity.norm();

    if (profile_.clearance(start_position) < -1e-12 * (1.0 + start_position.norm()))  // on it to round-off is on it
        throw std::invalid_argument("the release point lies below the ground");
    // Released on the ground and not leaving it: a slide from the start (the velocity along the ground).
    if (const int k = profile_.segment_at(start_position.x());
        profile_.clearance(start_position) <= 1e-12 * (1.0 + start_position.norm()) &&
        start_velocity.dot(profile_.segments()[k].normal) <= 0.0) {
        const SlopeSegment& seg = profile_.segments()[k];
        if (!slide(run, k, (start_position - seg.start).dot(seg.tangent), start_velocity.dot(seg.tangent), true))
            return out;
    } else {
        fly(run, start_position, start_velocity, 0.0);
    }

    // The flight, step by step: stations crossed, then what stopped the step (the ground, the water level, the
    // top of a bounce, the profile's ends, the end time).
    sunrealtype* Y = N_VGetArrayPointer(y_);
    std::vector<int> found(5);
    for (;;) {
        const double t_before = run.t, x_before = Y[0];
        const int flag = CVode(cvode_, settings_.end_time, y_, &run.t, CV_ONE_STEP);
        check(flag, "CVode");
        const Vec2 x(Y[0], Y[1]), v(Y[2], Y[3]);
        if (flag != CV_ROOT_RETURN && profile_.clearance(x) < -1e-6)
            throw std::logic_error("hazard trajectory: the block passed under the ground at x = " +
                                   std::to_string(x.x()) + ", t = " + std::to_string(run.t) + " (an impact missed)");
        record_flight_crossings(run, t_before, x_before, x.x());
        out.max_speed = std::max(out.max_speed, v.norm());
        if (record_path) out.path.push_back({run.t, x, v, false});
        if (flag == CV_TSTOP_RETURN || run.t >= settings_.end_time) {
            run.finish(TrajectoryEnd::time_limit, x, v);
            return out;
        }
        if (flag != CV_ROOT_RETURN) continue;
        check(CVodeGetRootInfo(cvode_, found.data()), "CVodeGetRootInfo");
        if (found[2] || found[3]) {
            run.finish(found[3] ? TrajectoryEnd::past_end : TrajectoryEnd::past_start, x, v);
            return out;
        }
        if (found[0]) {
            if (!impact(run, x, v)) return out;
            continue;
        }
        if (found[1]) fly(run, x, v, run.flight.spin, true);                                 // into or out of the water
        if (found[4] && !found[1]) out.apexes.push_back({run.t, x, profile_.clearance(x)});  // flies on
    }
}

void TrajectoryIntegrator::fly(Run& run, const Vec2& from, const Vec2& v, double spin, bool crossing) {
    // At the water level (`crossing`) the medium is the one the block is going into.
    run.flight.model = (crossing ? v.y() < 0.0 : profile_.wet(from.y())) ? run.wet : run.dry;
    run.flight.spin = spin;
    run.flight_start = from;
    // CVODE finds an impact where the clearance changes sign, so a flight must start strictly above the ground:
    // off an impact or a vertex it starts on it (to round-off), and near a concave vertex the next segment may rise
    // across its path at once, inside CVODE's first step. Near a vertex ahead (what the first steps, under 10 ms,
    // can reach), a lift to 1e-12 of the position's size (a few times the round-off of the impact point) makes
    // that next impact a sign change; elsewhere the block leaves the segment it is on, and nothing is changed.
    Vec2 x = from;
    const double lift = 1e-12 * (1.0 + x.norm());
    const double ahead = x.x() + (v.x() >= 0.0 ? 1.0 : -1.0) * (0.01 * std::abs(v.x()) + 1e-6);
    if (const double c = profile_.clearance(x); c < lift && profile_.segment_at(ahead) != profile_.segment_at(x.x()))
        x += (lift - c) * profile_.segments()[profile_.segment_at(x.x())].normal;
    start(run.flight, run.t, x, v);
}

void TrajectoryIntegrator::record_flight_crossings(Run& run, double t0, double x0, double x1) {
    run.stations_between(x0, x1, [&](std::size_t j) {
        // The crossing time by secant on x(t) through CVODE's interpolant (x is nearly linear in a step).
        const double station = run.stations[j];
        double ta = t0, xa = x0, tb = run.t, xb = x1, tau = run.t;
        Vec2 x, v;
        for (int iter = 0; iter < 20; ++iter) {
            tau = ta + (station - xa) * (tb - ta) / (xb - xa);
            check(CVodeGetDky(cvode_, tau, 0, dky_), "CVodeGetDky");
            const sunrealtype* D = N_VGetArrayPointer(dky_);
            x = Vec2(D[0], D[1]), v = Vec2(D[2], D[3]);
            if (std::abs(x.x() - station) < 1e-9 * (1.0 + std::abs(station))) break;
            if ((x.x() - station) * (xa - station) > 0.0)
                ta = tau, xa = x.x();
            else
                tb = tau, xb = x.x();
        }
        run.cross(j, v.norm(), run.flight.spin, std::max(0.0, profile_.clearance(x)));
    });
}

bool TrajectoryIntegrator::impact(Run& run, const Vec2& x, const Vec2& v) {
    const int k = profile_.segment_at(x.x());
    const SlopeSegment& seg = profile_.segments()[k];
    const Material& m = materials_[seg.material];
    Vec2 n = seg.normal;
    if (m.roughness > 0.0) {  // the segment's angle perturbed, still facing the block
        std::normal_distribution<double> rough(0.0, m.roughness * std::numbers::pi / 180.0);
        for (int tries = 0; tries < 10; ++tries) {
            const double a = rough(run.rng);
            const Vec2 nr(std::cos(a) * n.x() - std::sin(a) * n.y(), std::sin(a) * n.x() + std::cos(a) * n.y());
            if (v.dot(nr) < 0.0) {
                n = nr;
                break;
            }
        }
    }
    const Vec2 tangent(n.y(), -n.x());
    const double vn = v.dot(n), vt = v.dot(tangent);
    const double rn = m.normal_restitution.sample(run.rng), rt = m.tangential_restitution.sample(run.rng);
    Impact e;
    e.t = run.t;
    e.position = x;
    e.velocity_before = v;
    e.wet = profile_.wet(x.y());
    e.stokes =
        e.wet ? impact_stokes_number(run.block.density, std::abs(vn), run.block.size, water_.viscosity) : infinity;
    // The wake grew over the flight's chord (a flight is nearly straight in water, at about its terminal speed).
    e.travel = (x - run.flight_start).norm() / run.block.size;
    // The ground's inclination at the impact (roughness included) and which way is down it.
    const double inclination = ground_inclination(n);
    const Vec2 downslope = n.x() >= 0.0 ? tangent : Vec2(-tangent);
    const Restitution r = e.wet ? wet_restitution(settings_.wet_rebound, rn, rt, e.stokes, e.travel, inclination,
                                                  impact_obliquity(vt, vn))
                                : Restitution{rn, rt};
    e.normal_restitution = r.normal;
    e.tangential_restitution = r.tangential;
    e.push = r.push * std::abs(vn);
    e.velocity_after = -r.normal * vn * n + r.tangential * vt * tangent + e.push * downslope;
    run.out.impacts.push_back(e);
    const Vec2 after = e.velocity_after;
    if (after.dot(seg.normal) < settings_.sliding_speed ||
        static_cast<int>(run.out.impacts.size()) >= settings_.max_impacts)
        return slide(run, k, (x - seg.start).dot(seg.tangent), after.dot(seg.tangent), true);
    fly(run, x, after, after.dot(seg.tangent) / run.radius);  // rolling off: omega = v_t' / (a / 2)
    return true;
}

bool TrajectoryIntegrator::slide(Run& run, int k, double s, double v, bool new_slide) {
    const auto& segments = profile_.segments();
    TrajectoryResult& out = run.out;
    int material = new_slide ? -1 : segments[k].material;  // the friction drawn on this material goes on
    bool in_water = profile_.wet((segments[k].start + s * segments[k].tangent).y());
    long events = 0;
    for (;;) {
        const SlopeSegment& seg = segments[k];
        if (seg.material != material) {
            material = seg.material;
            run.friction = std::tan(materials_[material].friction_angle.sample(run.rng) * std::numbers::pi / 180.0);
        }
        const LumpedModelConfig& m = in_water ? run.wet : run.dry;
        const double fluid_mass = m.fluid_density * m.volume, buoyant = m.mass - fluid_mass;
        const double along = buoyant * m.gravity.dot(seg.tangent), pressing = -buoyant * m.gravity.dot(seg.normal);
        const Vec2 here = seg.start + s * seg.tangent;
        if (v == 0.0 && std::abs(along) <= run.friction * pressing) {
            run.finish(TrajectoryEnd::rest, here, Vec2::Zero());
            return false;
        }
        const double d = v != 0.0 ? (v > 0.0 ? 1.0 : -1.0) : (along > 0.0 ? 1.0 : -1.0);
        const double effective_mass = m.mass + m.added_mass_coefficient * fluid_mass;
        const SlideMotion motion((d * along - run.friction * pressing) / effective_mass,
                                 0.5 * m.fluid_density * m.drag_coefficient * m.frontal_area / effective_mass,
                                 std::abs(v));
        // The next event along the direction of motion: the segment's end, the water level, rest.
        const double to_end = d > 0.0 ? seg.length - s : s;
        const double rise = d * seg.tangent.y();  // dz per metre travelled
        double to_water = infinity;
        if (rise != 0.0) {
            const double w = (profile_.water_level() - here.y()) / rise;
            if (w > 1e-12 * (1.0 + seg.length) && w < to_end) to_water = w;
        }
        const double to_stop = motion.stop_distance();
        const double go = std::min({to_end, to_water, to_stop});
        double tau = go == to_stop ? motion.stop_time() : motion.time_to(go);
        const bool timed_out = run.t + tau >= settings_.end_time;
        if (timed_out) tau = settings_.end_time - run.t;
        const double travelled = timed_out ? motion.distance(tau) : go;
        const Vec2 there = seg.start + (s + d * travelled) * seg.tangent;
        run.stations_between(here.x(), there.x(), [&](std::size_t j) {
            const double u =
                motion.speed(motion.time_to(std::abs(run.stations[j] - here.x()) / std::abs(seg.tangent.x())));
            run.cross(j, u, 0.0, 0.0);  // sliding, not rolling: no spin
        });
        const double u_end = go == to_stop && !timed_out ? 0.0 : motion.speed(tau);
        out.max_speed = std::max({out.max_speed, std::abs(v), u_end});
        if (run.record_path) {
            if (out.path.empty() || !out.path.back().sliding) out.path.push_back({run.t, here, v * seg.tangent, true});
            out.path.push_back({run.t + tau, there, d * u_end * seg.tangent, true});
        }
        run.t += tau;
        s += d * travelled;
        if (timed_out) {
            run.finish(TrajectoryEnd::time_limit, there, d * u_end * seg.tangent);
            return false;
        }
        v = d * u_end;
        if (go == to_stop) {
            v = 0.0;  // rests if the friction holds, else slides back
            continue;
        }
        if (go == to_water) {
            in_water = rise < 0.0;  // going down: into the water
            continue;
        }
        // The segment's end.
        const int next = k + static_cast<int>(d);
        const Vec2 velocity = v * seg.tangent;
        if (next < 0 || next >= static_cast<int>(segments.size())) {
            run.finish(d > 0.0 ? TrajectoryEnd::past_end : TrajectoryEnd::past_start, there, velocity);
            return false;
        }
        const SlopeSegment& ns = segments[next];
        if (velocity.dot(ns.normal) > 0.0) {  // convex: the ground falls away, the block takes off
            fly(run, there, velocity, 0.0);   // off a slide: no spin
            return true;
        }
        k = next;  // concave: it keeps its velocity along the new segment
        s = d > 0.0 ? 0.0 : ns.length;
        v = velocity.dot(ns.tangent);
        // In a valley (a vertex both of whose segments rise away from it) a block steeper than its friction rocks
        // from side to side, losing a factor cos(turn) at each crossing: infinitely many crossings in a finite
        // time. Below 1 mm/s at the bottom it rests there.
        if (std::abs(v) < kValleyRestSpeed && (d > 0.0 ? ns.tangent.y() > 0.0 : ns.tangent.y() < 0.0) &&
            (d > 0.0 ? seg.tangent.y() < 0.0 : seg.tangent.y() > 0.0)) {
            run.finish(TrajectoryEnd::rest, there, Vec2::Zero());
            return false;
        }
        if (++events > kMaxSlideEvents) {  // a guard: a slide that has not settled after that many events
            run.finish(TrajectoryEnd::rest, there, velocity);
            return false;
        }
    }
}

}  // namespace chute
