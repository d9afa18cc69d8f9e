// The immersed boundary's section of the case-file schema (ibm_config.hpp) and its reading.
#include <string>

#include "case_reader.hpp"
#include "ibm_config.hpp"

namespace chute {

std::vector<CaseKey> ibm_keys() {
    using K = KeyType;
    return {
        {.path = "numerics.ibm", .type = K::section, .meaning = "Immersed-boundary forcing and force sampling."},
        {.path = "numerics.ibm.interface",
         .type = K::choice,
         .default_value = "diffuse",
         .choices = {"sharp", "diffuse"},
         .meaning = "How a body's surface enters the flow's equations. `sharp`: where it lies (Fadlun et al. 2000, "
                    "Balaras 2004): faces inside a body take its velocity, the fluid faces beside it a value "
                    "reconstructed along the normal between the body's velocity at the surface and the flow "
                    "turbulence.image_distance cells out (ibm/sharp_forcing.hpp); corners stay sharp. `diffuse`: "
                    "Lagrangian markers forced over a regularised delta kernel (Uhlmann 2005; the keys kernel, "
                    "forcing_iterations, retraction, volume_ramp), which rounds corners over about two cells."},
        {.path = "numerics.ibm.sharp_sweeps",
         .type = K::integer,
         .default_value = "3",
         .min = at_least(1),
         .max = at_most(20),
         .meaning = "Sharp interface: reconstructions of the faces beside the surface per forcing. The image point "
                    "of one may read another; each sweep shrinks what is left by the weight phi / L (below 3/4)."},
        {.path = "numerics.ibm.sharp_faces",
         .type = K::choice,
         .default_value = "forcing",
         .choices = {"forcing", "ghost"},
         .meaning = "Sharp interface: which faces the profile sets. `forcing`: the fluid faces beside the surface "
                    "(Fadlun et al. 2000); `ghost`: the faces inside the body beside the fluid, extrapolated through "
                    "the wall so that every fluid face keeps its own momentum equation (Tseng & Ferziger 2003)."},
        {.path = "numerics.ibm.cut_momentum",
         .type = K::boolean,
         .default_value = "false",
         .when_key = "sharp_faces",
         .when_values = {"ghost"},
         .meaning = "Ghost faces: every face with an open part keeps its own momentum equation (a face is a ghost "
                    "only when the surface shuts it whole), the viscous term of a face beside the surface takes the "
                    "wall where it lies along each grid line (Shortley-Weller, from the middle of a cut face's open "
                    "part) and the convection is transported by the faces' cut fluxes: the force follows the body's "
                    "place in its cells continuously (docs/validation.md, \"Sharp interface\", thirteenth and "
                    "fourteenth steps). With k-epsilon the wall parts take the wall law's shear."},
        {.path = "numerics.ibm.sharp_profile",
         .type = K::choice,
         .default_value = "auto",
         .choices = {"auto", "linear", "quadratic", "wall_law", "mirror"},
         .meaning =
             "Sharp interface: the velocity profile between the surface and the image points that sets the faces "
             "beside it. `auto`: `quadratic` in laminar runs (through the wall, 2 and 3 cells out: DFG 2D-1's "
             "drag in the band at D/h 40); with k-epsilon `wall_law` on forcing faces (the model's law of the wall "
             "from the image point down) and `mirror` on ghost faces; `linear`: straight from the wall to "
             "turbulence.image_distance cells out; `mirror` (ghost faces only): straight through the wall from the "
             "face's mirror image, so that the wall's flux is that of a body-fitted wall (with k-epsilon, the wall "
             "law's shear through the corners beside the surface)."},
        {.path = "numerics.ibm.kernel",
         .type = K::choice,
         .default_value = "roma3_smoothed",
         .choices = {"roma3", "peskin4", "roma3_smoothed"},
         .meaning = "Regularised delta kernel: `roma3_smoothed` (Yang et al. 2009; roma3 averaged over a cell: 4 "
                    "points, continuous first derivative; with 10 forcing iterations the falling block's force "
                    "ripples by 0.6 % instead of 1.45 %, docs/validation.md), `roma3` (Roma, Peskin & Berger 1999; 3 "
                    "points per direction) or `peskin4` (Peskin 2002; 4 points). Changing it asks for the "
                    "retraction to be re-set."},
        {.path = "numerics.ibm.forcing_iterations",
         .type = K::integer,
         .default_value = "10",
         .min = at_least(1),
         .max = at_most(50),
         .meaning = "Multi-direct forcing iterations per step (Breugem 2012): each one shrinks the slip "
                    "error at the markers (the falling block's rms slip: 0.95 % of its speed with 3, 0.45 % with "
                    "10)."},
        {.path = "numerics.ibm.projection_passes",
         .type = K::integer,
         .default_value = "1",
         .min = at_least(1),
         .max = at_most(50),
         .meaning = "Forcing and projection passes per step: each further pass forces the projected velocity "
                    "again and projects again, so less slip is left after the projection. A body held in a stream "
                    "feels that slip (the study's block fixed in a 2.32 m/s stream: drag 1284.6 N with 1 pass, "
                    "1332 N with 16, against 1338 N when it moves through still water: its Galilean pair within "
                    "0.5 %, docs/validation.md), but a moving body's force ripples more at the cell-crossing "
                    "frequency (8 passes: 1.7 % against 0.9 %), and each pass costs a pressure solve (16 passes: the "
                    "pair's runs took 3.1 times as long)."},
        {.path = "numerics.ibm.marker_spacing",
         .type = K::number,
         .default_value = "1.0",
         .min = at_least(0.3),
         .max = at_most(2.0),
         .meaning = "Distance between neighbouring markers, in grid cells (the smallest cell along the "
                    "outline)."},
        {.path = "numerics.ibm.retraction",
         .type = K::number,
         .default_value = "0.43",
         .min = at_least(0.0),
         .max = at_most(1.0),
         .meaning = "Markers of closed outlines moved this many cells inside the surface, to offset the "
                    "thickness of the diffuse interface (Breugem 2012: 0.3 with roma3 and 3 iterations). 0.43 puts the "
                    "DFG 2D-1 drag on the reference (5.5796 against 5.5795) at 40 cells per diameter with the default "
                    "kernel and iterations (docs/validation.md)."},
        {.path = "numerics.ibm.volume_ramp",
         .type = K::integer,
         .default_value = "2",
         .min = at_least(0),
         .max = at_most(4),
         .meaning = "Width, in cells, of the ramp over which the volume forcing of the fluid inside a closed body "
                    "fades in, from where the markers' kernel stops reaching; a partly forced face follows the "
                    "body's acceleration in full. 0: every face beyond that depth is forced fully, a switch that "
                    "makes the force of a body moving across the grid ripple (5 % on the falling block against 1.4 % "
                    "with 2, both with roma3 and 3 iterations; docs/validation.md, Cell-crossing ripple)."},
        {.path = "numerics.ibm.stress_probes",
         .type = K::number_list,
         .default_value = "[2.5, 3.5, 4.5]",
         .min = above(0),
         .meaning =
             "Distances from the surface, in cells along the normal, of the probes (2 to 6, increasing) that "
             "sample pressure and velocity for the surface-stress force. Fitted by least squares and "
             "evaluated at the surface: the pressure as p_wall + (dp/dn) y + c y^2 with dp/dn from the "
             "momentum equation at the wall, the tangential velocity as a y + b y^2 (no slip). Beyond "
             "2.2 cells the probes' bilinear stencils clear the diffuse interface's reach (docs/validation.md). "
             "With numerics.ibm.interface: sharp and the key not given, [1.5, 2.5, 3.5]: the sharp field has no "
             "smear to clear (DFG 2D-1 at D/h 40: (b) 5.5688 against 5.5441; the 1 m block 0.1 s after its impact "
             "on the bed, whose probes at 4.5 cells reached through the 2-cell gap into the bed: pressure + "
             "viscous + turbulent 12 % under the total against 36 %)."},
        {.path = "numerics.ibm.virtual_mass",
         .type = K::number,
         .default_value = "1.0",
         .min = at_least(0.0),
         .max = at_most(2.0),
         .meaning = "Virtual-mass coefficient C_V of the free-body update (Schwarz, Kempe & Froehlich 2015): C_V "
                    "rho_f V dU/dt is added to both sides, so light bodies (rho_s/rho_f near or below 1) stay "
                    "stable with an explicit coupling. It cancels at convergence; 0 switches it off."},
    };
}

IbmConfig read_ibm(const CaseReader& r) {
    IbmConfig m;
    m.interface =
        r.choice<Interface>("numerics.ibm.interface", {{"sharp", Interface::sharp}, {"diffuse", Interface::diffuse}});
    m.sharp_sweeps = static_cast<int>(r.integer("numerics.ibm.sharp_sweeps"));
    m.sharp_faces = r.choice<IbmConfig::SharpFaces>(
        "numerics.ibm.sharp_faces",
        {{"forcing", IbmConfig::SharpFaces::forcing}, {"ghost", IbmConfig::SharpFaces::ghost}});
    m.cut_momentum = r.boolean("numerics.ibm.cut_momentum");
    using P = IbmConfig::SharpProfileChoice;
    m.sharp_profile = r.choice<P>("numerics.ibm.sharp_profile", {{"auto", P::automatic},
                                                                 {"linear", P::linear},
                                                                 {"quadratic", P::quadratic},
                                                                 {"wall_law", P::wall_law},
                                                                 {"mirror", P::mirror}});
    m.kernel = r.choice<DeltaKernel>("numerics.ibm.kernel", {{"roma3", DeltaKernel::roma3},
                                                             {"peskin4", DeltaKernel::peskin4},
                                                             {"roma3_smoothed", DeltaKernel::roma3_smoothed}});
    m.forcing_iterations = static_cast<int>(r.integer("numerics.ibm.forcing_iterations"));
    m.projection_passes = static_cast<int>(r.integer("numerics.ibm.projection_passes"));
    m.marker_spacing = r.number("numerics.ibm.marker_spacing");
    m.retraction = r.number("numerics.ibm.retraction");
    m.volume_ramp = static_cast<int>(r.integer("numerics.ibm.volume_ramp"));
    m.stress_probes = r.number_list("numerics.ibm.stress_probes");
    // The sharp field is not smeared: the probes come a cell nearer the surface (docs/validation.md, "Sharp
    // interface", tenth step). Nearer still (0.5-1.5 cells) their stencils read the covered cells' extended pressure.
    if (m.interface == Interface::sharp && !r.present("numerics.ibm.stress_probes")) m.stress_probes = {1.5, 2.5, 3.5};
    m.virtual_mass = r.number("numerics.ibm.virtual_mass");
    const std::vector<double>& d = m.stress_probes;
    if (d.size() < 2 || d.size() > 6)
        r.fail("numerics.ibm.stress_probes", "expected 2 to 6 distances, got " + std::to_string(d.size()));
    static const char* const ordinal[] = {"first", "second", "third", "fourth", "fifth", "sixth"};
    for (std::size_t k = 1; k < d.size(); ++k)
        if (!(d[k] > d[k - 1]))
            r.fail("numerics.ibm.stress_probes", std::string("the ") + ordinal[k] +
                                                     " distance must be greater than the " + ordinal[k - 1] + ", got " +
                                                     exact_text(d[k - 1]) + " then " + exact_text(d[k]));
    return m;
}

}  // namespace chute
