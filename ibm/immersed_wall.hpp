#pragma once
// The walls a turbulence model sees beside immersed surfaces: which cells are solid, which are near a surface,
// and the flow sampled at an image point of each (body/carrier.hpp, WallSample); the wall law is the model's.
//
// Every cell gets the signed distance d to the nearest body surface (Outline::signed_distance; negative
// inside). Cells with d < 0 are solid: the scalar transport closes their faces. Cells with
// -2 h < d < Delta (h the cell size, Delta = turbulence.image_distance cells) form the near-wall band.
// For each band cell the flow is sampled at its image point x_s + Delta n, where x_s = x - d n is the
// nearest surface point and n the outward normal: beyond the reach of the forcing, which smears the
// velocity up to the kernel's support less the retraction outside the surface (1.57 cells by default). From k and the
// tangential velocity relative to the body there the model's wall law (turbulence/wall_function.hpp, y = Delta) gives
//   nu_w   the wall eddy viscosity; the band cells get nu_t >= nu_w, so the momentum flux through the
//          band, (nu + nu_w) U_t / Delta, is the log-law wall shear (the forcing keeps no-slip at the
//          surface, so without it the shear would be the unresolved nu U_t / Delta)
//   tau_w  the wall shear, which sets the production of k in the wall-function cells (0 <= d < h)
// Static bodies are located once; moving ones every step, within their bounding box.
//
// That band is the diffuse interface's (NearWall::band). A sharp interface with ghost faces (NearWall::surface) keeps
// every fluid cell's own equations up to the surface, as a body-fitted grid does: the samples are the wall-function
// cells alone (0 <= d < h), each at the point x_s + y n with y = max(d, h/2), its own centre where the surface lies
// on grid lines, and the model puts the wall law on the corners between fluid and solid cells rather than on a band
// of cells (turbulence/k_epsilon.cpp: the first cells of a body-fitted wall, sampled where those sit).
#include <vector>

#include "body.hpp"
#include "carrier.hpp"
#include "euler_lagrange.hpp"
#include "field.hpp"
#include "grid_placement.hpp"

namespace chute {

enum class NearWall { band, surface };

class ImmersedWall {
public:
    // image_cells: Delta, in cells (turbulence.image_distance).
    ImmersedWall(const Grid& grid, const std::vector<Body>& bodies, double image_cells,
                 NearWall near_wall = NearWall::band);

    bool empty() const { return bodies_.empty(); }
    NearWall near_wall() const { return near_wall_; }
    // Where the bodies are now: the fluid mask and the band (call on every rank after the bodies moved).
    void locate();
    // 1 in fluid cells, 0 inside a body; owned cells and ghosts.
    const Field2D& fluid() const { return fluid_; }
    // The flow at the image points of this rank's band cells, from u^{n+1} and k (collective).
    std::vector<WallSample> sample(const Velocity& vel, const Field2D& k) const;

private:
    struct BandCell {
        int gi, gj;  // global cell
        int body;
        double d, h;
        Vec2 surface, normal;
    };
    void scan(std::size_t b, int gi0, int gi1, int gj0, int gj1);  // cells of body b in a global index box
    void scan_around(std::size_t b, int margin);
    double cell_size(int gi, int gj) const;
    double sample_distance(const BandCell& c) const;  // from the surface, of the point a band cell samples

    const Grid& grid_;
    const std::vector<Body>& bodies_;
    double image_cells_;
    NearWall near_wall_;
    Field2D fluid_, static_fluid_;
    std::vector<BandCell> band_, static_band_;
    bool static_scanned_ = false;
    std::vector<Stencil> su_, sv_, sk_;
    GridPlacement placement_{grid_};  // of the wall cells
};

}  // namespace chute
