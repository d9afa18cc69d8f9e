// Case files: YAML text -> table of key paths -> checks -> CaseConfig.
//
//   1. yaml-cpp parses the text; a syntax error becomes a CaseError with its line and column.
//   2. Reader::add_document() walks the mappings and files every key under its full path
//      ("boundaries.left.velocity"). A key the schema does not know is an error, with the nearest known
//      key suggested (optimal string alignment distance) or the keys allowed there listed.
//   3. Reader::add_override() applies each --set: it replaces (or adds) that path and its sub-keys.
//   4. Reader::check_presence(): required keys are given; conditional keys (`when`) appear only where they
//      apply and, when required, are given there.
//   5. Reader::build(): typed reads against the schema (type, range, choices; absent keys take the
//      schema's default, so the documented default is the one used), then the checks that involve
//      several keys (end > start, periodic pairs, wall velocity tangential, probes inside, ...).
#include "case_file.hpp"

#include "axis.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <map>
#include <sstream>
#include <utility>

namespace chute {

namespace {

constexpr Bound above(double v) { return {v, false}; }
constexpr Bound at_least(double v) { return {v, true}; }
constexpr Bound at_most(double v) { return {v, true}; }

std::vector<CaseKey> make_schema() {
    using K = KeyType;
    const std::vector<std::string_view> from_ends = {"uniform", "tanh", "geometric", "clustered"};
    return {
        {.path = "name",
         .type = K::string,
         .default_doc = "file stem",
         .meaning = "Run name; output files are named after it. Default: the case file's name without "
                    "its extension."},

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
        {.path = "domain.<axis>.lines",
         .type = K::number_list,
         .required = true,
         .when_key = "spacing",
         .when_values = {"lines"},
         .units = "m",
         .meaning = "Every grid line, strictly increasing, at least 3; start, end and cells follow from "
                    "them and are not given."},
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
        {.path = "gravity",
         .type = K::vector2,
         .default_value = "[0.0, -9.81]",
         .units = "m/s^2",
         .meaning = "Gravity on free bodies. The pressure is dynamic (hydrostatic part removed), so the fluid "
                    "feels no gravity and each free body gets its buoyancy -rho_f V g explicitly."},

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
         .meaning = "Wall: the wall's own velocity, along the wall (normal component 0). Inflow with "
                    "`profile: uniform`: the inflow velocity (required there), pointing into the domain."},
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

        {.path = "bodies",
         .type = K::section,
         .meaning = "Immersed bodies, each under a name of its choosing (letters, digits, _ and -); the "
                    "name labels its output file `body_<name>.csv`. No bodies: no forcing."},
        {.path = "bodies.<body>", .type = K::section, .meaning = "One body."},
        {.path = "bodies.<body>.shape",
         .type = K::choice,
         .required = true,
         .choices = {"circle", "rectangle", "polygon", "plane", "segment"},
         .meaning = "`circle`; `rectangle` (the block); `polygon` (any closed outline); `plane` (a static "
                    "straight boundary across the domain: a bed or a slope); `segment` (a static straight "
                    "piece of boundary between two points). Planes and segments have their solid on the "
                    "right of their direction: a plane at angle 0 has its solid below."},
        {.path = "bodies.<body>.centre",
         .type = K::vector2,
         .required = true,
         .when_key = "shape",
         .when_values = {"circle", "rectangle"},
         .units = "m",
         .meaning = "Initial centre of the circle or rectangle."},
        {.path = "bodies.<body>.diameter",
         .type = K::number,
         .required = true,
         .min = above(0),
         .when_key = "shape",
         .when_values = {"circle"},
         .units = "m",
         .meaning = "Diameter of the circle."},
        {.path = "bodies.<body>.size",
         .type = K::vector2,
         .required = true,
         .min = above(0),
         .when_key = "shape",
         .when_values = {"rectangle"},
         .units = "m",
         .meaning = "Width (along x before rotation) and height of the rectangle."},
        {.path = "bodies.<body>.vertices",
         .type = K::point_list,
         .required = true,
         .when_key = "shape",
         .when_values = {"polygon"},
         .units = "m",
         .meaning = "Corners of the polygon in place, in order around it (either way round); at least 3. Its "
                    "centre is its centroid."},
        {.path = "bodies.<body>.angle",
         .type = K::number,
         .default_value = "0.0",
         .when_key = "shape",
         .when_values = {"rectangle", "polygon", "plane"},
         .units = "deg",
         .meaning = "Rectangle, polygon: initial rotation about the centre, counterclockwise. Plane: "
                    "inclination of its direction from the x axis (0: a horizontal bed, solid below; 30: a "
                    "slope rising to the right, solid below it)."},
        {.path = "bodies.<body>.point",
         .type = K::vector2,
         .required = true,
         .when_key = "shape",
         .when_values = {"plane"},
         .units = "m",
         .meaning = "A point of the plane, inside the domain."},
        {.path = "bodies.<body>.from",
         .type = K::vector2,
         .required = true,
         .when_key = "shape",
         .when_values = {"segment"},
         .units = "m",
         .meaning = "First end of the segment."},
        {.path = "bodies.<body>.to",
         .type = K::vector2,
         .required = true,
         .when_key = "shape",
         .when_values = {"segment"},
         .units = "m",
         .meaning = "Second end of the segment; the solid lies on the right going from `from` to `to`."},
        {.path = "bodies.<body>.motion",
         .type = K::section,
         .meaning = "Prescribed motion of the centre and angle (closed shapes only; planes and segments are "
                    "fixed)."},
        {.path = "bodies.<body>.motion.type",
         .type = K::choice,
         .default_value = "fixed",
         .choices = {"fixed", "constant_velocity", "oscillation", "uniform_acceleration", "free"},
         .meaning = "`fixed`; `constant_velocity`: x = x0 + V t; `oscillation`: x = x0 + A sin(2 pi f t + "
                    "phase); `uniform_acceleration` from rest: x = x0 + a t^2/2. The angle follows the same "
                    "law with its own rate, amplitude or acceleration. `free`: moved by gravity, buoyancy, the "
                    "fluid and contact (needs `density`); `velocity` and `angular_velocity` are its start."},
        {.path = "bodies.<body>.motion.lock_x",
         .type = K::boolean,
         .default_value = "false",
         .when_key = "type",
         .when_values = {"free"},
         .meaning = "Keep the free body from moving along x."},
        {.path = "bodies.<body>.motion.lock_y",
         .type = K::boolean,
         .default_value = "false",
         .when_key = "type",
         .when_values = {"free"},
         .meaning = "Keep the free body from moving along y."},
        {.path = "bodies.<body>.motion.lock_rotation",
         .type = K::boolean,
         .default_value = "false",
         .when_key = "type",
         .when_values = {"free"},
         .meaning = "Keep the free body from turning (Turmel & Locat 2008 locked rotation)."},
        {.path = "bodies.<body>.motion.velocity",
         .type = K::vector2,
         .default_value = "[0.0, 0.0]",
         .when_key = "type",
         .when_values = {"constant_velocity", "free"},
         .units = "m/s",
         .meaning = "Velocity V of the centre (`free`: at the start)."},
        {.path = "bodies.<body>.motion.angular_velocity",
         .type = K::number,
         .default_value = "0.0",
         .when_key = "type",
         .when_values = {"constant_velocity", "free"},
         .units = "rad/s",
         .meaning = "Angular velocity, counterclockwise (`free`: at the start)."},
        {.path = "bodies.<body>.motion.amplitude",
         .type = K::vector2,
         .default_value = "[0.0, 0.0]",
         .when_key = "type",
         .when_values = {"oscillation"},
         .units = "m",
         .meaning = "Amplitude A of the centre's oscillation (a negative component reverses its phase)."},
        {.path = "bodies.<body>.motion.angular_amplitude",
         .type = K::number,
         .default_value = "0.0",
         .when_key = "type",
         .when_values = {"oscillation"},
         .units = "deg",
         .meaning = "Amplitude of the angle's oscillation."},
        {.path = "bodies.<body>.motion.frequency",
         .type = K::number,
         .required = true,
         .min = above(0),
         .when_key = "type",
         .when_values = {"oscillation"},
         .units = "Hz",
         .meaning = "Frequency f of the oscillation."},
        {.path = "bodies.<body>.motion.phase",
         .type = K::number,
         .default_value = "0.0",
         .when_key = "type",
         .when_values = {"oscillation"},
         .units = "deg",
         .meaning = "Phase of the oscillation at t = 0."},
        {.path = "bodies.<body>.motion.acceleration",
         .type = K::vector2,
         .default_value = "[0.0, 0.0]",
         .when_key = "type",
         .when_values = {"uniform_acceleration"},
         .units = "m/s^2",
         .meaning = "Acceleration a of the centre."},
        {.path = "bodies.<body>.motion.angular_acceleration",
         .type = K::number,
         .default_value = "0.0",
         .when_key = "type",
         .when_values = {"uniform_acceleration"},
         .units = "rad/s^2",
         .meaning = "Angular acceleration, counterclockwise."},
        {.path = "bodies.<body>.density",
         .type = K::number,
         .min = above(0),
         .units = "kg/m^3",
         .meaning = "Density of a free body (the study's rocks: 2400-2700). Required with motion type `free`."},
        {.path = "bodies.<body>.reference",
         .type = K::section,
         .meaning = "Scales of the force coefficients C = F / (0.5 rho U^2 L depth) in the body's time "
                    "series."},
        {.path = "bodies.<body>.reference.velocity",
         .type = K::number,
         .default_value = "1.0",
         .min = above(0),
         .units = "m/s",
         .meaning = "Reference speed U."},
        {.path = "bodies.<body>.reference.length",
         .type = K::number,
         .default_doc = "size across x",
         .min = above(0),
         .units = "m",
         .meaning = "Reference length L. Default: the body's height (its extent across the x direction): "
                    "a circle's diameter, a rectangle's height; a plane's or segment's length."},

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
        {.path = "numerics.ibm", .type = K::section, .meaning = "Immersed-boundary forcing and force sampling."},
        {.path = "numerics.ibm.kernel",
         .type = K::choice,
         .default_value = "roma3",
         .choices = {"roma3", "peskin4"},
         .meaning = "Regularised delta kernel: `roma3` (Roma, Peskin & Berger 1999; 3 points per direction) "
                    "or `peskin4` (Peskin 2002; 4 points, smoother, thicker interface)."},
        {.path = "numerics.ibm.forcing_iterations",
         .type = K::integer,
         .default_value = "3",
         .min = at_least(1),
         .max = at_most(50),
         .meaning = "Multi-direct forcing iterations per step (Breugem 2012): each one shrinks the slip "
                    "error at the markers."},
        {.path = "numerics.ibm.marker_spacing",
         .type = K::number,
         .default_value = "1.0",
         .min = at_least(0.3),
         .max = at_most(2.0),
         .meaning = "Distance between neighbouring markers, in grid cells (the smallest cell along the "
                    "outline)."},
        {.path = "numerics.ibm.retraction",
         .type = K::number,
         .default_value = "0.3",
         .min = at_least(0.0),
         .max = at_most(1.0),
         .meaning =
             "Markers of closed outlines moved this many cells inside the surface, to offset the "
             "thickness of the diffuse interface (Breugem 2012, 0.3 with the roma3 kernel). 0.3 puts the DFG 2D-1 "
             "drag in the published band at 40 cells per diameter (docs/validation.md)."},
        {.path = "numerics.ibm.stress_probes",
         .type = K::vector2,
         .default_value = "[1.5, 2.5]",
         .min = above(0),
         .meaning = "Distances from the surface, in cells along the normal, of the two probes that sample "
                    "pressure and velocity for the surface-stress force (extrapolated to the surface)."},
        {.path = "numerics.ibm.virtual_mass",
         .type = K::number,
         .default_value = "1.0",
         .min = at_least(0.0),
         .max = at_most(2.0),
         .meaning = "Virtual-mass coefficient C_V of the free-body update (Schwarz, Kempe & Froehlich 2015): C_V "
                    "rho_f V dU/dt is added to both sides, so light bodies (rho_s/rho_f near or below 1) stay "
                    "stable with an explicit coupling. It cancels at convergence; 0 switches it off."},

        {.path = "contact",
         .type = K::section,
         .meaning = "Impacts of free bodies on planes and on wall or slip sides of the domain."},
        {.path = "contact.law",
         .type = K::choice,
         .default_value = "lumped",
         .choices = {"lumped", "impulse", "soft"},
         .meaning = "`lumped` (RocFall's lumped mass): v_n' = -Rn v_n, v_t' = Rt v_t on the centre's velocity, "
                    "spin kept. `impulse`: the same coefficients on the contact point's velocity, through an "
                    "impulse that also changes the spin. `soft`: a linear spring-dashpot at the contact point "
                    "lasting `duration`, damped to give Rn, with Coulomb `friction` along the surface."},
        {.path = "contact.normal_restitution",
         .type = K::number,
         .default_value = "0.8",
         .min = at_least(0.0),
         .max = at_most(1.0),
         .meaning = "Rn (Turmel & Locat 2008: 0.8)."},
        {.path = "contact.tangential_restitution",
         .type = K::number,
         .default_value = "0.8",
         .min = at_least(0.0),
         .max = at_most(1.0),
         .meaning = "Rt (Turmel & Locat 2008: 0.8)."},
        {.path = "contact.rest_speed",
         .type = K::number,
         .default_value = "0.01",
         .min = above(0.0),
         .units = "m/s",
         .meaning = "A rebound slower than this (normal speed of the contact point) leaves the body resting on "
                    "the obstacle, sliding with `friction`."},
        {.path = "contact.distance",
         .type = K::number,
         .default_value = "0.0",
         .min = at_least(0.0),
         .units = "m",
         .meaning = "Gap at which an impact happens. 0: at the surface. In water a flat face that meets a wall "
                    "squarely is stopped by the fluid it squeezes out; below about one cell the squeeze film is "
                    "unresolved (docs/validation.md), so a contact distance of one or two cells stands for the "
                    "unresolved approach. Turmel & Locat's body-fitted mesh needed about 0.1 m."},
        {.path = "contact.duration",
         .type = K::number,
         .default_value = "0.002",
         .min = above(0.0),
         .units = "s",
         .meaning = "Soft law: the duration of one impact (it sets the spring's stiffness; Rn sets its "
                    "damping). It is sub-stepped in 100 steps whatever the flow's step."},
        {.path = "contact.friction",
         .type = K::number,
         .default_value = "0.0",
         .min = at_least(0.0),
         .meaning = "Coulomb friction coefficient of a body resting (sliding) on an obstacle."},

        {.path = "lumped",
         .type = K::section,
         .meaning = "The lumped trajectory models written beside a run with free bodies (`lumped_<body>.csv`)."},
        {.path = "lumped.drag_coefficient",
         .type = K::number,
         .default_value = "2.0",
         .min = at_least(0.0),
         .meaning = "C_D of the Beranger et al. (1998) model (Turmel & Locat 2008: 2.0 for the block)."},
        {.path = "lumped.added_mass_coefficient",
         .type = K::number,
         .default_value = "0.5",
         .min = at_least(0.0),
         .meaning = "C_a of the Beranger model (Turmel & Locat 2008: 0.5)."},

        {.path = "turbulence",
         .type = K::section,
         .meaning = "Turbulence model (turbulence/). Inflow and initial k and epsilon follow from an intensity "
                    "and a length scale."},
        {.path = "turbulence.model",
         .type = K::choice,
         .default_value = "laminar",
         .choices = {"laminar", "k_epsilon"},
         .meaning = "`laminar`: molecular viscosity only. `k_epsilon`: standard k-epsilon (Launder & Spalding "
                    "1974: C_mu 0.09, C_1 1.44, C_2 1.92, sigma_k 1.0, sigma_eps 1.3) with log-law wall "
                    "functions (kappa 0.41, E 9.8, switch at y+ 11.53) on wall sides and immersed surfaces."},
        {.path = "turbulence.intensity",
         .type = K::number,
         .default_value = "0.05",
         .min = above(0.0),
         .max = at_most(1.0),
         .meaning = "Turbulence intensity I of the inflow and the initial field: k = 3/2 (I U)^2."},
        {.path = "turbulence.length_scale",
         .type = K::number,
         .default_value = "0.1",
         .min = above(0.0),
         .units = "m",
         .meaning = "Turbulence length scale l of the inflow and the initial field: eps = C_mu^(3/4) k^(3/2) / l."},
        {.path = "turbulence.velocity_scale",
         .type = K::number,
         .default_value = "0.0",
         .min = at_least(0.0),
         .units = "m/s",
         .meaning = "Speed U of the initial k. 0: the largest inflow or initial speed; give it for a body "
                    "released in still water (for instance its expected fall speed)."},
        {.path = "turbulence.production_limit",
         .type = K::number,
         .default_value = "10.0",
         .min = at_least(0.0),
         .meaning = "Production limiter P_k <= limit * eps (Menter 1994), which stops k piling up at "
                    "stagnation points; 0 switches it off."},
        {.path = "turbulence.production",
         .type = K::choice,
         .default_value = "standard",
         .choices = {"standard", "kato_launder"},
         .meaning = "Production of k: `standard` P_k = nu_t S^2, or `kato_launder` P_k = nu_t S Omega (Kato & "
                    "Launder 1993; S and Omega the strain and rotation rates), which is zero in irrotational "
                    "strain and so removes the standard model's excess of k where the flow meets a bluff "
                    "body's front face; the same in simple shear."},
        {.path = "turbulence.image_distance",
         .type = K::number,
         .default_value = "2.0",
         .min = above(0.0),
         .meaning = "Distance from an immersed surface, in cells along the normal, of the image point where "
                    "the wall function samples the tangential velocity and k (outside the forcing's reach)."},

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
         .meaning = "Number of MPI patches along x and y; 0: chosen automatically."},

