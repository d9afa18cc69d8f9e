#include "lumped_model.hpp"

#include "cvode_errors.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace chute {

namespace {

struct Problem {
    const LumpedModelConfig& model;
    const Outline& outline;
    const std::vector<Obstacle>& obstacles;
    double angle;
};

// y = (x, y, u, v).
int rhs(sunrealtype, N_Vector y, N_Vector dy, void* data) {
    const sunrealtype* Y = N_VGetArrayPointer(y);
    sunrealtype* D = N_VGetArrayPointer(dy);
    const Vec2 a = lumped_acceleration(static_cast<Problem*>(data)->model, Vec2(Y[2], Y[3]));
    D[0] = Y[2];
    D[1] = Y[3];
    D[2] = a.x();
    D[3] = a.y();
    return 0;
}

BodyState state_of(const sunrealtype* Y, double angle) {
    BodyState s;
    s.centre = Vec2(Y[0], Y[1]);
    s.velocity = Vec2(Y[2], Y[3]);
    s.angle = angle;
    return s;
}

int gaps(sunrealtype, N_Vector y, sunrealtype* g, void* data) {
    const auto* p = static_cast<Problem*>(data);
    const BodyState s = state_of(N_VGetArrayPointer(y), p->angle);
    for (std::size_t k = 0; k < p->obstacles.size(); ++k) g[k] = gap(p->outline, s, p->obstacles[k]).distance;
    return 0;
}

void check(int flag, const char* what) { cvode_check(flag, what, "lumped model"); }

}  // namespace

Vec2 lumped_acceleration(const LumpedModelConfig& m, const Vec2& v) {
    const double fluid_mass = m.fluid_density * m.volume;
    const Vec2 w = v - m.current;
    const Vec2 force =
        (m.mass - fluid_mass) * m.gravity - 0.5 * m.fluid_density * m.drag_coefficient * m.frontal_area * w.norm() * w;
    return force / (m.mass + m.added_mass_coefficient * fluid_mass);
}

LumpedTrajectory run_lumped_model(const LumpedModelConfig& model, const Outline& outline, const BodyState& start,
                                  const std::vector<Obstacle>& obstacles, const ContactConfig& contact, double t_end,
                                  double output_interval) {
    LumpedTrajectory out;
    Problem problem{model, outline, obstacles, start.angle};
    RigidInertia inertia;  // the lumped block does not turn
    inertia.mass = model.mass;
    inertia.inertia = 1.0;
    inertia.locked = {false, false, true};

    SUNContext ctx = nullptr;
    check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
    N_Vector y = N_VNew_Serial(4, ctx);
    sunrealtype* Y = N_VGetArrayPointer(y);
    Y[0] = start.centre.x(), Y[1] = start.centre.y(), Y[2] = start.velocity.x(), Y[3] = start.velocity.y();
    void* mem = CVodeCreate(CV_ADAMS, ctx);  // non-stiff
    SUNNonlinearSolver nls = SUNNonlinSol_FixedPoint(y, 0, ctx);
    double t = 0.0;
    try {
        keep_cvode_errors(mem);
        check(CVodeInit(mem, rhs, t, y), "CVodeInit");
        check(CVodeSStolerances(mem, model.relative_tolerance, model.absolute_tolerance), "CVodeSStolerances");
        check(CVodeSetNonlinearSolver(mem, nls), "CVodeSetNonlinearSolver");
        check(CVodeSetUserData(mem, &problem), "CVodeSetUserData");
        check(CVodeSetMaxNumSteps(mem, 1000000), "CVodeSetMaxNumSteps");
        const int n = static_cast<int>(obstacles.size());
        if (n > 0) {
            check(CVodeRootInit(mem, n, gaps), "CVodeRootInit");
            std::vector<int> falling(n, -1);  // only a gap that closes is an impact
            check(CVodeSetRootDirection(mem, falling.data()), "CVodeSetRootDirection");
        }
        out.samples.push_back({t, start.centre, start.velocity});
        double next_output = output_interval;
        std::vector<int> found(n);
        while (t < t_end) {
            const double tout = std::min(next_output, t_end);
            const int flag = CVode(mem, tout, y, &t, CV_NORMAL);
            check(flag, "CVode");
            out.samples.push_back({t, Vec2(Y[0], Y[1]), Vec2(Y[2], Y[3])});
            if (flag != CV_ROOT_RETURN) {
                next_output += output_interval;
                continue;
            }
            check(CVodeGetRootInfo(mem, found.data()), "CVodeGetRootInfo");
            for (int k = 0; k < n; ++k) {
                if (found[k] == 0) continue;
                BodyState s = state_of(Y, start.angle);
                const Gap g = gap(outline, s, obstacles[k]);
                ContactEvent e = rebound(s, g.point, obstacles[k].normal, inertia, contact);
                e.time = t;
                e.body = "block";
                e.obstacle = obstacles[k].name;
                // A bounce series shortening geometrically has infinitely many impacts in finite time (Zeno):
                // after 1000 the block rests, as contact/impacts.cpp settles free bodies.
                e.rests = s.velocity.dot(obstacles[k].normal) < contact.rest_speed || out.events.size() >= 999;
                out.events.push_back(e);
                Y[2] = s.velocity.x(), Y[3] = s.velocity.y();
                if (e.rests) out.rests = true;
            }
            out.samples.push_back({t, Vec2(Y[0], Y[1]), Vec2(Y[2], Y[3])});
            if (out.rests) break;
            check(CVodeReInit(mem, t, y), "CVodeReInit");
        }
    } catch (...) {
        CVodeFree(&mem);
        SUNNonlinSolFree(nls);
        N_VDestroy(y);
        SUNContext_Free(&ctx);
        throw;
    }
    CVodeFree(&mem);
    SUNNonlinSolFree(nls);
    N_VDestroy(y);
    SUNContext_Free(&ctx);
    return out;
}

BerangerFreeFall beranger_free_fall(const LumpedModelConfig& m) {
    const double fluid_mass = m.fluid_density * m.volume, g = m.gravity.norm();
    return {(m.mass - fluid_mass) * g / (m.mass + m.added_mass_coefficient * fluid_mass),
            std::sqrt(2.0 * (m.mass - fluid_mass) * g / (m.fluid_density * m.drag_coefficient * m.frontal_area))};
}

double BerangerFreeFall::speed(double t) const {
    return terminal_speed * std::tanh(reduced_gravity * t / terminal_speed);
}

double BerangerFreeFall::distance(double t) const {
    return terminal_speed * terminal_speed / reduced_gravity *
           std::log(std::cosh(reduced_gravity * t / terminal_speed));
}

}  // namespace chute
