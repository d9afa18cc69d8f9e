// Case files: the schema as data, read by the generic reader (case_reader.hpp: YAML, --set overrides,
// unknown keys, presence, typed reads), then build(): the typed reads into a CaseConfig and the checks that
// involve several keys (end > start, periodic pairs, wall velocity tangential, probes inside, ...).
#include "case_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

#include "axis.hpp"

namespace chute {

namespace {

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
        {.path = "domain.<axis>",
         .type = K::section,
         .required = true,
         .meaning = "Grid lines along x or along y."},
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
         .meaning = "Markers of closed outlines moved this many cells inside the surface, to offset the "
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

        {.path = "contact", .type = K::section, .meaning = "Impacts of free bodies on planes and on wall or slip sides of the domain."},
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
        {.path = "output.plots",
         .type = K::boolean,
         .default_value = "true",
         .meaning = "Write plots of the results."},
    };
}

constexpr std::array<std::string_view, 4> kSideNames = {"left", "right", "bottom", "top"};

const std::vector<Placeholder>& case_placeholders() {
    static const std::vector<Placeholder> placeholders = {
        {"<axis>", {"x", "y"}}, {"<side>", {kSideNames.begin(), kSideNames.end()}}, {"<body>"}};
    return placeholders;
}

// ---- sections read as a whole, and the checks across keys ----

void read_axis(const CaseReader& r, const std::string& p, AxisConfig& a) {
    a.spacing = r.choice(p + ".spacing");
    a.beta = r.number(p + ".beta");
    a.ratio = r.number(p + ".ratio");
    if (a.spacing == "lines") {
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
            a.cells =
                static_cast<int>(clustered_lines(a.start, a.end, a.core[0], a.core[1], a.core_cells, a.ratio).size()) -
                1;
        } else {
            a.cells = static_cast<int>(r.integer(p + ".cells"));
        }
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
        if (!(inward * b.velocity[normal] > 0.0))
            r.fail(p + ".velocity", "an inflow must enter the domain: on the " + side + " side " + component +
                                        " must be " + (inward > 0 ? "> 0" : "< 0") + ", got " +
                                        exact_text(b.velocity[normal]));
    }
}

void read_ibm(const CaseReader& r, IbmConfig& m) {
    m.kernel = r.choice<DeltaKernel>("numerics.ibm.kernel",
                                     {{"roma3", DeltaKernel::roma3}, {"peskin4", DeltaKernel::peskin4}});
    m.forcing_iterations = static_cast<int>(r.integer("numerics.ibm.forcing_iterations"));
    m.marker_spacing = r.number("numerics.ibm.marker_spacing");
    m.retraction = r.number("numerics.ibm.retraction");
    m.stress_probes = r.vector2("numerics.ibm.stress_probes");
    m.virtual_mass = r.number("numerics.ibm.virtual_mass");
    if (!(m.stress_probes[1] > m.stress_probes[0]))
        r.fail("numerics.ibm.stress_probes", "the second distance must be greater than the first, got [" +
                                                 exact_text(m.stress_probes[0]) + ", " +
                                                 exact_text(m.stress_probes[1]) + "]");
}