        {.path = "output", .type = K::section, .meaning = "What is written, and how often."},
        {.path = "output.fields_interval",
         .type = K::number,
         .default_value = "0.0",
         .min = at_least(0),
         .units = "s",
         .meaning = "Simulated time between field snapshots; 0: first and last only."},
        {.path = "output.checkpoint_interval",
         .type = K::number,
         .default_value = "0.0",
         .min = at_least(0),
         .units = "s",
         .meaning = "Simulated time between checkpoints; 0: at the end only."},
        {.path = "output.checkpoints_kept",
         .type = K::integer,
         .default_value = "2",
         .min = at_least(1),
         .meaning = "Number of newest checkpoints kept; older ones are deleted."},
        {.path = "output.timeseries_every",
         .type = K::integer,
         .default_value = "1",
         .min = at_least(1),
         .units = "steps",
         .meaning = "Steps between rows of the time series."},
        {.path = "output.progress_interval",
         .type = K::number,
         .default_value = "2.0",
         .min = at_least(0),
         .units = "s (wall)",
         .meaning = "Wall-clock time between progress lines."},
        {.path = "output.probes",
         .type = K::point_list,
         .default_value = "[]",
         .units = "m",
         .meaning = "Points [x, y] sampled into the time series; each must lie inside the domain."},
        {.path = "output.plots", .type = K::boolean, .default_value = "true", .meaning = "Write plots of the results."},
    };
}

