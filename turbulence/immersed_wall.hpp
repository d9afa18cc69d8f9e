#pragma once
// Wall functions beside immersed surfaces (the bodies of ibm/), for the k-epsilon model.
//
// Every cell gets the signed distance d to the nearest body surface (Outline::signed_distance; negative
// inside). Cells with d < 0 are solid: the scalar transport closes their faces. Cells with
// -2 h < d < Delta (h the cell size, Delta = turbulence.image_distance cells) form the near-wall band.
// For each band cell the flow is sampled at its image point x_s + Delta n, where x_s = x - d n is the
// nearest surface point and n the outward normal: beyond the reach of the forcing, which smears the
// velocity over 1.5 cells each side of the surface. From k and the tangential velocity relative to the
// body there (wall_function.hpp, y = Delta):
//   nu_w   the wall eddy viscosity; the band cells get nu_t >= nu_w, so the momentum flux through the
//          band, (nu + nu_w) U_t / Delta, is the log-law wall shear (the forcing keeps no-slip at the
//          surface, so without it the shear would be the unresolved nu U_t / Delta)
//   tau_w  the wall shear, which sets the production of k in the wall-function cells (0 <= d < h)
// Static bodies are located once; moving ones every step, within their bounding box.
#include <vector>

#include "case_config.hpp"
#include "euler_lagrange.hpp"
#include "field.hpp"
#include "immersed_boundary.hpp"

namespace chute {

struct NearWallCell {
    int i, j;            // local indices (owned cell)
    double distance;     // d of the cell centre (m); negative inside the body
    double size;         // h (m)
    double nu_wall;      // m^2/s
    double tau_wall;     // kinematic wall shear, m^2/s^2
    bool wall_function;  // 0 <= d < h: epsilon and the production of k come from the wall function
};

class ImmersedWall {
public:
    ImmersedWall(const Grid& grid, const ImmersedBoundary& bodies, const CaseConfig& config);

    bool empty() const { return bodies_.empty(); }
    // Where the bodies are now: the fluid mask and the band (call on every rank after the bodies moved).
    void locate();
    // 1 in fluid cells, 0 inside a body; owned cells and ghosts.
    const Field2D& fluid() const { return fluid_; }
    // Wall-function values at this rank's band cells, sampled from u^{n+1} and k (collective).
    std::vector<NearWallCell> evaluate(const Velocity& vel, const Field2D& k) const;

private:
    struct BandCell {
        int gi, gj;       // global cell
        int body;
        double d, h;
        Vec2 surface, normal;
    };
    void scan(std::size_t b, int gi0, int gi1, int gj0, int gj1);  // cells of body b in a global index box
    void scan_around(std::size_t b, int margin);
    double cell_size(int gi, int gj) const;

    const Grid& grid_;
    const ImmersedBoundary& bodies_;
    double nu_, image_cells_;
    Field2D fluid_, static_fluid_;
    std::vector<BandCell> band_, static_band_;
    bool static_scanned_ = false;
    std::vector<Stencil> su_, sv_, sk_;
    bool located_ = false;
};

}  // namespace chute
