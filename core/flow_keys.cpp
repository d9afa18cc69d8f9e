// The flow's section of the case-file schema (flow_config.hpp) and its reading: the keys as data, checked and
// typed by the generic reader (io/case_reader.hpp); then the checks that involve several of them.
#include <algorithm>
#include <cmath>
#include <string>

#include "axis.hpp"
#include "case_reader.hpp"
#include "flow_config.hpp"

namespace chute {

namespace {

// domain.refinement f scales an axis as a grid-convergence study does: f times the cells, each f times narrower,
// the growth ratio r^(1/f) so that f cells grow as much as one did (the stretching keeps its shape).
void refine_axis(const CaseReader& r, const std::string& p, double f, AxisConfig& a) {
    if (f == 1.0) return;
    if (a.spacing == "lines")
        r.fail("domain.refinement",
               "cannot refine " + p + ", whose lines are listed one by one (spacing: lines); got " + exact_text(f));
    const auto refined = [&](int n) { return std::max(2, static_cast<int>(std::lround(n * f))); };
    a.cells = refined(a.cells);
    a.core_cells = refined(a.core_cells);
    a.ratio = std::pow(a.ratio, 1.0 / f);
    a.first /= f;
    a.max_width /= f;
}

void read_axis(const CaseReader& r, const std::string& p, double refinement, AxisConfig& a) {
    a.spacing = r.choice(p + ".spacing");
    a.beta = r.number(p + ".beta");
    a.ratio = r.number(p + ".ratio");
    if (a.spacing == "lines") {
        refine_axis(r, p, refinement, a);
        a.lines = r.number_list(p + ".lines");
        if (a.lines.size() < 3)
            r.fail(p + ".lines", "expected at least 3 lines (2 cells), got " + std::to_string(a.lines.size()));
        for (std::size_t i = 1; i < a.lines.size(); ++i)
            if (!(a.lines[i] > a.lines[i - 1]))
                r.fail(CaseReader::indexed(p + ".lines", i), "lines must be strictly increasing, got " +
                                                                 exact_text(a.lines[i]) + " after " +
                                                                 exact_text(a.lines[i - 1]));
        a.start = a.lines.front();
        a.end = a.lines.back();
        a.cells = static_cast<int>(a.lines.size()) - 1;
    } else {
        a.start = r.number(p + ".start");
        a.end = r.number(p + ".end");
        if (!(a.end > a.start))
            r.fail(p + ".end",
                   "must be greater than " + p + ".start (" + exact_text(a.start) + "), got " + exact_text(a.end));
        if (!std::isfinite(a.end - a.start))
            r.fail(p + ".end", "the length end - start = " + exact_text(a.end) + " - " + exact_text(a.start) +
                                   " is beyond the largest number");
        if (a.spacing == "clustered") {
            a.core = r.vector2(p + ".core");
            a.core_cells = static_cast<int>(r.integer(p + ".core_cells"));
            if (!(a.core[0] >= a.start && a.core[1] <= a.end && a.core[1] > a.core[0]))
                r.fail(p + ".core", "the window must lie in [start, end] = [" + exact_text(a.start) + ", " +
                                        exact_text(a.end) + "] with to > from, got [" + exact_text(a.core[0]) + ", " +
                                        exact_text(a.core[1]) + "]");
            if (!(a.ratio >= 1.0))
                r.fail(p + ".ratio",
                       "clustered cells grow away from the window: ratio >= 1, got " + exact_text(a.ratio));
            a.first = r.present(p + ".first") ? r.number(p + ".first") : 0.0;
            a.max_width = r.present(p + ".max") ? r.number(p + ".max") : 0.0;
            refine_axis(r, p, refinement, a);
            const double window = a.core[1] - a.core[0];
            if (a.first > 0.0 && !(a.core_cells * a.first < window))
                r.fail(p + ".first",
                       "cells " + exact_text(a.first) +
                           " wide at the window's ends cannot be clustered: " + std::to_string(a.core_cells) +
                           " of them (core_cells) span " + exact_text(a.core_cells * a.first) + ", the window [" +
                           exact_text(a.core[0]) + ", " + exact_text(a.core[1]) + "] only " + exact_text(window) +
                           " (a smaller first, or fewer core_cells)");
            const double outermost = a.first > 0.0 ? a.first : window / a.core_cells;
            if (a.max_width > 0.0 && !(a.max_width >= outermost))
                r.fail(p + ".max", "the outer cells grow from the window's end cell (" + exact_text(outermost) +
                                       " m): max must be at least that, got " + exact_text(a.max_width));
            // Counted before the lines are made: ratio 1 across a long domain would ask for more than memory holds.
            const double count =
                clustered_cell_count(a.start, a.end, a.core[0], a.core[1], a.core_cells, a.ratio, a.first, a.max_width);
            if (count > kMaxCells)
                r.fail(p + ".core_cells", "the window's " + std::to_string(a.core_cells) + " cells, growing by ratio " +
                                              exact_text(a.ratio) + " to start and end, make about " +
                                              exact_text(count) + " cells along this axis; a case may have at most " +
                                              exact_text(kMaxCells) + " cells in all");
            const auto lines =
                clustered_lines(a.start, a.end, a.core[0], a.core[1], a.core_cells, a.ratio, a.first, a.max_width);
            a.cells = static_cast<int>(lines.size()) - 1;
        } else {
            a.cells = static_cast<int>(r.integer(p + ".cells"));
            refine_axis(r, p, refinement, a);
        }
    }
}

// The key that sets the number of cells along an axis, and the one that shapes its lines, for messages.
std::string count_key(const std::string& p, const AxisConfig& a) {
    if (a.spacing == "lines") return p + ".lines";
    return p + (a.spacing == "clustered" ? ".core_cells" : ".cells");
}

std::string shape_key(const std::string& p, const AxisConfig& a) {
    if (a.spacing == "tanh") return p + ".beta";
    if (a.spacing == "geometric" || a.spacing == "clustered") return p + ".ratio";
    return count_key(p, a);
}

// The grid as a whole: no more cells than a case may have (checked before any line is made), then lines
// that increase strictly (a strong tanh beta or geometric ratio makes neighbouring lines equal in double
// precision, or overflows), as the solver's grid requires.
void check_grid(const CaseReader& r, const FlowConfig& c) {
    const double cells = static_cast<double>(c.x.cells) * c.y.cells;
    if (cells > kMaxCells) {
        const std::string kx = count_key("domain.x", c.x), ky = count_key("domain.y", c.y);
        r.fail(c.x.cells >= c.y.cells ? kx : ky, "the grid would have " + std::to_string(c.x.cells) + " x " +
                                                     std::to_string(c.y.cells) + " = " + exact_text(cells) +
                                                     " cells (" + kx + ", " + ky + "); a case may have at most " +
                                                     exact_text(kMaxCells) + " (about 70 GB at 700 bytes per cell)");
    }
    for (const auto& [p, a] : {std::pair<std::string, const AxisConfig*>{"domain.x", &c.x}, {"domain.y", &c.y}}) {
        const std::vector<double> lines = axis_lines(*a);
        for (std::size_t k = 1; k < lines.size(); ++k)
            if (!(std::isfinite(lines[k]) && lines[k] > lines[k - 1]))
                r.fail(shape_key(p, *a), "the grid lines of spacing '" + a->spacing + "' with " +
                                             std::to_string(a->cells) + " cells do not increase strictly: line " +
                                             std::to_string(k - 1) + " is " + exact_text(lines[k - 1]) + ", line " +
                                             std::to_string(k) + " is " + exact_text(lines[k]));
    }
}

void read_boundary(const CaseReader& r, int s, BoundaryConfig& b) {
    const std::string side(kSideNames[s]), p = "boundaries." + side;
    b.type = r.choice<BoundaryType>(p + ".type", {{"wall", BoundaryType::wall},
                                                  {"slip", BoundaryType::slip},
                                                  {"inflow", BoundaryType::inflow},
                                                  {"outflow", BoundaryType::outflow},
                                                  {"periodic", BoundaryType::periodic}});
    b.velocity = r.vector2(p + ".velocity");
    b.profile = r.choice<InflowProfile>(p + ".profile",
                                        {{"uniform", InflowProfile::uniform}, {"parabolic", InflowProfile::parabolic}});
    b.outflow = r.choice<OutflowKind>(
        p + ".kind", {{"convective", OutflowKind::convective}, {"zero_stress", OutflowKind::zero_stress}});
    if (r.present(p + ".peak")) b.peak = r.number(p + ".peak");
    if (b.type == BoundaryType::inflow && b.profile == InflowProfile::parabolic && r.present(p + ".velocity"))
        r.fail(p + ".velocity", "not used with profile: parabolic (the peak sets the inflow)");

    const int normal = s < 2 ? 0 : 1;               // velocity component normal to this side
    const double inward = s % 2 == 0 ? 1.0 : -1.0;  // sign of that component for flow into the domain
    const std::string component = "velocity[" + std::to_string(normal) + "]";
    if (b.type == BoundaryType::wall && b.velocity[normal] != 0.0)
        r.fail(p + ".velocity", "a wall moves along itself: the normal component " + component + " must be 0 on the " +
                                    side + " side, got " + exact_text(b.velocity[normal]));
    if (b.type == BoundaryType::inflow && b.profile == InflowProfile::uniform) {
        if (!r.present(p + ".velocity"))
            r.fail(p + ".velocity",
                   "missing required key (an inflow with profile: uniform needs its velocity; or "
                   "use profile: parabolic with a peak)");
        // 0 is water at rest: what a grid carried by a body-fitted block meets ahead of it.
        if (!(inward * b.velocity[normal] >= 0.0))
            r.fail(p + ".velocity", "an inflow must enter the domain (or be water at rest): on the " + side + " side " +
                                        component + " must be " + (inward > 0 ? ">= 0" : "<= 0") + ", got " +
                                        exact_text(b.velocity[normal]));
    }
}

// Conditions that involve more than one side.
void check_boundaries(const CaseReader& r, const FlowConfig& c) {
    const auto type_of = [&](int s) { return c.boundary[s].type; };
    for (int s = 0; s < 4; ++s) {
        const int opposite = s ^ 1;  // left <-> right, bottom <-> top
        if (type_of(s) == BoundaryType::periodic && type_of(opposite) != BoundaryType::periodic)
            r.fail("boundaries." + std::string(kSideNames[s]) + ".type",
                   "periodic sides come in pairs: boundaries." + std::string(kSideNames[opposite]) +
                       ".type must be periodic too, got '" +
                       r.choice("boundaries." + std::string(kSideNames[opposite]) + ".type") + "'");
    }
    bool outflow = false;
    for (int s = 0; s < 4; ++s) outflow = outflow || type_of(s) == BoundaryType::outflow;
    for (int s = 0; s < 4; ++s)
        if (type_of(s) == BoundaryType::inflow && !outflow)
            r.fail("boundaries." + std::string(kSideNames[s]) + ".type",
                   "an inflow needs an outflow side somewhere: with none, the mass let in cannot leave");
}

}  // namespace

std::vector<CaseKey> flow_keys() {
    using K = KeyType;
    const std::vector<std::string_view> from_ends = {"uniform", "tanh", "geometric", "clustered"};
    return {
        {.path = "domain", .type = K::section, .required = true, .meaning = "The rectangle and its grid."},
        {.path = "domain.<axis>", .type = K::section, .required = true, .meaning = "Grid lines along x or along y."},
        {.path = "domain.<axis>.start",
         .type = K::number,
         .required = true,
         .when_key = "spacing",
         .when_values = from_ends,
         .units = "m",
         .meaning = "First grid line: the left (x) or bottom (y) boundary."},
        {.path = "domain.<axis>.end",
         .type = K::number,
         .required = true,
         .when_key = "spacing",
         .when_values = from_ends,
         .units = "m",
         .meaning = "Last grid line: the right (x) or top (y) boundary; must be greater than start."},
        {.path = "domain.<axis>.cells",
         .type = K::integer,
         .required = true,
         .min = at_least(2),
         .when_key = "spacing",
         .when_values = {"uniform", "tanh", "geometric"},
         .meaning = "Number of cells."},
        {.path = "domain.<axis>.spacing",
         .type = K::choice,
         .default_value = "uniform",
         .choices = {"uniform", "tanh", "geometric", "clustered", "lines"},
         .meaning = "Placement of the lines: `uniform`; `tanh`, clustered towards both ends; `geometric`, "
                    "each cell `ratio` times as wide as the one before; `clustered`, uniform cells in the "
                    "window `core` growing by `ratio` per cell towards both ends (a fine window around a "
                    "body; the cell count follows); `lines`, listed one by one."},
        {.path = "domain.<axis>.beta",
         .type = K::number,
         .default_value = "2.0",
         .min = above(0),
         .when_key = "spacing",
         .when_values = {"tanh"},
         .meaning = "Clustering strength of tanh spacing: larger is finer at the ends (towards 0: "
                    "uniform)."},
        {.path = "domain.<axis>.ratio",
         .type = K::number,
         .default_value = "1.05",
         .min = above(0),
         .when_key = "spacing",
         .when_values = {"geometric", "clustered"},
         .meaning = "Width of each cell over the width of the one before it (geometric spacing; clustered "
                    "spacing outside the window)."},
        {.path = "domain.<axis>.core",
         .type = K::vector2,
         .required = true,
         .when_key = "spacing",
         .when_values = {"clustered"},
         .units = "m",
         .meaning = "The window [from, to] of uniform fine cells; inside [start, end]."},
        {.path = "domain.<axis>.core_cells",
         .type = K::integer,
         .required = true,
         .min = at_least(2),
         .when_key = "spacing",
         .when_values = {"clustered"},
         .meaning = "Number of cells across the window."},
        {.path = "domain.<axis>.first",
         .type = K::number,
         .min = above(0),
         .when_key = "spacing",
         .when_values = {"clustered"},
         .units = "m",
         .meaning = "Optional: the width of the window's end cells, as a body-fitted mesh gives its first cell at "
                    "a body's faces (the window is then the body's extent). The window's cells grow geometrically "
                    "from both ends towards its middle and the outer cells grow by `ratio` from `first`. Not "
                    "given: a uniform window."},
        {.path = "domain.<axis>.max",
         .type = K::number,
         .min = above(0),
         .when_key = "spacing",
         .when_values = {"clustered"},
         .units = "m",
         .meaning = "Optional: the largest outer cell; the cells grow by `ratio` up to it, then keep it. Not "
                    "given: they grow to the domain's ends."},
        {.path = "domain.<axis>.lines",
         .type = K::number_list,
         .required = true,
         .when_key = "spacing",
         .when_values = {"lines"},
         .units = "m",
         .meaning = "Every grid line, strictly increasing, at least 3; start, end and cells follow from "
                    "them and are not given."},
        {.path = "domain.refinement",
         .type = K::number,
         .default_value = "1.0",
         .min = above(0),
         .max = at_most(16),
         .meaning = "A grid-convergence factor on both axes: f times the cells (`cells`, `core_cells`), `first` and "
                    "`max` divided by f and `ratio` taken to the power 1/f, so the grid keeps its shape (0.5: half "
                    "the cells each way; 1.5: the study of a finer grid). Not for listed lines."},
        {.path = "domain.depth",
         .type = K::number,
         .default_value = "1.0",
         .min = above(0),
         .units = "m",
         .meaning = "Span (in z) that the 2D flow stands for; scales forces and flow rates."},

        {.path = "fluid", .type = K::section, .required = true, .meaning = "Fluid properties."},
        {.path = "fluid.density",
         .type = K::number,
         .default_value = "1000.0",
         .min = above(0),
         .units = "kg/m^3",
         .meaning = "Density."},
        {.path = "fluid.viscosity",
         .type = K::number,
         .required = true,
         .min = above(0),
         .units = "m^2/s",
         .meaning = "Kinematic viscosity."},
        {.path = "fluid.body_force",
         .type = K::vector2,
         .default_value = "[0.0, 0.0]",
         .units = "m/s^2",
         .meaning = "Constant acceleration on the fluid, e.g. gravity [0, -9.81]."},

        {.path = "initial", .type = K::section, .meaning = "Initial velocity field."},
        {.path = "initial.type",
         .type = K::choice,
         .default_value = "uniform",
         .choices = {"uniform", "taylor_green"},
         .meaning = "`uniform`: the constant `velocity` everywhere; `taylor_green`: Taylor-Green vortices "
                    "of peak speed `amplitude`."},
        {.path = "initial.velocity",
         .type = K::vector2,
         .default_value = "[0.0, 0.0]",
         .when_key = "type",
         .when_values = {"uniform"},
         .units = "m/s",
         .meaning = "Uniform initial velocity."},
        {.path = "initial.amplitude",
         .type = K::number,
         .default_value = "1.0",
         .when_key = "type",
         .when_values = {"taylor_green"},
         .units = "m/s",
         .meaning = "Peak speed of the Taylor-Green vortices."},
        {.path = "initial.perturbation",
         .type = K::number,
         .default_value = "0.0",
         .min = at_least(0),
         .when_key = "type",
         .when_values = {"uniform"},
         .units = "m/s",
         .meaning = "Amplitude e of a cross-stream velocity v = e sin(2 pi (x - x_start) / L_x) added at t = 0: "
                    "it breaks the mirror symmetry of a symmetric set-up so that vortex shedding starts within "
                    "a few periods instead of growing from round-off (0.01 U is plenty)."},

        {.path = "boundaries",
         .type = K::section,
         .required = true,
         .meaning = "One condition per side; all four sides are required."},
        {.path = "boundaries.<side>",
         .type = K::section,
         .required = true,
         .meaning = "Condition on one side of the domain."},
        {.path = "boundaries.<side>.type",
         .type = K::choice,
         .required = true,
         .choices = {"wall", "slip", "inflow", "outflow", "periodic"},
         .meaning = "`wall`: no slip, the wall moving at `velocity`; `slip`: free slip (no flow through, "
                    "no shear stress); `inflow`: given velocity into the domain; `outflow`: open exit; "
                    "`periodic`: the flow leaving here enters at the opposite side (set on both)."},
        {.path = "boundaries.<side>.velocity",
         .type = K::vector2,
         .default_value = "[0.0, 0.0]",
         .when_key = "type",
         .when_values = {"wall", "inflow"},
         .units = "m/s",
         .meaning =
             "Wall: the wall's own velocity, along the wall (normal component 0). Inflow with "
             "`profile: uniform`: the inflow velocity (required there), pointing into the domain, or 0: water at rest, "
             "which a grid carried by a moving body_fitted body meets ahead of it."},
        {.path = "boundaries.<side>.profile",
         .type = K::choice,
         .default_value = "uniform",
         .choices = {"uniform", "parabolic"},
         .when_key = "type",
         .when_values = {"inflow"},
         .meaning = "Inflow profile: `uniform` (the vector `velocity`) or `parabolic` (normal to the side, "
                    "zero at its ends, `peak` at its middle)."},
        {.path = "boundaries.<side>.peak",
         .type = K::number,
         .required = true,
         .min = above(0),
         .when_key = "profile",
         .when_values = {"parabolic"},
         .units = "m/s",
         .meaning = "Peak speed into the domain of a parabolic inflow."},
        {.path = "boundaries.<side>.kind",
         .type = K::choice,
         .default_value = "convective",
         .choices = {"convective", "zero_stress"},
         .when_key = "type",
         .when_values = {"outflow"},
         .meaning = "Outflow condition: `convective` (du_n/dt + U du_n/dn = 0, U the mean exit speed: "
                    "eddies leave cleanly) or `zero_stress` (du_n/dn = 0 and p = 0: zero normal stress)."},

        {.path = "numerics", .type = K::section, .meaning = "Discretisation, time step and solver settings."},
        {.path = "numerics.convection",
         .type = K::choice,
         .default_value = "central",
         .choices = {"central", "van_leer", "koren"},
         .meaning = "Convection scheme: `central` (second order) or a TVD scheme with the `van_leer` or "
                    "`koren` limiter."},
        {.path = "numerics.cfl",
         .type = K::number,
         .default_value = "0.3",
         .min = above(0),
         .max = at_most(1),
         .meaning = "Courant number of the adaptive time step, dt <= cfl / max(|u|/dx + |v|/dy). With "
                    "Adams-Bashforth 2 the stable limits measured on the Re 1000 cavity (128^2) are 0.5 and "
                    "more for `central`, 0.4 for `van_leer`, 0.3 for `koren`: the default suits all three."},
        {.path = "numerics.diffusion_number",
         .type = K::number,
         .default_value = "0.2",
         .min = above(0),
         .max = at_most(0.25),
         .meaning = "Diffusion number d of the adaptive time step: dt <= d / (nu (1/dx^2 + 1/dy^2)); "
                    "the explicit update is stable up to 1/4."},
        {.path = "numerics.diffusion",
         .type = K::choice,
         .default_value = "auto",
         .choices = {"auto", "explicit", "implicit"},
         .meaning = "Time integration of the viscous and turbulent stress: `explicit` (Adams-Bashforth 2, "
                    "second order, step limited by diffusion_number) or `implicit` (backward Euler for the "
                    "normal and same-direction shear terms, first order, no diffusion limit on the step; "
                    "core/implicit_diffusion.hpp). `auto`: explicit for laminar runs; with k-epsilon the step "
                    "follows the CFL number alone and each step is implicit when it exceeds the explicit "
                    "diffusion limit of nu + max nu_t (and stays implicit until the step is below 2/3 of that "
                    "limit); the step after a switch is forward Euler."},
        {.path = "numerics.dt",
         .type = K::number_or_auto,
         .default_value = "auto",
         .min = above(0),
         .units = "s",
         .meaning = "`auto`: dt follows cfl and diffusion_number each step; a number: fixed dt."},
        {.path = "numerics.max_dt",
         .type = K::number,
         .default_value = "1.0e30",
         .min = above(0),
         .units = "s",
         .meaning = "Upper limit of the time step."},
        {.path = "numerics.poisson", .type = K::section, .meaning = "Pressure Poisson solver."},
        {.path = "numerics.poisson.tolerance",
         .type = K::number,
         .default_value = "1.0e-8",
         .min = above(0),
         .max = at_most(1e-2),
         .meaning = "Convergence tolerance (relative residual)."},
        {.path = "numerics.poisson.max_iterations",
         .type = K::integer,
         .default_value = "200",
         .min = at_least(1),
         .meaning = "Iteration limit per solve."},
        {.path = "numerics.poisson.solver",
         .type = K::choice,
         .default_value = "auto",
         .choices = {"auto", "multigrid"},
         .meaning = "`auto`: a direct solve (FFTW transform along a uniform axis, tridiagonal systems along the "
                    "other) where an axis is uniform and no cell is solid, else hypre's PFMG-preconditioned CG "
                    "(tolerance and max_iterations apply to it); `multigrid`: always hypre."},
        {.path = "numerics.divergence_limit",
         .type = K::number,
         .default_value = "1.0e-3",
         .min = above(0),
         .meaning = "The run stops with an error when max |div u| dt exceeds this."},

        {.path = "time", .type = K::section, .required = true, .meaning = "Length of the run."},
        {.path = "time.end",
         .type = K::number,
         .required = true,
         .min = above(0),
         .units = "s",
         .meaning = "Simulated time at which the run ends."},
        {.path = "time.max_steps",
         .type = K::integer,
         .default_value = "-1",
         .min = at_least(1),
         .also = -1,
         .meaning = "Step limit; -1: none."},

        {.path = "parallel", .type = K::section, .meaning = "Domain decomposition."},
        {.path = "parallel.ranks",
         .type = K::integer_vector2,
         .default_value = "[0, 0]",
         .min = at_least(0),
         .meaning = "Number of MPI patches along x and y; 0: chosen automatically (with one uniform axis and the "
                    "direct Poisson solve, only the other axis is split; else MPI's choice)."},
    };
}

std::vector<Placeholder> flow_placeholders() {
    return {{"<axis>", {"x", "y"}}, {"<side>", {kSideNames.begin(), kSideNames.end()}}};
}

FlowConfig read_flow(const CaseReader& r) {
    FlowConfig c;
    const double refinement = r.number("domain.refinement");
    read_axis(r, "domain.x", refinement, c.x);
    read_axis(r, "domain.y", refinement, c.y);
    check_grid(r, c);
    c.depth = r.number("domain.depth");

    c.density = r.number("fluid.density");
    c.viscosity = r.number("fluid.viscosity");
    c.body_force = r.vector2("fluid.body_force");

    c.initial = r.choice<InitialCondition>(
        "initial.type", {{"uniform", InitialCondition::uniform}, {"taylor_green", InitialCondition::taylor_green}});
    c.initial_velocity = r.vector2("initial.velocity");
    c.taylor_green_amplitude = r.number("initial.amplitude");
    c.initial_perturbation = r.number("initial.perturbation");

    for (int s = 0; s < 4; ++s) read_boundary(r, s, c.boundary[s]);
    check_boundaries(r, c);

    c.convection = r.choice<ConvectionScheme>("numerics.convection", {{"central", ConvectionScheme::central},
                                                                      {"van_leer", ConvectionScheme::van_leer},
                                                                      {"koren", ConvectionScheme::koren}});
    c.cfl = r.number("numerics.cfl");
    c.diffusion_number = r.number("numerics.diffusion_number");
    c.diffusion = r.choice<DiffusionScheme>("numerics.diffusion", {{"explicit", DiffusionScheme::explicit_ab2},
                                                                   {"implicit", DiffusionScheme::implicit_euler},
                                                                   {"auto", DiffusionScheme::automatic}});
    c.fixed_dt = r.number_or_auto("numerics.dt");
    c.max_dt = r.number("numerics.max_dt");
    if (c.fixed_dt && *c.fixed_dt > c.max_dt)
        r.fail("numerics.dt",
               "must not exceed numerics.max_dt (" + exact_text(c.max_dt) + "), got " + exact_text(*c.fixed_dt));
    c.poisson_tolerance = r.number("numerics.poisson.tolerance");
    c.poisson_max_iterations = static_cast<int>(r.integer("numerics.poisson.max_iterations"));
    c.poisson_method = r.choice<PoissonMethod>(
        "numerics.poisson.solver", {{"auto", PoissonMethod::automatic}, {"multigrid", PoissonMethod::multigrid}});
    c.divergence_limit = r.number("numerics.divergence_limit");

    c.end_time = r.number("time.end");
    c.max_steps = r.integer("time.max_steps");

    c.ranks = r.integer_vector2("parallel.ranks");
    return c;
}

}  // namespace chute