void read_bodies(const CaseReader& r, CaseConfig& c) {
    constexpr double deg = 3.14159265358979323846 / 180.0;
    for (const std::string& p : r.instances("bodies.<body>")) {
        BodyConfig b;
        b.name = p.substr(p.rfind('.') + 1);
        b.shape = r.choice<BodyShape>(p + ".shape", {{"circle", BodyShape::circle},
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
        if (b.shape == BodyShape::circle || b.shape == BodyShape::rectangle) b.centre = r.vector2(p + ".centre");
        if (b.shape == BodyShape::rectangle || b.shape == BodyShape::polygon || b.shape == BodyShape::plane)
            b.angle = r.number(p + ".angle") * deg;
        switch (b.shape) {
            case BodyShape::circle: {
                b.diameter = r.number(p + ".diameter");
                const double radius = 0.5 * b.diameter;
                extent = {{b.centre[0] - radius, b.centre[1] - radius}, {b.centre[0] + radius, b.centre[1] + radius}};
                height = b.diameter;
                break;
            }
            case BodyShape::rectangle: {
                b.size = r.vector2(p + ".size");
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
                b.vertices = r.point_list(p + ".vertices");
                if (b.vertices.size() < 3)
                    r.fail(p + ".vertices",
                           "a polygon needs at least 3 corners, got " + std::to_string(b.vertices.size()));
                double a2 = 0.0, ymin = 1e300, ymax = -1e300;
                for (std::size_t k = 0; k < b.vertices.size(); ++k) {
                    const auto& v = b.vertices[k];
                    const auto& w = b.vertices[(k + 1) % b.vertices.size()];
                    a2 += v[0] * w[1] - v[1] * w[0];
                    ymin = std::min(ymin, v[1]);
                    ymax = std::max(ymax, v[1]);
                }
                if (std::abs(a2) < 1e-14) r.fail(p + ".vertices", "the corners enclose no area");
                extent = b.vertices;  // the rotation about the centroid is checked by the solver
                height = ymax - ymin;
                break;
            }
            case BodyShape::plane:
                b.point = r.vector2(p + ".point");
                extent = {b.point};
                break;
            case BodyShape::segment:
                b.from = r.vector2(p + ".from");
                b.to = r.vector2(p + ".to");
                if (b.from == b.to) r.fail(p + ".to", "the two ends of the segment coincide");
                extent = {b.from, b.to};
                height = std::hypot(b.to[0] - b.from[0], b.to[1] - b.from[1]);
                break;
        }
        for (const auto& [x, y] : extent)
            if (x < c.x.start || x > c.x.end || y < c.y.start || y > c.y.end)
                r.fail(where_key, "the body reaches outside the domain [" + exact_text(c.x.start) + ", " +
                                      exact_text(c.x.end) + "] x [" + exact_text(c.y.start) + ", " +
                                      exact_text(c.y.end) + "]: point [" + exact_text(x) + ", " + exact_text(y) + "]");

        const std::string m = p + ".motion";
        b.motion.type = r.choice<MotionType>(m + ".type", {{"fixed", MotionType::fixed},
                                                           {"constant_velocity", MotionType::constant_velocity},
                                                           {"oscillation", MotionType::oscillation},
                                                           {"uniform_acceleration", MotionType::uniform_acceleration},
                                                           {"free", MotionType::free}});
        if (!closed && b.motion.type != MotionType::fixed)
            r.fail(m + ".type", "planes and segments are fixed; only circles, rectangles and polygons move");
        b.motion.velocity = r.vector2(m + ".velocity");
        b.motion.angular_velocity = r.number(m + ".angular_velocity");
        b.motion.amplitude = r.vector2(m + ".amplitude");
        b.motion.angular_amplitude = r.number(m + ".angular_amplitude") * deg;
        if (r.present(m + ".frequency")) b.motion.frequency = r.number(m + ".frequency");
        b.motion.phase = r.number(m + ".phase") * deg;
        b.motion.acceleration = r.vector2(m + ".acceleration");
        b.motion.angular_acceleration = r.number(m + ".angular_acceleration");
        if (b.motion.type == MotionType::free) {
            if (!r.present(p + ".density")) r.fail(p + ".density", "a free body needs its density");
            b.density = r.number(p + ".density");
            b.motion.locked = {r.boolean(m + ".lock_x"), r.boolean(m + ".lock_y"), r.boolean(m + ".lock_rotation")};
        } else if (r.present(p + ".density")) {
            r.fail(p + ".density", "only free bodies (motion type `free`) have a density");
        }

        b.reference_velocity = r.number(p + ".reference.velocity");
        if (r.present(p + ".reference.length"))
            b.reference_length = r.number(p + ".reference.length");
        else if (b.shape == BodyShape::plane)
            b.reference_length = std::hypot(c.x.end - c.x.start, c.y.end - c.y.start);
        else
            b.reference_length = height;
        if (!(b.reference_length > 0.0))
            r.fail(p + ".reference.length", "the default (the body's extent across x) is 0: give a length");
        c.bodies.push_back(std::move(b));
    }
}

void check_boundaries(const CaseReader& r, const CaseConfig& c) {
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

CaseConfig build(const CaseReader& r, const std::string& default_name) {
    r.check_presence();
    CaseConfig c;

    c.name = r.present("name") ? r.string("name") : default_name;
    if (c.name.empty()) r.fail("name", "must not be empty");
    if (c.name.find_first_of("/\\") != std::string::npos)
        r.fail("name", "must not contain '/' or '\\' (output files are named after it), got '" + c.name + "'");

    read_axis(r, "domain.x", c.x);
    read_axis(r, "domain.y", c.y);
    c.depth = r.number("domain.depth");

    c.density = r.number("fluid.density");
    c.viscosity = r.number("fluid.viscosity");
    c.body_force = r.vector2("fluid.body_force");
    c.gravity = r.vector2("gravity");
    c.contact.law = r.choice<ReboundLaw>(
        "contact.law", {{"lumped", ReboundLaw::lumped}, {"impulse", ReboundLaw::impulse}, {"soft", ReboundLaw::soft}});
    c.contact.normal_restitution = r.number("contact.normal_restitution");
    c.contact.tangential_restitution = r.number("contact.tangential_restitution");
    c.contact.rest_speed = r.number("contact.rest_speed");
    c.contact.friction = r.number("contact.friction");
    c.contact.distance = r.number("contact.distance");
    c.contact.duration = r.number("contact.duration");
    c.lumped.drag_coefficient = r.number("lumped.drag_coefficient");
    c.lumped.added_mass_coefficient = r.number("lumped.added_mass_coefficient");

    c.turbulence.model = r.choice<TurbulenceModelType>(
        "turbulence.model", {{"laminar", TurbulenceModelType::laminar}, {"k_epsilon", TurbulenceModelType::k_epsilon}});
    c.turbulence.intensity = r.number("turbulence.intensity");
    c.turbulence.length_scale = r.number("turbulence.length_scale");
    c.turbulence.velocity_scale = r.number("turbulence.velocity_scale");
    c.turbulence.production_limit = r.number("turbulence.production_limit");
    c.turbulence.kato_launder = r.choice("turbulence.production") == "kato_launder";
    c.turbulence.image_distance = r.number("turbulence.image_distance");

    c.initial = r.choice<InitialCondition>(
        "initial.type", {{"uniform", InitialCondition::uniform}, {"taylor_green", InitialCondition::taylor_green}});
    c.initial_velocity = r.vector2("initial.velocity");
    c.taylor_green_amplitude = r.number("initial.amplitude");
    c.initial_perturbation = r.number("initial.perturbation");

    for (int s = 0; s < 4; ++s) read_boundary(r, s, c.boundary[s]);
    check_boundaries(r, c);

    read_ibm(r, c.ibm);
    read_bodies(r, c);

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
    c.divergence_limit = r.number("numerics.divergence_limit");

    c.end_time = r.number("time.end");
    c.max_steps = r.integer("time.max_steps");

    c.ranks = r.integer_vector2("parallel.ranks");

    c.field_interval = r.number("output.fields_interval");
    c.checkpoint_interval = r.number("output.checkpoint_interval");
    c.checkpoints_kept = static_cast<int>(r.integer("output.checkpoints_kept"));
    c.timeseries_every = static_cast<int>(r.integer("output.timeseries_every"));
    c.progress_interval = r.number("output.progress_interval");
    c.probes = r.point_list("output.probes");
    for (std::size_t i = 0; i < c.probes.size(); ++i) {
        const auto [px, py] = c.probes[i];
        if (px < c.x.start || px > c.x.end || py < c.y.start || py > c.y.end)
            r.fail(CaseReader::indexed("output.probes", i),
                   "point [" + exact_text(px) + ", " + exact_text(py) + "] lies outside the domain [" +
                       exact_text(c.x.start) + ", " + exact_text(c.x.end) + "] x [" + exact_text(c.y.start) + ", " +
                       exact_text(c.y.end) + "]");
    }
    c.plots = r.boolean("output.plots");
    return c;
}

}  // namespace

const std::vector<CaseKey>& case_schema() {
    static const std::vector<CaseKey> schema = make_schema();
    return schema;
}

CaseConfig parse_case(const YAML::Node& root) {
    CaseReader reader(case_schema(), case_placeholders());
    reader.add_document(root);
    return build(reader, "case");
}

CaseConfig parse_case_text(const std::string& yaml_text, const std::vector<std::string>& overrides) {
    CaseReader reader(case_schema(), case_placeholders());
    reader.add_text(yaml_text);
    for (const std::string& o : overrides) reader.add_override(o);
    return build(reader, "case");
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
    CaseReader reader(case_schema(), case_placeholders(), name);
    reader.add_text(text.str());
    for (const std::string& o : overrides) reader.add_override(o);
    return build(reader, file.stem().string());
}

std::string schema_markdown() { return markdown_table(case_schema()); }

}  // namespace chute
