#include "calibration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>

#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include "text_file.hpp"

namespace chute {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The root of an increasing f - target in [lo, hi] by bisection (to 1e-6); the nearer end if there is none.
double solve_increasing(const std::function<double(double)>& f, double target, double lo, double hi) {
    if (f(lo) >= target) return lo;
    if (f(hi) <= target) return hi;
    while (hi - lo > 1e-6) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// The minimum of f in [lo, hi] by golden-section search (f unimodal there), to 1e-5.
double golden_minimum(const std::function<double(double)>& f, double lo, double hi) {
    const double r = (std::sqrt(5.0) - 1.0) / 2.0;
    double a = lo, b = hi, c = b - r * (b - a), d = a + r * (b - a);
    double fc = f(c), fd = f(d);
    while (b - a > 1e-5) {
        if (fc < fd)
            b = d, d = c, fd = fc, c = b - r * (b - a), fc = f(c);
        else
            a = c, c = d, fc = fd, d = a + r * (b - a), fd = f(d);
    }
    return 0.5 * (a + b);
}

LumpedModelConfig model_of(double size, double density, const BlockFluid& f, double cd, double ca) {
    LumpedModelConfig m;
    m.volume = size * size * size;
    m.mass = density * m.volume;
    m.frontal_area = size * size;
    m.fluid_density = f.fluid_density;
    m.drag_coefficient = cd;
    m.added_mass_coefficient = ca;
    m.gravity = Vec2(0.0, -f.gravity);
    return m;
}

// kappa_n(travel) = kappa_inf + (kappa_0 - kappa_inf) exp(-travel / L) through the bed runs' own kappa_n by least
// squares: for each L the two kappas are a linear fit; L by a scan over 0.1-100 block sizes refined by golden
// section. Needs three runs after falls of different lengths (two would fit any L); returns false otherwise, and
// when the runs show no growth the law can carry (L at an end of the scan, a kappa outside [0.05, 2]): then
// kappa_n is one constant, as before.
bool fit_wake_growth(const std::vector<CalibrationPoint*>& beds, WetRebound& law) {
    std::vector<double> travels;
    for (const CalibrationPoint* p : beds)
        if (std::none_of(travels.begin(), travels.end(), [&](double s) { return std::abs(s - p->cfd.travel) < 0.1; }))
            travels.push_back(p->cfd.travel);
    if (travels.size() < 3) return false;
    struct Fit {
        double kappa_inf, kappa_0, residual;
    };
    const auto fit = [&](double L) {
        double s11 = 0, s12 = 0, s22 = 0, b1 = 0, b2 = 0;  // normal equations for (kappa_inf, kappa_0 - kappa_inf)
        for (const CalibrationPoint* p : beds) {
            const double e = std::exp(-p->cfd.travel / L);
            s11 += 1, s12 += e, s22 += e * e, b1 += p->kappa, b2 += e * p->kappa;
        }
        const double det = s11 * s22 - s12 * s12;
        const double a = (s22 * b1 - s12 * b2) / det, d = (s11 * b2 - s12 * b1) / det;
        double r = 0.0;
        for (const CalibrationPoint* p : beds) r += std::pow(a + d * std::exp(-p->cfd.travel / L) - p->kappa, 2);
        return Fit{a, a + d, r};
    };
    const double lo = std::log(0.1), hi = std::log(100.0);
    double best_log = std::nan(""), best_residual = std::numeric_limits<double>::infinity();
    for (double lg = lo; lg <= hi; lg += 0.02)
        if (const double r = fit(std::exp(lg)).residual; std::isfinite(r) && r < best_residual)
            best_log = lg, best_residual = r;
    if (!std::isfinite(best_log)) return false;
    const double L = std::exp(
        golden_minimum([&](double lg) { return fit(std::exp(lg)).residual; }, best_log - 0.02, best_log + 0.02));
    const Fit best = fit(L);
    const auto usable = [](double kappa) { return kappa >= 0.05 && kappa <= 2.0; };
    if (!usable(best.kappa_inf) || !usable(best.kappa_0) || best_log <= lo + 0.05 || best_log >= hi - 0.05)
        return false;
    law.kappa_n = best.kappa_inf;
    law.kappa_n_start = best.kappa_0;
    law.wake_length = L;
    return true;
}

// The slope's law through runs on one angle: their own kappa_n against the impact angle, their own push against
// travel (each table increasing, runs closer than `merge` averaged).
SlopeRebound slope_law_of(const std::vector<const CalibrationPoint*>& runs) {
    SlopeRebound law;
    law.angle = std::abs(runs.front()->cfd.slope_angle);
    const auto tabulate = [&](const std::function<double(const CalibrationPoint*)>& of, double merge,
                              double CalibrationPoint::*value, std::vector<double>& x, std::vector<double>& y) {
        std::vector<const CalibrationPoint*> sorted = runs;
        std::sort(sorted.begin(), sorted.end(),
                  [&](const CalibrationPoint* a, const CalibrationPoint* b) { return of(a) < of(b); });
        std::vector<int> count;
        for (const CalibrationPoint* p : sorted) {
            if (x.empty() || of(p) - x.back() / count.back() > merge)
                x.push_back(0.0), y.push_back(0.0), count.push_back(0);
            x.back() += of(p), y.back() += p->*value, ++count.back();
        }
        for (std::size_t i = 0; i < count.size(); ++i) x[i] /= count[i], y[i] /= count[i];
    };
    tabulate([](const CalibrationPoint* p) { return p->cfd.impact_angle(); }, 0.5 * std::numbers::pi / 180.0,
             &CalibrationPoint::kappa, law.impact_angle, law.kappa_n);
    tabulate([](const CalibrationPoint* p) { return p->cfd.travel; }, 0.1, &CalibrationPoint::push, law.travel,
             law.push);
    return law;
}

}  // namespace

double drag_coefficient_from_terminal_speed(double terminal_speed, double size, double density, const BlockFluid& f) {
    return 2.0 * (density - f.fluid_density) * f.gravity * size / (f.fluid_density * terminal_speed * terminal_speed);
}

namespace {

// The CFD's bed as a plane along tilted gravity: it descends towards +x at the slope's angle, through the origin
// (the impact point), with the run's dry coefficients; the lumped model on it.
struct TiltedBed {
    Vec2 tangent, normal;
    SlopeProfile plane;
    std::vector<Material> materials;
    HazardBlock block;
    std::unique_ptr<TrajectoryIntegrator> integrator;  // keeps references to plane and materials: not copied

