#pragma once
// The immersed boundary's part of a case (docs/case-file.md, `numerics.ibm`): the delta kernel, the forcing,
// where the markers sit, how the surface stress is sampled, and the virtual mass of the free-body update.
// Plain data: read_ibm() fills it (ibm_keys.cpp, the schema's numerics.ibm section).
#include <array>
#include <vector>

namespace chute {

enum class DeltaKernel { roma3, peskin4, roma3_smoothed };
// How the surface enters the equations (immersed_forcing.hpp).
enum class Interface { sharp, diffuse };

struct IbmConfig {
    Interface interface = Interface::diffuse;
    int sharp_sweeps = 3;
    // Which faces the sharp interface reconstructs: the fluid faces beside the surface (forcing, Fadlun et al. 2000)
    // or the faces inside it beside the fluid (ghost, Tseng & Ferziger 2003), the fluid faces then free.
    enum class SharpFaces { forcing, ghost } sharp_faces = SharpFaces::forcing;
    // Ghost faces: the faces a surface cuts keep their own momentum, with the wall in their viscous stencils where it
    // lies, and the convection is transported by the cut fluxes (sharp_forcing.hpp, "cut momentum").
    bool cut_momentum = false;
    // The sharp interface's profile beside the surface (sharp_forcing.hpp): automatic (quadratic in laminar runs;
    // with a wall-function model the law of the wall on forcing faces, the mirror on ghost faces), or one of them.
    enum class SharpProfileChoice {
        automatic,
        linear,
        quadratic,
        wall_law,
        mirror
    } sharp_profile = SharpProfileChoice::automatic;
    DeltaKernel kernel = DeltaKernel::roma3_smoothed;  // Yang et al. 2009: no cell-crossing ripple
    int forcing_iterations = 10;                       // multi-direct forcing (Breugem 2012)
    int projection_passes = 1;                         // forcing and projection per step (run/step.cpp)
    double marker_spacing = 1.0;                       // in grid cells
    double retraction = 0.43;                          // markers moved inwards by this many cells (DFG 2D-1 drag)
    int volume_ramp = 2;                               // cells over which the volume forcing fades in (0: a switch)
    // Probe distances along the normal, in cells (the sharp interface's default, when the key is not given, is
    // 1.5, 2.5, 3.5: read_ibm).
    std::vector<double> stress_probes{2.5, 3.5, 4.5};
    double virtual_mass = 1.0;  // C_V of the free-body update (Schwarz et al. 2015)
};

// The schema's numerics.ibm section (io/case_reader.hpp) and its reading (2 to 6 probes, each beyond the one before).
struct CaseKey;
class CaseReader;
std::vector<CaseKey> ibm_keys();
IbmConfig read_ibm(const CaseReader& reader);

}  // namespace chute