// ---- key paths -------------------------------------------------------------------------------------

constexpr std::array<std::string_view, 4> kSideNames = {"left", "right", "bottom", "top"};

// A body name: letters, digits, '_' and '-', starting with a letter.
bool is_body_name(std::string_view s) {
    if (s.empty() || !std::isalpha(static_cast<unsigned char>(s[0]))) return false;
    return std::all_of(s.begin(), s.end(),
                       [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-'; });
}

// The names a path segment stands for: a placeholder's values, or itself. (`<body>` stands for any body
// name and is matched by segment_matches.)
std::vector<std::string_view> expand(std::string_view segment) {
    if (segment == "<axis>") return {"x", "y"};
    if (segment == "<side>") return {kSideNames.begin(), kSideNames.end()};
    return {segment};
}

std::vector<std::string_view> split(std::string_view path) {
    std::vector<std::string_view> parts;
    if (path.empty()) return parts;
    for (std::size_t begin = 0;;) {
        const std::size_t dot = path.find('.', begin);
        parts.push_back(path.substr(begin, dot == std::string_view::npos ? dot : dot - begin));
        if (dot == std::string_view::npos) return parts;
        begin = dot + 1;
    }
}

std::string_view parent_of(std::string_view path) {
    const std::size_t dot = path.rfind('.');
    return dot == std::string_view::npos ? std::string_view{} : path.substr(0, dot);
}

std::string_view leaf_of(std::string_view path) {
    const std::size_t dot = path.rfind('.');
    return dot == std::string_view::npos ? path : path.substr(dot + 1);
}

std::string join(std::string_view parent, std::string_view leaf) {
    return parent.empty() ? std::string(leaf) : std::string(parent) + "." + std::string(leaf);
}

std::string indexed(std::string_view path, std::size_t i) { return std::string(path) + "[" + std::to_string(i) + "]"; }

// Does the concrete path ("boundaries.left.type") match the schema pattern ("boundaries.<side>.type")?
bool segment_matches(std::string_view pattern, std::string_view name) {
    if (pattern == "<body>") return is_body_name(name);
    const auto names = expand(pattern);
    return std::find(names.begin(), names.end(), name) != names.end();
}

bool matches(std::string_view pattern, std::string_view path) {
    const auto a = split(pattern), b = split(path);
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!segment_matches(a[i], b[i])) return false;
    return true;
}

const CaseKey* find_key(std::string_view path) {
    for (const CaseKey& key : case_schema())
        if (matches(key.path, path)) return &key;
    return nullptr;
}

// The key names the schema allows directly under a concrete section ("" for the top level).
std::vector<std::string> keys_under(std::string_view section) {
    std::vector<std::string> names;
    for (const CaseKey& key : case_schema())
        if (matches(parent_of(key.path), section))
            for (std::string_view name : expand(leaf_of(key.path))) names.emplace_back(name);
    return names;
}

// ---- text helpers ----------------------------------------------------------------------------------

std::string fmt(double v) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, result.ptr);
}

std::string list(const std::vector<std::string_view>& items, std::string_view last_sep = ", ") {
    std::string s;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) s += (i + 1 == items.size()) ? last_sep : ", ";
        s += items[i];
    }
    return s;
}