    TiltedBed(const TiltedBed&) = delete;
    TiltedBed& operator=(const TiltedBed&) = delete;
    TiltedBed(const BounceObservation& o, const BlockFluid& f, double drag_coefficient, double added_mass_coefficient,
              const WetRebound& law, const GroundEffect& ground)
        : tangent(std::cos(o.slope_angle), -std::sin(o.slope_angle)),
          normal(std::sin(o.slope_angle), std::cos(o.slope_angle)),
          plane({-100.0 * tangent, 400.0 * tangent}, {0}, 1e30) {
        Material m;
        m.normal_restitution = Distribution::fixed(o.normal_restitution);
        m.tangential_restitution = Distribution::fixed(o.tangential_restitution);
        materials = {m};
        TrajectorySettings settings;
        settings.gravity = f.gravity;
        settings.drag_coefficient = drag_coefficient;
        settings.added_mass_coefficient = added_mass_coefficient;
        settings.wet_rebound = law;
        settings.ground_effect = ground;
        settings.end_time = 30.0;
        settings.relative_tolerance = 1e-10, settings.absolute_tolerance = 1e-12;
        integrator = std::make_unique<TrajectoryIntegrator>(plane, materials,
                                                            WaterProperties{f.fluid_density, f.viscosity}, settings);
        block.size = o.size;
        block.density = o.density;
    }
    TrajectoryResult fly(const Vec2& from, const Vec2& velocity, bool record_path = false) {
        std::mt19937_64 rng(0);  // nothing is drawn: fixed coefficients, no roughness
        return integrator->run(block, from, velocity, {}, rng, record_path);
    }
};

}  // namespace

LumpedBounce lumped_bounce(const BounceObservation& o, const BlockFluid& f, double drag_coefficient,
                           double added_mass_coefficient, const WetRebound& law, const GroundEffect& ground) {
    TiltedBed bed(o, f, drag_coefficient, added_mass_coefficient, law, ground);
    const Vec2& tangent = bed.tangent;
    // The law's rebound at the CFD's impact, then the flight to the next impact.
    const double vt = o.impact_velocity.x(), vn = o.impact_velocity.y();
    const Restitution e = wet_restitution(law, o.normal_restitution, o.tangential_restitution,
                                          impact_stokes_number(o.density, std::abs(vn), o.size, f.viscosity), o.travel,
                                          o.slope_angle, o.impact_angle());
    const Vec2 after = (e.tangential * vt + e.push * std::abs(vn)) * tangent - e.normal * vn * bed.normal;
    const TrajectoryResult r = bed.fly(Vec2::Zero(), after);
    LumpedBounce b;
    b.height = r.apexes.empty() ? 0.0 : r.apexes.front().height;
    b.runout = r.impacts.empty() ? nan : r.impacts.front().position.dot(tangent);
    return b;
}

LumpedBounce lumped_bounce_from_release(const BounceObservation& o, const BlockFluid& f, double drag_coefficient,
                                        double added_mass_coefficient, const WetRebound& law,
                                        const GroundEffect& ground, double& impact_speed) {
    impact_speed = nan;
    if (!std::isfinite(o.release_offset.x())) return {};
    TiltedBed bed(o, f, drag_coefficient, added_mass_coefficient, law, ground);
    const Vec2 x0 = o.release_offset.x() * bed.tangent + o.release_offset.y() * bed.normal;
    const TrajectoryResult r = bed.fly(x0, o.release_velocity.x() * bed.tangent + o.release_velocity.y() * bed.normal);
    LumpedBounce b;
    if (r.impacts.empty()) return b;
    const Impact& first = r.impacts.front();
    impact_speed = -first.velocity_before.dot(bed.normal);
    b.height = 0.0;  // a rebound slower than the sliding speed: none
    for (const Apex& a : r.apexes)
        if (a.t > first.t) {
            b.height = a.height;
            break;
        }
    if (r.impacts.size() > 1) b.runout = (r.impacts[1].position - first.position).dot(bed.tangent);
    return b;
}

std::vector<double> lumped_approach(const BounceObservation& o, const BlockFluid& f, double drag_coefficient,
                                    double added_mass_coefficient, const GroundEffect& ground) {
    if (o.approach_clearance.empty()) return {};
    TiltedBed bed(o, f, drag_coefficient, added_mass_coefficient, WetRebound{}, ground);
    const Vec2 v0 = o.approach_velocity.front();
    const TrajectoryResult r =
        bed.fly(o.approach_clearance.front() * bed.normal, v0.x() * bed.tangent + v0.y() * bed.normal, true);
    if (r.impacts.empty()) throw std::logic_error(o.name + ": the lumped approach never meets the bed");
    // The flight's points up to the impact, as (clearance, speed towards the bed), clearance falling.
    std::vector<double> c, w;
    for (const PathSample& p : r.path) {
        if (p.t > r.impacts.front().t) break;
        c.push_back(std::max(p.position.dot(bed.normal), 0.0));
        w.push_back(-p.velocity.dot(bed.normal));
    }
    c.push_back(0.0);
    w.push_back(-r.impacts.front().velocity_before.dot(bed.normal));
    std::vector<double> speeds;
    for (const double target : o.approach_clearance) speeds.push_back(bracket_falling(c, target).at(w));
    return speeds;
}

FallingBracket bracket_falling(const std::vector<double>& c, double target) {
    FallingBracket b;
    while (b.k + 1 < c.size() && c[b.k] > target) ++b.k;
    const double span = c[b.k - 1] - c[b.k];
    b.weight = span > 0.0 ? std::clamp((c[b.k - 1] - target) / span, 0.0, 1.0) : 1.0;
    return b;
}

namespace {

// The ground effect through the bed runs' approaches: strength and decay minimising the squared relative
// differences of the normal speed at the approach samples, by Levenberg-Marquardt (Eigen, forward differences) in
// (strength, log decay) from the best of a coarse grid. Needs two runs with an approach; none if the runs show no
// braking (a strength below 0).
struct ApproachResiduals {
    using Scalar = double;
    enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
    using InputType = Eigen::VectorXd;
    using ValueType = Eigen::VectorXd;
    using JacobianType = Eigen::MatrixXd;

    std::vector<const BounceObservation*> runs;
    const BlockFluid* fluid = nullptr;
    double cd = 0.0, ca = 0.0;
    int count = 0;

    int inputs() const { return 2; }
    int values() const { return count; }
    int operator()(const Eigen::VectorXd& p, Eigen::VectorXd& r) const {
        const GroundEffect g{p[0], std::exp(p[1])};
        int i = 0;
        for (const BounceObservation* o : runs) {
            const std::vector<double> model = lumped_approach(*o, *fluid, cd, ca, g);
            for (std::size_t k = 0; k < model.size(); ++k) r[i++] = model[k] / -o->approach_velocity[k].y() - 1.0;
        }
        return 0;
    }
};

bool fit_ground_effect(const std::vector<CalibrationPoint*>& beds, const BlockFluid& f, double cd, double ca,
                       GroundEffect& out) {
    ApproachResiduals residuals;
    residuals.fluid = &f, residuals.cd = cd, residuals.ca = ca;
    for (const CalibrationPoint* p : beds)
        if (p->cfd.approach_clearance.size() >= 2) {
            residuals.runs.push_back(&p->cfd);
            residuals.count += static_cast<int>(p->cfd.approach_clearance.size());
        }
    if (residuals.runs.size() < 2) return false;
    Eigen::VectorXd p(2), r(residuals.count);
    double best = std::numeric_limits<double>::infinity();
    for (const double strength : {0.5, 1.0, 2.0, 4.0, 8.0, 16.0})
        for (const double decay : {0.1, 0.2, 0.3, 0.5, 0.8, 1.2}) {
            const Eigen::VectorXd q{{strength, std::log(decay)}};
            residuals(q, r);
            if (r.squaredNorm() < best) best = r.squaredNorm(), p = q;
        }
    Eigen::NumericalDiff<ApproachResiduals> differences(residuals, 1e-12);  // steps of 1e-6 of the parameters
    Eigen::LevenbergMarquardt<Eigen::NumericalDiff<ApproachResiduals>> lm(differences);
    lm.parameters.xtol = 1e-10;
    lm.parameters.ftol = 1e-12;
    lm.minimize(p);
    if (!(p[0] > 0.0) || !std::isfinite(p[1])) return false;
    out = {p[0], std::exp(p[1])};
    return true;
}

}  // namespace

Calibration calibrate(const FreeFallObservation& fall, double size, double density,
                      const std::vector<BounceObservation>& bounces, const BlockFluid& f, double beta) {
    Calibration out;
    CalibrationFile& k = out.constants;
    k.block_size = size;
    k.block_density = density;
    k.wet_rebound.beta = beta;
    out.terminal_speed = fall.terminal_speed;
    k.drag_coefficient = drag_coefficient_from_terminal_speed(fall.terminal_speed, size, density, f);

    // C_a: the closed form's speed against the CFD's up to 0.8 v_t.
    std::size_t n = 0;
    while (n < fall.t.size() && fall.speed[n] < 0.8 * fall.terminal_speed) ++n;
    out.early_window = n ? fall.t[n - 1] : 0.0;
    const auto misfit = [&](double ca) {
        const BerangerFreeFall model = beranger_free_fall(model_of(size, density, f, k.drag_coefficient, ca));
        double sum = 0.0;
        for (std::size_t i = 0; i < n; ++i) sum += std::pow(model.speed(fall.t[i]) - fall.speed[i], 2);
        return sum;
    };
    k.added_mass_coefficient = golden_minimum(misfit, 0.0, 3.0);
    out.early_rms = n ? std::sqrt(misfit(k.added_mass_coefficient) / static_cast<double>(n)) : nan;

    for (const BounceObservation& o : bounces) {
        CalibrationPoint p;
        p.cfd = o;
        p.stokes = impact_stokes_number(o.density, std::abs(o.impact_velocity.y()), o.size, f.viscosity);
        p.kappa = p.push = nan;
        out.points.push_back(p);
    }
    const auto bounce = [&](const BounceObservation& o, const WetRebound& law) {
        return lumped_bounce(o, f, k.drag_coefficient, k.added_mass_coefficient, law, k.ground_effect);
    };
    // The ground effect from the beds' approaches, before the restitution: the rebound flies through it too.
    {
        std::vector<CalibrationPoint*> beds;
        for (CalibrationPoint& p : out.points)
            if (p.cfd.fitted && p.cfd.on_bed()) beds.push_back(&p);
        fit_ground_effect(beds, f, k.drag_coefficient, k.added_mass_coefficient, k.ground_effect);
    }
    // The beds: each run's own kappa_n (its bounce height, by bisection within [0.05, 1 / Rn]: a wet coefficient
    // above 1 would create energy), then the wake's growth through them (three or more falls of different
    // lengths) or their least-squares constant.
    std::vector<CalibrationPoint*> beds;
    for (CalibrationPoint& p : out.points)
        if (p.cfd.fitted && p.cfd.on_bed()) beds.push_back(&p);
    if (!beds.empty()) {
        const double limit = [&] {
            double l = 2.0;
            for (const CalibrationPoint* p : beds) l = std::min(l, 1.0 / p->cfd.normal_restitution);
            return l;
        }();
        for (CalibrationPoint* p : beds) {
            WetRebound law = k.wet_rebound;  // no wake's growth yet: kappa_n at any travel
            p->kappa = solve_increasing(
                [&](double kappa) {
                    law.kappa_n = kappa;
                    return bounce(p->cfd, law).height;
                },
                p->cfd.rebound_height, 0.05, limit);
        }
        if (!fit_wake_growth(beds, k.wet_rebound)) {
            k.wet_rebound.kappa_n = golden_minimum(
                [&](double kappa) {
                    WetRebound law = k.wet_rebound;
                    law.kappa_n = kappa;
                    double sum = 0.0;
                    for (const CalibrationPoint* p : beds)
                        sum +=
                            std::pow((bounce(p->cfd, law).height - p->cfd.rebound_height) / p->cfd.rebound_height, 2);
                    return sum;
                },
                0.05, limit);
        }
    }

    // The slopes (one angle): each run's own kappa_n and push, the pair that gives its bounce height and its runout
    // (the runout rises with the push; for each push, kappa_n by bisection for the height), then the slope's law
    // through them (slope_law_of: kappa_n against the impact angle, the push against travel; wet_rebound.hpp).
    std::vector<CalibrationPoint*> slopes;
    for (CalibrationPoint& p : out.points)
        if (p.cfd.fitted && !p.cfd.on_bed() && std::isfinite(p.cfd.runout)) slopes.push_back(&p);
    for (const CalibrationPoint* p : slopes)
        if (std::abs(std::abs(p->cfd.slope_angle) - std::abs(slopes.front()->cfd.slope_angle)) > 1e-3)
            throw std::invalid_argument("the slope runs fitted to (" + slopes.front()->cfd.name + ", " + p->cfd.name +
                                        ") are on different angles: the law is measured on one; mark the others "
                                        "`use: check`");
    for (CalibrationPoint* p : slopes) {
        const double limit = 1.0 / p->cfd.normal_restitution;
        WetRebound law;  // this run's (kappa_n, push) at any travel
        law.beta = k.wet_rebound.beta;
        law.slope = {std::abs(p->cfd.slope_angle), {p->cfd.impact_angle()}, {1.0}, {p->cfd.travel}, {0.0}};
        const auto kappa_for = [&](double push) {
            return solve_increasing(
                [&](double kappa) {
                    law.slope.kappa_n = {kappa}, law.slope.push = {push};
                    return bounce(p->cfd, law).height;
                },
                p->cfd.rebound_height, 0.05, limit);
        };
        p->push = solve_increasing(
            [&](double push) {
                const double kappa = kappa_for(push);
                law.slope.kappa_n = {kappa}, law.slope.push = {push};
                return bounce(p->cfd, law).runout;
            },
            p->cfd.runout, -2.0, 2.0);
        p->kappa = kappa_for(p->push);
    }
    if (!slopes.empty()) {
        k.wet_rebound.slope = slope_law_of({slopes.begin(), slopes.end()});
        // Each run left out in turn: how well the law fitted to the others predicts it (a cross-validation).
        for (CalibrationPoint* left : slopes) {
            std::vector<const CalibrationPoint*> others;
            for (const CalibrationPoint* p : slopes)
                if (p != left) others.push_back(p);
            if (others.empty()) continue;
            WetRebound law = k.wet_rebound;
            law.slope = slope_law_of(others);
            const LumpedBounce b = bounce(left->cfd, law);
            left->left_out_height = b.height, left->left_out_runout = b.runout;
        }
    }
    for (CalibrationPoint& p : out.points) {
        p.law_kappa = k.wet_rebound.normal_kappa(p.cfd.travel, p.cfd.slope_angle, p.cfd.impact_angle());
        p.law_push = k.wet_rebound.push(p.cfd.travel, p.cfd.slope_angle);
        const LumpedBounce b = bounce(p.cfd, k.wet_rebound);
        p.lumped_height = b.height;
        p.lumped_runout = b.runout;
        if (!p.cfd.approach_clearance.empty()) {
            p.approach_impact_speed =
                lumped_approach(p.cfd, f, k.drag_coefficient, k.added_mass_coefficient, k.ground_effect).back();
            p.approach_impact_speed_plain =
                lumped_approach(p.cfd, f, k.drag_coefficient, k.added_mass_coefficient, {}).back();
        }
        p.released = lumped_bounce_from_release(p.cfd, f, k.drag_coefficient, k.added_mass_coefficient, k.wet_rebound,
                                                k.ground_effect, p.released_impact_speed);
    }
    return out;
}

namespace {

double percent(double model, double cfd) { return 100.0 * (model - cfd) / std::abs(cfd); }

std::string kappa_and_push(double kappa, double push) {
    if (!std::isfinite(kappa)) return "-";
    return std::isfinite(push) ? printf_text("%.4f, %+.4f", kappa, push) : printf_text("%.4f", kappa);
}

}  // namespace

std::string calibration_points_csv(const Calibration& c) {
    std::string t =
        "run,use,slope_deg,travel,impact_u,impact_v,stokes,cfd_height,lumped_height,cfd_runout,lumped_runout,own_kappa,"
        "own_push,law_kappa,law_push,left_out_height,left_out_runout,approach_from,approach_impact_speed,"
        "approach_impact_speed_plain,released_impact_speed,released_height,released_runout\n";
    for (const CalibrationPoint& p : c.points)
        t += printf_text(
            "%s,%s,%.6g,%.6g,%.9g,%.9g,%.6g,%.9g,%.9g,%.9g,%.9g,%.6g,%.6g,%.6g,%.6g,%.9g,%.9g,%.6g,%.9g,%.9g,%.9g,%.9g,"
            "%.9g\n",
            p.cfd.name.c_str(), p.cfd.fitted ? "fit" : "check", p.cfd.slope_angle * 180.0 / std::numbers::pi,
            p.cfd.travel, p.cfd.impact_velocity.x(), p.cfd.impact_velocity.y(), p.stokes, p.cfd.rebound_height,
            p.lumped_height, p.cfd.runout, p.lumped_runout, p.kappa, p.push, p.law_kappa, p.law_push, p.left_out_height,
            p.left_out_runout, p.cfd.approach_clearance.empty() ? nan : p.cfd.approach_clearance.front(),
            p.approach_impact_speed, p.approach_impact_speed_plain, p.released_impact_speed, p.released.height,
            p.released.runout);
    return t;
}

std::string calibration_markdown(const Calibration& c) {
    const CalibrationFile& k = c.constants;
    std::string t = printf_text(
        "Block %.3g m, %.4g kg/m^3. Free fall: terminal speed %.4f m/s -> C_D = %.4f; early speed up to %.3f s -> "
        "C_a = %.4f (rms misfit %.3g m/s). Bounces: kappa_n = %.4f, kappa_t = %.4f, beta = %.3g",
        k.block_size, k.block_density, c.terminal_speed, k.drag_coefficient, c.early_window, k.added_mass_coefficient,
        c.early_rms, k.wet_rebound.kappa_n, k.wet_rebound.kappa_t, k.wet_rebound.beta);
    t += k.wet_rebound.wake_length > 0.0
             ? printf_text(
                   "; the wake's growth: kappa_n_start = %.4f, wake_length = %.3f block sizes (kappa_n(travel) = "
                   "kappa_n + (kappa_n_start - kappa_n) exp(-travel / wake_length)).\n\n",
                   k.wet_rebound.kappa_n_start, k.wet_rebound.wake_length)
             : std::string(".\n\n");
    if (const GroundEffect& g = k.ground_effect; g.active()) {
        t += printf_text(
            "The ground effect (ground_effect.hpp; fitted to the approach of the bed runs marked fit): the normal "
            "drag times G(c) = %.4f exp(-c / (%.4f a)) at clearance c above the impact point. The approach flown from "
            "the CFD's state up to 2 block sizes above the impact, its speed towards the bed at the impact:\n\n"
            "| run | use | slope | from (sizes) | CFD | lumped | diff | lumped without the ground effect | diff |\n"
            "|---|---|---|---|---|---|---|---|---|\n",
            g.strength, g.decay);
        for (const CalibrationPoint& p : c.points) {
            if (!std::isfinite(p.approach_impact_speed)) continue;
            const double cfd = -p.cfd.impact_velocity.y();
            t +=
                printf_text("| %s | %s | %.0f deg | %.2f | %.3f m/s | %.3f m/s | %+.1f %% | %.3f m/s | %+.1f %% |\n",
                            p.cfd.name.c_str(), p.cfd.fitted ? "fit" : "check",
                            p.cfd.slope_angle * 180.0 / std::numbers::pi, p.cfd.approach_clearance.front() / p.cfd.size,
                            cfd, p.approach_impact_speed, percent(p.approach_impact_speed, cfd),
                            p.approach_impact_speed_plain, percent(p.approach_impact_speed_plain, cfd));
        }
        t += "\n";
    }
    if (const SlopeRebound& s = k.wet_rebound.slope; s.measured()) {
        t += printf_text(
            "The slope's law (measured at %.3g degrees; wet_rebound.hpp): kappa_n against the impact's angle "
            "from the normal:",
            s.angle * 180.0 / std::numbers::pi);
        for (std::size_t i = 0; i < s.impact_angle.size(); ++i)
            t += printf_text("%s %.1f deg %.4f", i ? ";" : "", s.impact_angle[i] * 180.0 / std::numbers::pi,
                             s.kappa_n[i]);
        t += "; the push against travel:";
        for (std::size_t i = 0; i < s.travel.size(); ++i)
            t += printf_text("%s %.2f sizes %+.4f", i ? ";" : "", s.travel[i], s.push[i]);
        t += ".\n\n";
    }
    t += "| run | use | slope | travel (sizes) | impact (along, normal) m/s | St | height CFD | height lumped | diff | "
         "runout CFD | runout lumped | diff | own kappa_n, push | law's kappa_n, push | left out: height, runout |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const CalibrationPoint& p : c.points) {
        const std::string runout =
            p.cfd.on_bed() ? "- | - | -"
                           : printf_text("%.3f m | %.3f m | %+.1f %% (%+.3f m)", p.cfd.runout, p.lumped_runout,
                                         percent(p.lumped_runout, p.cfd.runout), p.lumped_runout - p.cfd.runout);
        t += printf_text(
            "| %s | %s | %.0f deg | %.2f | (%.3f, %.3f) | %.3g | %.4f m | %.4f m | %+.1f %% | %s | %s | %s | %s |\n",
            p.cfd.name.c_str(), p.cfd.fitted ? "fit" : "check", p.cfd.slope_angle * 180.0 / std::numbers::pi,
            p.cfd.travel, p.cfd.impact_velocity.x(), p.cfd.impact_velocity.y(), p.stokes, p.cfd.rebound_height,
            p.lumped_height, percent(p.lumped_height, p.cfd.rebound_height), runout.c_str(),
            kappa_and_push(p.kappa, p.push).c_str(),
            kappa_and_push(p.law_kappa, p.cfd.on_bed() ? nan : p.law_push).c_str(),
            std::isfinite(p.left_out_height)
                ? printf_text("%+.1f %%, %+.1f %% (%+.3f m)", percent(p.left_out_height, p.cfd.rebound_height),
                              percent(p.left_out_runout, p.cfd.runout), p.left_out_runout - p.cfd.runout)
                      .c_str()
                : "-");
    }
    t += "\n(left out: a fitted slope run predicted by the slope's law fitted to the other slope runs.)\n";
    t += "\nThe same bounces flown from the CFD's release, as a hazard run flies them (the ground effect, the law at "
         "the lumped block's own impact velocity and travel):\n\n"
         "| run | use | slope | impact speed normal to the bed CFD | lumped | diff | height CFD | lumped | diff | "
         "runout CFD | lumped | diff |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const CalibrationPoint& p : c.points) {
        if (!std::isfinite(p.released_impact_speed)) continue;
        const double cfd = -p.cfd.impact_velocity.y();
        const std::string runout =
            p.cfd.on_bed() ? "- | - | -"
                           : printf_text("%.3f m | %.3f m | %+.1f %% (%+.3f m)", p.cfd.runout, p.released.runout,
                                         percent(p.released.runout, p.cfd.runout), p.released.runout - p.cfd.runout);
        t += printf_text("| %s | %s | %.0f deg | %.3f m/s | %.3f m/s | %+.1f %% | %.4f m | %.4f m | %+.1f %% | %s |\n",
                         p.cfd.name.c_str(), p.cfd.fitted ? "fit" : "check",
                         p.cfd.slope_angle * 180.0 / std::numbers::pi, cfd, p.released_impact_speed,
                         percent(p.released_impact_speed, cfd), p.cfd.rebound_height, p.released.height,
                         percent(p.released.height, p.cfd.rebound_height), runout.c_str());
    }
    return t;
}

}  // namespace chute