// The gist of a key's meaning, for a hint: its text up to the first '.', ';' or ':'.
std::string gist(std::string_view text) {
    std::size_t stop = text.size();
    for (std::string_view mark : {". ", "; ", ": "}) stop = std::min(stop, text.find(mark));
    std::string s(text.substr(0, stop));
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

// Optimal string alignment distance: edits, with a swap of neighbours counting as one.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// The candidate nearest to `word`, if it is near enough to be a likely typo.
std::optional<std::string> nearest(std::string_view word, const std::vector<std::string>& candidates) {
    const std::size_t limit = std::clamp<std::size_t>(word.size() / 3, 1, 3);
    std::optional<std::string> best;
    std::size_t best_distance = limit + 1;
    for (const std::string& c : candidates) {
        const std::size_t d = edit_distance(word, c);
        if (d < best_distance) best = c, best_distance = d;
    }
    return best;
}

// The hint after "unknown key": the likely intended key, or the keys allowed there.
std::string unknown_key_hint(std::string_view path) {
    const std::string_view section = parent_of(path), name = leaf_of(path);
    const std::vector<std::string> siblings = keys_under(section);
    if (auto best = nearest(name, siblings)) return "; did you mean '" + join(section, *best) + "'?";
    for (const CaseKey& key : case_schema())
        if (leaf_of(key.path) == name) return "; did you mean '" + std::string(key.path) + "'?";
    std::string hint = section.empty() ? "; top-level keys: " : "; keys in " + std::string(section) + ": ";
    for (std::size_t i = 0; i < siblings.size(); ++i) hint += (i ? ", " : "") + siblings[i];
    return hint;
}

std::string describe(const YAML::Node& n) {
    switch (n.Type()) {
        case YAML::NodeType::Scalar:
            return "'" + n.Scalar() + "'";
        case YAML::NodeType::Sequence:
            return "a list";
        case YAML::NodeType::Map:
            return "a mapping";
        default:
            return "nothing (empty value)";
    }
}

std::string range_text(const CaseKey& k, bool in_sentence) {
    std::string r;
    if (k.min && k.max)
        r = std::string(in_sentence ? "in " : "") + (k.min->inclusive ? "[" : "(") + fmt(k.min->value) + ", " +
            fmt(k.max->value) + (k.max->inclusive ? "]" : ")");
    else if (k.min)
        r = (k.min->inclusive ? ">= " : "> ") + fmt(k.min->value);
    else if (k.max)
        r = (k.max->inclusive ? "<= " : "< ") + fmt(k.max->value);
    if (k.also) r = fmt(*k.also) + " or " + r;
    return r;
}

template <class E>
E to_enum(std::string_view path, const std::string& value,
          std::initializer_list<std::pair<std::string_view, E>> table) {
    for (const auto& [name, e] : table)
        if (name == value) return e;
    throw std::logic_error("case_file: choice '" + value + "' of " + std::string(path) + " has no enum value");
}

YAML::Node load_yaml(const std::string& text, const std::string& file) {
    try {
        return YAML::Load(text);
    } catch (const YAML::Exception& e) {
        std::string where = file.empty() ? "" : file + ", ";
        if (!e.mark.is_null())
            where += "line " + std::to_string(e.mark.line + 1) + ", column " + std::to_string(e.mark.column + 1);
        throw CaseError(where + ": YAML syntax error: " + e.msg);
    }
}

// ---- the reader ------------------------------------------------------------------------------------

class Reader {
public:
    Reader(std::string file, std::string default_name)
        : file_(std::move(file)), default_name_(std::move(default_name)) {}

    void add_document(const YAML::Node& root) {
        if (!root.IsDefined() || root.IsNull()) return;  // an empty file: the required keys are missing
        if (!root.IsMap()) fail("", "a case is a mapping of keys (key: value lines), got " + describe(root), &root);
        flatten(root, "");
    }

    void add_override(const std::string& text) {
        const std::string where = "--set " + text;
        const std::size_t eq = text.find('=');
        if (eq == std::string::npos) throw CaseError(where + ": expected key.path=value");
        const std::string path = trim(text.substr(0, eq));
        if (path.empty()) throw CaseError(where + ": no key path before '='");
        // Every step of the path must be a known key, and all but the last a section.
        const auto steps = split(path);
        std::string prefix;
        for (std::size_t i = 0; i < steps.size(); ++i) {
            prefix = join(prefix, steps[i]);
            const CaseKey* key = find_key(prefix);
            if (!key) throw CaseError(where + ": " + prefix + ": unknown key" + unknown_key_hint(prefix));
            if (i + 1 < steps.size() && key->type != KeyType::section)
                throw CaseError(where + ": " + prefix + ": takes a value, it has no sub-keys");
            if (i + 1 < steps.size() && !entries_.contains(prefix))
                entries_[prefix] = {YAML::Node(YAML::NodeType::Null), YAML::Mark::null_mark(), text};
        }
        YAML::Node value;
        try {
            value = YAML::Load(text.substr(eq + 1));
        } catch (const YAML::Exception& e) {
            throw CaseError(where + ": " + path + ": YAML syntax error in the value: " + e.msg);
        }
        // The new value replaces the old one and everything under it.
        std::erase_if(entries_,
                      [&](const auto& entry) { return entry.first == path || entry.first.starts_with(path + "."); });
        entries_[path] = {value, YAML::Mark::null_mark(), text};
        if (find_key(path)->type == KeyType::section) flatten_section(value, path);
    }

    CaseConfig build() const {
        check_presence();
        CaseConfig c;

        c.name = present("name") ? string("name") : default_name_;
        if (c.name.empty()) fail("name", "must not be empty");
        if (c.name.find_first_of("/\\") != std::string::npos)
            fail("name", "must not contain '/' or '\\' (output files are named after it), got '" + c.name + "'");

        read_axis("domain.x", c.x);
        read_axis("domain.y", c.y);
        c.depth = number("domain.depth");

        c.density = number("fluid.density");
        c.viscosity = number("fluid.viscosity");
        c.body_force = vector2("fluid.body_force");
        c.gravity = vector2("gravity");
        c.contact.law = to_enum<ReboundLaw>(
            "contact.law", choice("contact.law"),
            {{"lumped", ReboundLaw::lumped}, {"impulse", ReboundLaw::impulse}, {"soft", ReboundLaw::soft}});
        c.contact.normal_restitution = number("contact.normal_restitution");
        c.contact.tangential_restitution = number("contact.tangential_restitution");
        c.contact.rest_speed = number("contact.rest_speed");
        c.contact.friction = number("contact.friction");
        c.contact.distance = number("contact.distance");
        c.contact.duration = number("contact.duration");
        c.lumped.drag_coefficient = number("lumped.drag_coefficient");
        c.lumped.added_mass_coefficient = number("lumped.added_mass_coefficient");

        c.turbulence.model = to_enum<TurbulenceModelType>(
            "turbulence.model", choice("turbulence.model"),
            {{"laminar", TurbulenceModelType::laminar}, {"k_epsilon", TurbulenceModelType::k_epsilon}});
        c.turbulence.intensity = number("turbulence.intensity");
        c.turbulence.length_scale = number("turbulence.length_scale");
        c.turbulence.velocity_scale = number("turbulence.velocity_scale");
        c.turbulence.production_limit = number("turbulence.production_limit");
        c.turbulence.kato_launder = choice("turbulence.production") == "kato_launder";
        c.turbulence.image_distance = number("turbulence.image_distance");

        c.initial = to_enum<InitialCondition>(
            "initial.type", choice("initial.type"),
            {{"uniform", InitialCondition::uniform}, {"taylor_green", InitialCondition::taylor_green}});
        c.initial_velocity = vector2("initial.velocity");
        c.taylor_green_amplitude = number("initial.amplitude");
        c.initial_perturbation = number("initial.perturbation");

        for (int s = 0; s < 4; ++s) read_boundary(s, c.boundary[s]);
        check_boundaries(c);

        read_ibm(c.ibm);
        read_bodies(c);

        c.convection = to_enum<ConvectionScheme>("numerics.convection", choice("numerics.convection"),
                                                 {{"central", ConvectionScheme::central},
                                                  {"van_leer", ConvectionScheme::van_leer},
                                                  {"koren", ConvectionScheme::koren}});
        c.cfl = number("numerics.cfl");
        c.diffusion_number = number("numerics.diffusion_number");
        c.diffusion = to_enum<DiffusionScheme>("numerics.diffusion", choice("numerics.diffusion"),
                                               {{"explicit", DiffusionScheme::explicit_ab2},
                                                {"implicit", DiffusionScheme::implicit_euler},
                                                {"auto", DiffusionScheme::automatic}});
        c.fixed_dt = number_or_auto("numerics.dt");
        c.max_dt = number("numerics.max_dt");
        if (c.fixed_dt && *c.fixed_dt > c.max_dt)
            fail("numerics.dt", "must not exceed numerics.max_dt (" + fmt(c.max_dt) + "), got " + fmt(*c.fixed_dt));
        c.poisson_tolerance = number("numerics.poisson.tolerance");
        c.poisson_max_iterations = static_cast<int>(integer("numerics.poisson.max_iterations"));
        c.divergence_limit = number("numerics.divergence_limit");

        c.end_time = number("time.end");
        c.max_steps = integer("time.max_steps");

        c.ranks = integer_vector2("parallel.ranks");

        c.field_interval = number("output.fields_interval");
        c.checkpoint_interval = number("output.checkpoint_interval");
        c.checkpoints_kept = static_cast<int>(integer("output.checkpoints_kept"));
        c.timeseries_every = static_cast<int>(integer("output.timeseries_every"));
        c.progress_interval = number("output.progress_interval");
        c.probes = point_list("output.probes");
        for (std::size_t i = 0; i < c.probes.size(); ++i) {
            const auto [px, py] = c.probes[i];
            if (px < c.x.start || px > c.x.end || py < c.y.start || py > c.y.end)
                fail(indexed("output.probes", i), "point [" + fmt(px) + ", " + fmt(py) + "] lies outside the domain [" +
                                                      fmt(c.x.start) + ", " + fmt(c.x.end) + "] x [" + fmt(c.y.start) +
                                                      ", " + fmt(c.y.end) + "]");
        }
        c.plots = boolean("output.plots");
        return c;
    }

private:
    struct Entry {
        YAML::Node node;
        YAML::Mark key_mark;  // where the key itself is written (null: made by a --set)
        std::string origin;   // the --set that gave it; empty: the file
    };

    static std::string trim(const std::string& s) {
        const std::size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
        return b == std::string::npos ? std::string{} : s.substr(b, e - b + 1);
    }

    void flatten(const YAML::Node& map, const std::string& section) {
        for (const auto& item : map) {
            const YAML::Node& key = item.first;
            if (!key.IsScalar()) fail(section, "keys must be plain names, got " + describe(key), &key);
            const std::string path = join(section, key.Scalar());
            if (!find_key(path)) fail(path, "unknown key" + unknown_key_hint(path), &key);
            if (const auto old = entries_.find(path); old != entries_.end()) {
                const YAML::Mark m = old->second.key_mark;
                fail(path, "given twice" + (m.is_null() ? "" : " (first on line " + std::to_string(m.line + 1) + ")"),
                     &key);
            }
            const std::string origin = origin_of(section);
            entries_[path] = {item.second, key.Mark(), origin};
            if (find_key(path)->type == KeyType::section) flatten_section(item.second, path);
        }
    }

    void flatten_section(const YAML::Node& value, const std::string& path) {
        if (value.IsMap())
            flatten(value, path);
        else if (!value.IsNull())
            fail(path, "expected a mapping of keys (key: value), got " + describe(value), &value);
    }

    std::string origin_of(std::string_view section) const {
        const auto it = entries_.find(section);
        return it == entries_.end() ? std::string{} : it->second.origin;
    }

    // The entry at `path` or, if that is absent, at its nearest ancestor.
    const Entry* nearest_entry(std::string_view path) const {
        std::string_view p = path.substr(0, path.find('['));
        for (; !p.empty(); p = parent_of(p))
            if (const auto it = entries_.find(p); it != entries_.end()) return &it->second;
        return nullptr;
    }

    // "file, line N", or "--set key=value", for an error about `path`: the line of its value `node` if
    // given, else of the key itself or, for a missing key, of its section's key.
    std::string where(std::string_view path, const YAML::Node* node) const {
        const Entry* e = nearest_entry(path);
        if (e && !e->origin.empty()) return "--set " + e->origin;
        YAML::Mark mark = YAML::Mark::null_mark();
        if (node && node->IsDefined())
            mark = node->Mark();
        else if (e)
            mark = e->key_mark;
        std::string s = file_;
        if (!mark.is_null()) s += (s.empty() ? "" : ", ") + std::string("line ") + std::to_string(mark.line + 1);
        return s;
    }

    [[noreturn]] void fail(std::string_view path, const std::string& reason, const YAML::Node* node = nullptr) const {
        const std::string w = where(path, node);
        throw CaseError((w.empty() ? "" : w + ": ") + (path.empty() ? "" : std::string(path) + ": ") + reason);
    }

    bool present(std::string_view path) const { return entries_.contains(path); }

    // Every concrete section present that matches a schema section pattern ("" is the top level).
    std::vector<std::string> instances(std::string_view pattern) const {
        if (pattern.empty()) return {""};
        std::vector<std::string> found;
        for (const auto& [path, entry] : entries_)
            if (matches(pattern, path)) found.push_back(path);
        return found;
    }

    void check_presence() const {
        for (const CaseKey& k : case_schema()) {
            for (const std::string& section : instances(parent_of(k.path))) {
                for (std::string_view name : expand(leaf_of(k.path))) {
                    const std::string path = join(section, name);
                    std::string condition;  // the value of the `when` key, if the key does not apply
                    bool applies = true;
                    if (!k.when_key.empty()) {
                        condition = choice(join(section, k.when_key));
                        applies =
                            std::find(k.when_values.begin(), k.when_values.end(), condition) != k.when_values.end();
                    }
                    if (present(path) && !applies)
                        fail(path, "not used when " + std::string(k.when_key) + " is '" + condition + "' (only with " +
                                       std::string(k.when_key) + ": " + list(k.when_values, " or ") + ")");
                    if (!present(path) && applies && k.required)
                        fail(path, "missing required key (" +
                                       (k.type == KeyType::choice ? "one of " + list(k.choices) : gist(k.meaning)) +
                                       (k.when_key.empty()
                                            ? ""
                                            : "; needed when " + std::string(k.when_key) + " is '" + condition + "'") +
                                       ")");
                }
            }
        }
    }

    // ---- typed reads: the value given, or the schema's default; checked against the schema ----

    const CaseKey& key(std::string_view path, KeyType type) const {
        const CaseKey* k = find_key(path);
        if (!k || k->type != type)
            throw std::logic_error("case_file: no schema key '" + std::string(path) + "' of the type read");
        return *k;
    }

    YAML::Node node(std::string_view path, const CaseKey& k) const {
        if (const auto it = entries_.find(path); it != entries_.end()) return it->second.node;
        if (k.default_value.empty())
            throw std::logic_error("case_file: '" + std::string(path) + "' read with no value and no default");
        return YAML::Load(std::string(k.default_value));
    }

    void check_range(std::string_view path, const YAML::Node& n, double v, const CaseKey& k) const {
        const bool above_min = !k.min || (k.min->inclusive ? v >= k.min->value : v > k.min->value);
        const bool below_max = !k.max || (k.max->inclusive ? v <= k.max->value : v < k.max->value);
        if (!(above_min && below_max) && !(k.also && v == *k.also))
            fail(path, "must be " + range_text(k, true) + ", got " + n.Scalar(), &n);
    }

    double to_number(std::string_view path, const YAML::Node& n, const CaseKey& k) const {
        double v = 0.0;
        if (!n.IsScalar() || !YAML::convert<double>::decode(n, v))
            fail(path, "expected a number, got " + describe(n), &n);
        if (!std::isfinite(v)) fail(path, "expected a finite number, got " + describe(n), &n);
        check_range(path, n, v, k);
        return v;
    }

    long to_integer(std::string_view path, const YAML::Node& n, const CaseKey& k) const {
        double v = 0.0;
        if (!n.IsScalar() || !YAML::convert<double>::decode(n, v) || !std::isfinite(v) || std::floor(v) != v)
            fail(path, "expected an integer, got " + describe(n), &n);
        check_range(path, n, v, k);
        if (std::abs(v) > INT_MAX)
            fail(path, "is too large (at most " + std::to_string(INT_MAX) + "), got " + n.Scalar(), &n);
        return static_cast<long>(v);
    }

    // A list of exactly 2 items (`what`, e.g. "2 numbers like [1, 0]"), each read by `item`.
    template <class T, class Item>
    std::array<T, 2> read_pair(std::string_view path, const YAML::Node& n, const std::string& what, Item item) const {
        if (!n.IsSequence()) fail(path, "expected " + what + ", got " + describe(n), &n);
        if (n.size() != 2)
            fail(path,
                 "expected " + what.substr(0, what.find(" like")) + ", got " + std::to_string(n.size()) +
                     (n.size() == 1 ? " item" : " items"),
                 &n);
        std::array<T, 2> v{};
        std::size_t i = 0;
        for (const auto& element : n) v[i] = item(indexed(path, i), element), ++i;
        return v;
    }

    double number(std::string_view path) const {
        const CaseKey& k = key(path, KeyType::number);
        return to_number(path, node(path, k), k);
    }

    long integer(std::string_view path) const {
        const CaseKey& k = key(path, KeyType::integer);
        return to_integer(path, node(path, k), k);
    }

    bool boolean(std::string_view path) const {
        const YAML::Node n = node(path, key(path, KeyType::boolean));
        bool v = false;
        if (!n.IsScalar() || !YAML::convert<bool>::decode(n, v))
            fail(path, "expected true or false, got " + describe(n), &n);
        return v;
    }

    std::string string(std::string_view path) const {
        const YAML::Node n = node(path, key(path, KeyType::string));
        if (!n.IsScalar()) fail(path, "expected a text, got " + describe(n), &n);
        return n.Scalar();
    }

    std::string choice(std::string_view path) const {
        const CaseKey& k = key(path, KeyType::choice);
        const YAML::Node n = node(path, k);
        if (!n.IsScalar()) fail(path, "expected one of " + list(k.choices) + ", got " + describe(n), &n);
        const std::string& v = n.Scalar();
        if (std::find(k.choices.begin(), k.choices.end(), v) != k.choices.end()) return v;
        std::string reason = "invalid choice '" + v + "'; choices: " + list(k.choices);
        if (auto best = nearest(v, std::vector<std::string>(k.choices.begin(), k.choices.end())))
            reason += " (did you mean '" + *best + "'?)";
        fail(path, reason, &n);
    }

    std::array<double, 2> vector2(std::string_view path) const {
        const CaseKey& k = key(path, KeyType::vector2);
        return read_pair<double>(path, node(path, k), "a list of 2 numbers like [1, 0]",
                                 [&](const std::string& p, const YAML::Node& e) { return to_number(p, e, k); });
    }

    std::array<int, 2> integer_vector2(std::string_view path) const {
        const CaseKey& k = key(path, KeyType::integer_vector2);
        return read_pair<int>(
            path, node(path, k), "a list of 2 integers like [2, 1]",
            [&](const std::string& p, const YAML::Node& e) { return static_cast<int>(to_integer(p, e, k)); });
    }

    std::vector<double> number_list(std::string_view path) const {
        const CaseKey& k = key(path, KeyType::number_list);
        const YAML::Node n = node(path, k);
        if (!n.IsSequence()) fail(path, "expected a list of numbers like [0, 0.5, 1], got " + describe(n), &n);
        std::vector<double> v;
        for (const auto& element : n) v.push_back(to_number(indexed(path, v.size()), element, k));
        return v;
    }

    std::vector<std::array<double, 2>> point_list(std::string_view path) const {
        const CaseKey& k = key(path, KeyType::point_list);
        const YAML::Node n = node(path, k);
        if (!n.IsSequence()) fail(path, "expected a list of points like [[0.5, 0.5]], got " + describe(n), &n);
        std::vector<std::array<double, 2>> v;
        for (const auto& element : n)
            v.push_back(
                read_pair<double>(indexed(path, v.size()), element, "a point [x, y] like [0.5, 0.5]",
                                  [&](const std::string& p, const YAML::Node& e) { return to_number(p, e, k); }));
        return v;
    }

    std::optional<double> number_or_auto(std::string_view path) const {
        const CaseKey& k = key(path, KeyType::number_or_auto);
        const YAML::Node n = node(path, k);
        double v = 0.0;
        if (n.IsScalar() && n.Scalar() == "auto") return std::nullopt;
        if (!n.IsScalar() || !YAML::convert<double>::decode(n, v) || !std::isfinite(v))
            fail(path, "expected auto or a number, got " + describe(n), &n);
        check_range(path, n, v, k);
        return v;
    }

    // ---- sections read as a whole, and the checks across keys ----

    void read_axis(const std::string& p, AxisConfig& a) const {
        a.spacing = choice(p + ".spacing");
        a.beta = number(p + ".beta");
        a.ratio = number(p + ".ratio");
        if (a.spacing == "lines") {
            a.lines = number_list(p + ".lines");
            if (a.lines.size() < 3)
                fail(p + ".lines", "expected at least 3 lines (2 cells), got " + std::to_string(a.lines.size()));
            for (std::size_t i = 1; i < a.lines.size(); ++i)
                if (!(a.lines[i] > a.lines[i - 1]))
                    fail(indexed(p + ".lines", i),
                         "lines must be strictly increasing, got " + fmt(a.lines[i]) + " after " + fmt(a.lines[i - 1]));
            a.start = a.lines.front();
            a.end = a.lines.back();
            a.cells = static_cast<int>(a.lines.size()) - 1;
        } else {
            a.start = number(p + ".start");
            a.end = number(p + ".end");
            if (!(a.end > a.start))
                fail(p + ".end", "must be greater than " + p + ".start (" + fmt(a.start) + "), got " + fmt(a.end));
            if (a.spacing == "clustered") {
                a.core = vector2(p + ".core");
                a.core_cells = static_cast<int>(integer(p + ".core_cells"));
                if (!(a.core[0] >= a.start && a.core[1] <= a.end && a.core[1] > a.core[0]))
                    fail(p + ".core", "the window must lie in [start, end] = [" + fmt(a.start) + ", " + fmt(a.end) +
                                          "] with to > from, got [" + fmt(a.core[0]) + ", " + fmt(a.core[1]) + "]");
                if (!(a.ratio >= 1.0))
                    fail(p + ".ratio", "clustered cells grow away from the window: ratio >= 1, got " + fmt(a.ratio));
                a.cells = static_cast<int>(
                              clustered_lines(a.start, a.end, a.core[0], a.core[1], a.core_cells, a.ratio).size()) -
                          1;
            } else {
                a.cells = static_cast<int>(integer(p + ".cells"));
            }
        }
    }

    void read_boundary(int s, BoundaryConfig& b) const {
        const std::string side(kSideNames[s]), p = "boundaries." + side;
        b.type = to_enum<BoundaryType>(p + ".type", choice(p + ".type"),
                                       {{"wall", BoundaryType::wall},
                                        {"slip", BoundaryType::slip},
                                        {"inflow", BoundaryType::inflow},
                                        {"outflow", BoundaryType::outflow},
                                        {"periodic", BoundaryType::periodic}});
        b.velocity = vector2(p + ".velocity");
        b.profile =
            to_enum<InflowProfile>(p + ".profile", choice(p + ".profile"),
                                   {{"uniform", InflowProfile::uniform}, {"parabolic", InflowProfile::parabolic}});
        b.outflow =
            to_enum<OutflowKind>(p + ".kind", choice(p + ".kind"),
                                 {{"convective", OutflowKind::convective}, {"zero_stress", OutflowKind::zero_stress}});
        if (present(p + ".peak")) b.peak = number(p + ".peak");
        if (b.type == BoundaryType::inflow && b.profile == InflowProfile::parabolic && present(p + ".velocity"))
            fail(p + ".velocity", "not used with profile: parabolic (the peak sets the inflow)");

        const int normal = s < 2 ? 0 : 1;               // velocity component normal to this side
        const double inward = s % 2 == 0 ? 1.0 : -1.0;  // sign of that component for flow into the domain
        const std::string component = "velocity[" + std::to_string(normal) + "]";
        if (b.type == BoundaryType::wall && b.velocity[normal] != 0.0)
            fail(p + ".velocity", "a wall moves along itself: the normal component " + component +
                                      " must be 0 on the " + side + " side, got " + fmt(b.velocity[normal]));
        if (b.type == BoundaryType::inflow && b.profile == InflowProfile::uniform) {
            if (!present(p + ".velocity"))
                fail(p + ".velocity",
                     "missing required key (an inflow with profile: uniform needs its velocity; or "
                     "use profile: parabolic with a peak)");
            if (!(inward * b.velocity[normal] > 0.0))
                fail(p + ".velocity", "an inflow must enter the domain: on the " + side + " side " + component +
                                          " must be " + (inward > 0 ? "> 0" : "< 0") + ", got " +
                                          fmt(b.velocity[normal]));
        }
    }

    void read_ibm(IbmConfig& m) const {
        m.kernel = to_enum<DeltaKernel>("numerics.ibm.kernel", choice("numerics.ibm.kernel"),
                                        {{"roma3", DeltaKernel::roma3}, {"peskin4", DeltaKernel::peskin4}});
        m.forcing_iterations = static_cast<int>(integer("numerics.ibm.forcing_iterations"));
        m.marker_spacing = number("numerics.ibm.marker_spacing");
        m.retraction = number("numerics.ibm.retraction");
        m.stress_probes = vector2("numerics.ibm.stress_probes");
        m.virtual_mass = number("numerics.ibm.virtual_mass");
        if (!(m.stress_probes[1] > m.stress_probes[0]))
            fail("numerics.ibm.stress_probes", "the second distance must be greater than the first, got [" +
                                                   fmt(m.stress_probes[0]) + ", " + fmt(m.stress_probes[1]) + "]");
    }

    void read_bodies(CaseConfig& c) const {
        constexpr double deg = 3.14159265358979323846 / 180.0;
        for (const std::string& p : instances("bodies.<body>")) {
            BodyConfig b;
            b.name = std::string(leaf_of(p));
            b.shape = to_enum<BodyShape>(p + ".shape", choice(p + ".shape"),
                                         {{"circle", BodyShape::circle},
                                          {"rectangle", BodyShape::rectangle},
                                          {"polygon", BodyShape::polygon},
                                          {"plane", BodyShape::plane},
                                          {"segment", BodyShape::segment}});
            const bool closed =
                b.shape == BodyShape::circle || b.shape == BodyShape::rectangle || b.shape == BodyShape::polygon;
            std::vector<std::array<double, 2>> extent;  // points that must lie in the domain
            const std::string where_key = p + (b.shape == BodyShape::plane     ? ".point"
                                               : b.shape == BodyShape::segment ? ".from"
                                               : b.shape == BodyShape::polygon ? ".vertices"
                                                                               : ".centre");
            double height = 0.0;
            if (b.shape == BodyShape::circle || b.shape == BodyShape::rectangle) b.centre = vector2(p + ".centre");
            if (b.shape == BodyShape::rectangle || b.shape == BodyShape::polygon || b.shape == BodyShape::plane)
                b.angle = number(p + ".angle") * deg;
            switch (b.shape) {
                case BodyShape::circle: {
                    b.diameter = number(p + ".diameter");
                    const double r = 0.5 * b.diameter;
                    extent = {{b.centre[0] - r, b.centre[1] - r}, {b.centre[0] + r, b.centre[1] + r}};
                    height = b.diameter;
                    break;
                }
                case BodyShape::rectangle: {
                    b.size = vector2(p + ".size");
                    const double cs = std::cos(b.angle), sn = std::sin(b.angle);
                    double ymin = 1e300, ymax = -1e300;
                    for (const double sx : {-0.5, 0.5})
                        for (const double sy : {-0.5, 0.5}) {
                            const double x = sx * b.size[0], y = sy * b.size[1];
                            extent.push_back({b.centre[0] + cs * x - sn * y, b.centre[1] + sn * x + cs * y});
                            ymin = std::min(ymin, extent.back()[1]);
                            ymax = std::max(ymax, extent.back()[1]);
                        }
                    height = ymax - ymin;
                    break;
                }
                case BodyShape::polygon: {
                    b.vertices = point_list(p + ".vertices");
                    if (b.vertices.size() < 3)
                        fail(p + ".vertices",
                             "a polygon needs at least 3 corners, got " + std::to_string(b.vertices.size()));
                    double a2 = 0.0, ymin = 1e300, ymax = -1e300;
                    for (std::size_t k = 0; k < b.vertices.size(); ++k) {
                        const auto& v = b.vertices[k];
                        const auto& w = b.vertices[(k + 1) % b.vertices.size()];
                        a2 += v[0] * w[1] - v[1] * w[0];
                        ymin = std::min(ymin, v[1]);
                        ymax = std::max(ymax, v[1]);
                    }
                    if (std::abs(a2) < 1e-14) fail(p + ".vertices", "the corners enclose no area");
                    extent = b.vertices;  // the rotation about the centroid is checked by the solver
                    height = ymax - ymin;
                    break;
                }
                case BodyShape::plane:
                    b.point = vector2(p + ".point");
                    extent = {b.point};
                    break;
                case BodyShape::segment:
                    b.from = vector2(p + ".from");
                    b.to = vector2(p + ".to");
                    if (b.from == b.to) fail(p + ".to", "the two ends of the segment coincide");
                    extent = {b.from, b.to};
                    height = std::hypot(b.to[0] - b.from[0], b.to[1] - b.from[1]);
                    break;
            }
            for (const auto& [x, y] : extent)
                if (x < c.x.start || x > c.x.end || y < c.y.start || y > c.y.end)
                    fail(where_key, "the body reaches outside the domain [" + fmt(c.x.start) + ", " + fmt(c.x.end) +
                                        "] x [" + fmt(c.y.start) + ", " + fmt(c.y.end) + "]: point [" + fmt(x) + ", " +
                                        fmt(y) + "]");

            const std::string m = p + ".motion";
            b.motion.type = to_enum<MotionType>(m + ".type", choice(m + ".type"),
                                                {{"fixed", MotionType::fixed},
                                                 {"constant_velocity", MotionType::constant_velocity},
                                                 {"oscillation", MotionType::oscillation},
                                                 {"uniform_acceleration", MotionType::uniform_acceleration},
                                                 {"free", MotionType::free}});
            if (!closed && b.motion.type != MotionType::fixed)
                fail(m + ".type", "planes and segments are fixed; only circles, rectangles and polygons move");
            b.motion.velocity = vector2(m + ".velocity");
            b.motion.angular_velocity = number(m + ".angular_velocity");
            b.motion.amplitude = vector2(m + ".amplitude");
            b.motion.angular_amplitude = number(m + ".angular_amplitude") * deg;
            if (present(m + ".frequency")) b.motion.frequency = number(m + ".frequency");
            b.motion.phase = number(m + ".phase") * deg;
            b.motion.acceleration = vector2(m + ".acceleration");
            b.motion.angular_acceleration = number(m + ".angular_acceleration");
            if (b.motion.type == MotionType::free) {
                if (!present(p + ".density")) fail(p + ".density", "a free body needs its density");
                b.density = number(p + ".density");
                b.motion.locked = {boolean(m + ".lock_x"), boolean(m + ".lock_y"), boolean(m + ".lock_rotation")};
            } else if (present(p + ".density")) {
                fail(p + ".density", "only free bodies (motion type `free`) have a density");
            }

            b.reference_velocity = number(p + ".reference.velocity");
            if (present(p + ".reference.length"))
                b.reference_length = number(p + ".reference.length");
            else if (b.shape == BodyShape::plane)
                b.reference_length = std::hypot(c.x.end - c.x.start, c.y.end - c.y.start);
            else
                b.reference_length = height;
            if (!(b.reference_length > 0.0))
                fail(p + ".reference.length", "the default (the body's extent across x) is 0: give a length");
            c.bodies.push_back(std::move(b));
        }
    }

    void check_boundaries(const CaseConfig& c) const {
        const auto type_of = [&](int s) { return c.boundary[s].type; };
        for (int s = 0; s < 4; ++s) {
            const int opposite = s ^ 1;  // left <-> right, bottom <-> top
            if (type_of(s) == BoundaryType::periodic && type_of(opposite) != BoundaryType::periodic)
                fail("boundaries." + std::string(kSideNames[s]) + ".type",
                     "periodic sides come in pairs: boundaries." + std::string(kSideNames[opposite]) +
                         ".type must be periodic too, got '" +
                         choice("boundaries." + std::string(kSideNames[opposite]) + ".type") + "'");
        }
        bool outflow = false;
        for (int s = 0; s < 4; ++s) outflow = outflow || type_of(s) == BoundaryType::outflow;
        for (int s = 0; s < 4; ++s)
            if (type_of(s) == BoundaryType::inflow && !outflow)
                fail("boundaries." + std::string(kSideNames[s]) + ".type",
                     "an inflow needs an outflow side somewhere: with none, the mass let in cannot leave");
    }

    std::string file_, default_name_;
    std::map<std::string, Entry, std::less<>> entries_;  // full key path -> value, as given
};

}  // namespace

const std::vector<CaseKey>& case_schema() {
    static const std::vector<CaseKey> schema = make_schema();
    return schema;
}

CaseConfig parse_case(const YAML::Node& root) {
    Reader reader("", "case");
    reader.add_document(root);
    return reader.build();
}

CaseConfig parse_case_text(const std::string& yaml_text, const std::vector<std::string>& overrides) {
    Reader reader("", "case");
    reader.add_document(load_yaml(yaml_text, ""));
    for (const std::string& o : overrides) reader.add_override(o);
    return reader.build();
}

CaseConfig load_case(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
    const std::string name = file.string();
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw CaseError(name + ": case file not found");
    if (std::filesystem::is_directory(file, ec)) throw CaseError(name + ": is a directory, not a case file");
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) throw CaseError(name + ": cannot read the case file");
    Reader reader(name, file.stem().string());
    reader.add_document(load_yaml(text.str(), name));
    for (const std::string& o : overrides) reader.add_override(o);
    return reader.build();
}

std::string schema_markdown() {
    const auto cell = [](std::string_view text) {
        std::string s;
        for (char ch : text) s += ch == '|' ? std::string("\\|") : std::string(1, ch);
        return s;
    };
    const auto code = [](std::string_view text) { return "`" + std::string(text) + "`"; };
    std::string md =
        "| Key | Type | Default | Allowed | Units | Meaning |\n"
        "|-----|------|---------|---------|-------|---------|\n";
    for (const CaseKey& k : case_schema()) {
        std::string type, allowed = range_text(k, false), fallback;
        switch (k.type) {
            case KeyType::section:
                type = "section";
                break;
            case KeyType::string:
                type = "text";
                break;
            case KeyType::number:
                type = "number";
                break;
            case KeyType::integer:
                type = "integer";
                break;
            case KeyType::boolean:
                type = "true/false";
                break;
            case KeyType::choice:
                type = "choice";
                break;
            case KeyType::vector2:
                type = "[number, number]";
                break;
            case KeyType::integer_vector2:
                type = "[integer, integer]";
                break;
            case KeyType::number_list:
                type = "list of numbers";
                break;
            case KeyType::point_list:
                type = "list of [x, y]";
                break;
            case KeyType::number_or_auto:
                type = "`auto` or number";
                break;
        }
        if (k.type == KeyType::choice) {
            for (std::string_view c : k.choices) allowed += (allowed.empty() ? "" : ", ") + code(c);
        }
        if ((k.type == KeyType::vector2 || k.type == KeyType::integer_vector2) && !allowed.empty())
            allowed = "each " + allowed;
        if (k.type == KeyType::number_or_auto) allowed = code("auto") + " or " + allowed;

        std::string dflt;
        if (k.required)
            dflt = "**required**";
        else if (!k.default_doc.empty())
            dflt = std::string(k.default_doc);
        else if (!k.default_value.empty())
            dflt = code(k.default_value);

        std::string meaning(k.meaning);
        if (!k.when_key.empty()) {
            // "Only with `spacing: tanh`." or "Only with `spacing: uniform`, `tanh` or `geometric`."
            const auto& values = k.when_values;
            std::string options = code(std::string(k.when_key) + ": " + std::string(values.front()));
            for (std::size_t i = 1; i < values.size(); ++i)
                options += (i + 1 == values.size() ? " or " : ", ") + code(values[i]);
            meaning += " Only with " + options + ".";
        }
        md += "| " + code(k.path) + " | " + cell(type) + " | " + cell(dflt) + " | " + cell(allowed) + " | " +
              cell(k.units) + " | " + cell(meaning) + " |\n";
    }
    return md;
}

}  // namespace chute
