#include "sharp_forcing.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "cut_faces.hpp"       // on_surface_tolerance, surface_distance
#include "direct_forcing.hpp"  // min_spacing_along

namespace chute {

namespace {

// Every rank's values, in rank order; `first`: where this rank's start.
std::vector<double> gathered(const Grid& grid, const std::vector<double>& mine, std::size_t& first) {
    const int count = static_cast<int>(mine.size());
    std::vector<int> counts(grid.size()), offsets(grid.size(), 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, grid.comm());
    for (int r = 1; r < grid.size(); ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    std::vector<double> all(offsets.back() + counts.back());
    MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, grid.comm());
    first = static_cast<std::size_t>(offsets[grid.rank()]);
    return all;
}

}  // namespace

std::vector<Stencil> gathered_stencils(const Grid& grid, Staggering s, const std::vector<Vec2>& mine,
                                       std::size_t& first) {
    std::vector<double> flat;
    for (const Vec2& X : mine) flat.insert(flat.end(), {X.x(), X.y()});
    const std::vector<double> all = gathered(grid, flat, first);
    std::vector<Vec2> points(all.size() / 2);
    for (std::size_t k = 0; k < points.size(); ++k) points[k] = {all[2 * k], all[2 * k + 1]};
    first /= 2;
    return bilinear_stencils(grid, s, points);
}

SharpForcing::SharpForcing(const Grid& grid, const IbmConfig& config, const std::vector<Body>& bodies,
                           double image_cells, SharpProfile profile, double viscosity, WallProfile wall_profile)
    : grid_(grid),
      config_(config),
      bodies_(bodies),
      image_cells_(image_cells),
      profile_(profile),
      viscosity_(viscosity),
      ghost_(config.sharp_faces == IbmConfig::SharpFaces::ghost),
      cut_momentum_(ghost_ && config.cut_momentum),
      wall_profile_(std::move(wall_profile)),
      uncovered_(grid, 1.0),
      result_(bodies.size()),
      open_flux_(grid),
      wall_faces_(grid) {
    for (const Body& body : bodies_) cell_size_.push_back(min_spacing_along(grid_, body));
    if (profile_ == SharpProfile::wall_law && !wall_profile_)
        throw std::invalid_argument("SharpForcing: the wall-law profile needs the law (wall_profile)");
    if (profile_ == SharpProfile::mirror && !ghost_)
        throw std::invalid_argument("SharpForcing: the mirror profile sets ghost faces (numerics.ibm.sharp_faces)");
}

void SharpForcing::classify_component(bool is_u, Component& out) const {
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    auto position = [&](int i, int j) { return is_u ? Vec2(X.f(i), Y.c(j)) : Vec2(X.c(i), Y.f(j)); };
    auto volume = [&](int i, int j) { return is_u ? X.dc(i) * Y.w(j) : X.w(i) * Y.dc(j); };

    // Every body's candidates, then one entry per face: inside a body first, else the nearest surface.
    std::vector<ForcedFace> candidates;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const Body& body = bodies_[b];
        const Outline& outline = body.outline();
        const double surface = on_surface(b);
        const auto [i0, i1, j0, j1] = faces_in_reach(b, is_u);
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const Vec2 p = position(i, j);
                const double phi = outline.signed_distance(body.to_body(p));
                const double spacing = std::max(X.dc(i) + X.w(i), Y.dc(j) + Y.w(j));  // bounds a neighbour's distance
                // A forcing face is at most one face spacing from the surface (sqrt 2 of a cell at a corner).
                if (phi >= 1.5 * spacing) continue;
                // Reconstructed: beside the surface on the side the method sets (a neighbour across it).
                const bool inside = phi < surface;
                // Deeper inside than a neighbour's spacing (the distance is 1-Lipschitz): no neighbour across, the
                // body's velocity alone (no surface point needed). Below a plane, half the grid.
                if (inside && phi < surface - spacing) {
                    candidates.push_back({i, j, static_cast<int>(b), volume(i, j), p, phi, p, Vec2(0.0, 0.0), false});
                    continue;
                }
                if (ghost_ && !inside) {  // ghost faces: only inside faces, and those the body left since
                    if (!out.inside.empty() && out.inside[face_key(i, j)]) {
                        const SurfacePoint s = outline.nearest(body.to_body(p));
                        ForcedFace f{i,   j,   static_cast<int>(b),       volume(i, j),
                                     p,   phi, body.to_world(s.position), body.direction_to_world(s.normal),
                                     true};
                        f.fresh = true;
                        candidates.push_back(f);
                    }
                    continue;
                }
                bool across = false;
                if (cut_momentum_) {
                    // Inside here. A face with an open part is a fluid face; a shut one a ghost beside one.
                    if (face_cut_any(is_u, i, j).alpha > 0.0) continue;
                    for (const auto& [di, dj] : {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}})
                        across = across || face_cut_any(is_u, i + di, j + dj).alpha > 0.0;
                } else {
                    const Vec2 neighbours[4] = {position(i - 1, j), position(i + 1, j), position(i, j - 1),
                                                position(i, j + 1)};
                    for (const Vec2& q : neighbours)
                        across = across || (outline.signed_distance(body.to_body(q)) < surface) != inside;
                }
                if (!inside && !across) continue;
                const SurfacePoint s = outline.nearest(body.to_body(p));
                candidates.push_back({i, j, static_cast<int>(b), volume(i, j), p, phi, body.to_world(s.position),
                                      body.direction_to_world(s.normal), ghost_ ? across : !inside});
            }
    }
    std::vector<int> chosen(face_keys(), -1);  // per face: its place in `faces`
    std::vector<ForcedFace> faces;
    for (const ForcedFace& f : candidates) {
        int& place = chosen[face_key(f.i, f.j)];
        if (place < 0) {
            place = static_cast<int>(faces.size());
            faces.push_back(f);
        } else if (ForcedFace& kept = faces[place]; f.phi < kept.phi)  // inside first, then the nearest
            kept = f;
    }
    out.solid.clear();
    out.forcing.clear();
    out.inside.assign(face_keys(), 0);
    for (const ForcedFace& f : faces) {
        (f.reconstructed ? out.forcing : out.solid).push_back(f);
        if (ghost_ && !f.fresh) out.inside[face_key(f.i, f.j)] = 1;
    }

    // Image points X_s + L n, L = image_cells h_n (h_n the cells' extent along n), at least 4/3 of phi so that the
    // face's own weight stays at most 3/4, and with a quadratic profile a second one at L2 = L + h_n. Every rank
    // builds the stencils of every rank's image points (gathered_stencils) and keeps its own part of each.
    std::vector<Vec2> mine, mine2;
    for (ForcedFace& f : out.forcing) {
        if (ghost_) {
            const auto [a, b] = end_distances(f.body, is_u, f.i, f.j);
            f.cut = (a < 0.0) != (b < 0.0);
            f.open_phi = 0.5 * std::max({a, b, 0.0});
        }
        const Vec2 n = f.normal;
        const Vec2 h = local_spacing(grid_, f.surface);
        const double hn = std::hypot(n.x() * h.x(), n.y() * h.y());
        const bool mirror = profile_ == SharpProfile::mirror && !f.fresh;
        const double L = mirror ? std::max(std::abs(f.phi), 0.5 * hn) : std::max(image_cells_ * hn, f.phi / 0.75);
        f.image_distance = L;
        mine.push_back(f.surface + L * n);
        if (profile_ != SharpProfile::quadratic) {
            f.weight = f.phi / L;
            f.weight2 = 0.0;
            f.open_weight = f.open_phi / L;
        } else {
            // Lagrange weights of the quadratic through (0, U_s), (L, u_1), (L2, u_2), at y: at the face (phi) and
            // at the middle of its open part.
            const double L2 = L + hn;
            const auto weights = [&](double y) {
                return std::pair{y * (L2 - y) / (L * (L2 - L)), -y * (L - y) / (L2 * (L2 - L))};
            };
            std::tie(f.weight, f.weight2) = weights(f.phi);
            std::tie(f.open_weight, f.open_weight2) = weights(f.open_phi);
            mine2.push_back(f.surface + L2 * n);
        }
    }
    if (profile_ == SharpProfile::quadratic)
        out.images2 = gathered_stencils(grid_, is_u ? Staggering::u_face : Staggering::v_face, mine2, out.first_image);
    out.images = gathered_stencils(grid_, is_u ? Staggering::u_face : Staggering::v_face, mine, out.first_image);
    if (profile_ == SharpProfile::wall_law)
        out.images_other =
            gathered_stencils(grid_, is_u ? Staggering::v_face : Staggering::u_face, mine, out.first_image);
    // A face near its image point is part of the image's stencil (the face's own row is one of the two a bilinear
    // interpolation reads; beside a domain wall, whose faces are no unknowns, the only one): reconstruction() solves
    // for that part instead of iterating it. (Iterated, the mirror u = 2 U_b - u(image) with the image wholly on the
    // face itself flips its sign every sweep and never settles: a block resting a third of a cell above the bed kept
    // the gap's faces at 2.2 m/s and diverged.)
    out.self.assign(out.forcing.size(), 0.0);
    for (std::size_t k = 0; k < out.forcing.size(); ++k)
        for (const StencilPoint& q : out.images[out.first_image + k])
            if (q.i == out.forcing[k].i && q.j == out.forcing[k].j) out.self[k] += q.weight;
}

SharpForcing::FaceRange SharpForcing::faces_in_reach(std::size_t b, bool is_u) const {
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    // Faces on a non-periodic domain boundary are the boundary conditions' (euler_lagrange.cpp, axis_points).
    const int first_i = is_u && !grid_.x_axis().periodic() && X.offset == 0 ? 1 : 0;
    const int first_j = !is_u && !grid_.y_axis().periodic() && Y.offset == 0 ? 1 : 0;
    auto position = [&](int i, int j) { return is_u ? Vec2(X.f(i), Y.c(j)) : Vec2(X.c(i), Y.f(j)); };
    FaceRange r{first_i, grid_.nx() - 1, first_j, grid_.ny() - 1};
    const Body& body = bodies_[b];
    if (!body.outline().closed()) return r;
    const Vec2 c = body.state().centre;
    const double reach = body.outline().reach() + 2.0 * cell_size_[b];
    while (r.i0 <= r.i1 && position(r.i0, 0).x() < c.x() - reach - X.w(r.i0)) ++r.i0;
    while (r.i1 >= r.i0 && position(r.i1, 0).x() > c.x() + reach + X.w(r.i1)) --r.i1;
    while (r.j0 <= r.j1 && position(0, r.j0).y() < c.y() - reach - Y.w(r.j0)) ++r.j0;
    while (r.j1 >= r.j0 && position(0, r.j1).y() > c.y() + reach + Y.w(r.j1)) --r.j1;
    return r;
}

SharpForcing::FaceCut SharpForcing::face_cut(std::size_t b, bool is_u, int i, int j) const {
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    const Vec2 A(X.f(i), Y.f(j));
    const Vec2 B = is_u ? Vec2(X.f(i), Y.f(j + 1)) : Vec2(X.f(i + 1), Y.f(j));
    const Vec2 centre = 0.5 * (A + B);
    const auto [a, b_end] = end_distances(b, is_u, i, j);
    if ((a < 0.0) == (b_end < 0.0)) return {a < 0.0 ? 0.0 : 1.0, centre};
    const Vec2 outer = a >= 0.0 ? A : B, inner = a >= 0.0 ? B : A;
    const double alpha = open_fraction(bodies_[b], outer, inner, on_surface(b));
    if (alpha < kWholeFace) return {0.0, centre};  // CutFaces' rule: that near an end, whole
    if (alpha > 1.0 - kWholeFace) return {1.0, centre};
    return {alpha, outer + 0.5 * alpha * (inner - outer)};
}

SharpForcing::FaceCut SharpForcing::face_cut_any(bool is_u, int i, int j) const {
    // Asked about each face and its neighbours several times per classification: kept per face key until the next.
    const bool keyed = i >= 0 && j >= 0 && i <= grid_.nx() && j <= grid_.ny();
    std::vector<FaceCut>& cache = face_cuts_[is_u ? 0 : 1];
    if (keyed) {
        if (cache.empty()) cache.assign(face_keys(), FaceCut{-1.0, Vec2::Zero(), -1});
        const FaceCut& kept = cache[face_key(i, j)];
        if (kept.alpha >= 0.0) return kept;
    }
    const FaceCut cut = face_cut_across_bodies(is_u, i, j);
    if (keyed) cache[face_key(i, j)] = cut;
    return cut;
}

SharpForcing::FaceCut SharpForcing::face_cut_across_bodies(bool is_u, int i, int j) const {
    // As CutFaces counts a face: each end's distance to the nearest surface, the face cut by the body its inside end
    // is in (the deeper end's when both are).
    double ends[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    int owner[2] = {-1, -1};
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const auto [a, e] = end_distances(b, is_u, i, j);
        if (a < ends[0]) ends[0] = a, owner[0] = static_cast<int>(b);
        if (e < ends[1]) ends[1] = e, owner[1] = static_cast<int>(b);
    }
    if (ends[0] >= 0.0 && ends[1] >= 0.0) {  // open whole: its centre
        const LocalAxis& X = grid_.lx();
        const LocalAxis& Y = grid_.ly();
        return {1.0, is_u ? Vec2(X.f(i), Y.c(j)) : Vec2(X.c(i), Y.f(j)), -1};
    }
    const int body = ends[0] <= ends[1] ? owner[0] : owner[1];
    FaceCut cut = face_cut(static_cast<std::size_t>(body), is_u, i, j);
    cut.body = body;
    return cut;
}

void SharpForcing::find_wall_stencils() {
    wall_stencils_.clear();
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    for (const bool is_u : {true, false}) {
        auto centre = [&](int i, int j) { return is_u ? Vec2(X.f(i), Y.c(j)) : Vec2(X.c(i), Y.f(j)); };
        const int along = is_u ? 1 : 0;          // the axis of the face's segment: a cut moves its point along it
        std::vector<char> seen(face_keys(), 0);  // a face in the reach of several bodies is done once
        for (std::size_t b = 0; b < bodies_.size(); ++b) {
            const Body& body = bodies_[b];
            const auto [i0, i1, j0, j1] = faces_in_reach(b, is_u);
            for (int j = j0; j <= j1; ++j)
                for (int i = i0; i <= i1; ++i) {
                    char& done = seen[face_key(i, j)];
                    if (done) continue;
                    // Beyond two face spacings from this body no stencil reaches it (a plane's reach is the grid).
                    const double spacing = std::max(X.dc(i) + X.w(i), Y.dc(j) + Y.w(j));
                    if (body.outline().signed_distance(body.to_body(centre(i, j))) > spacing) continue;
                    done = 1;
                    const FaceCut F = face_cut_any(is_u, i, j);
                    if (F.alpha <= 0.0) continue;
                    WallStencil w;
                    w.i = i;
                    w.j = j;
                    w.body = F.body;
                    w.is_u = is_u;
                    double nearest = std::numeric_limits<double>::infinity();  // the nearest wall part's distance
                    for (int d = 0; d < 2; ++d) {
                        const int step[2] = {d == 0 ? 1 : 0, d == 0 ? 0 : 1};
                        bool active = F.alpha < 1.0 && d == along;
                        for (int side = 0; side < 2; ++side) {
                            const int sign = side == 0 ? -1 : 1;
                            const int gi = i + sign * step[0], gj = j + sign * step[1];
                            const Vec2 offset = centre(gi, gj) - centre(i, j);
                            w.uniform[d][side] = std::abs(offset[d]);
                            const FaceCut G = face_cut_any(is_u, gi, gj);
                            if (G.alpha > 0.0) {
                                w.distance[d][side] = std::abs((G.point - F.point)[d]);
                                active = active || (G.alpha < 1.0 && d == along);
                                if (w.body < 0 && G.body >= 0) w.body = G.body;
                                continue;
                            }
                            // Shut: the first surface between the point and the neighbour's place seen from it.
                            double a = 1.0;
                            int by = G.body;
                            for (std::size_t c = 0; c < bodies_.size(); ++c) {
                                const double f = open_fraction(bodies_[c], F.point, F.point + offset, on_surface(c));
                                if (f < a) a = f, by = static_cast<int>(c);
                            }
                            w.wall[d][side] = true;
                            w.wall_body[d][side] = by;
                            w.distance[d][side] = std::max(a, 1e-9) * w.uniform[d][side];
                            w.wall_point[d][side] = F.point + a * offset;
                            if (w.distance[d][side] < nearest && F.alpha >= 1.0)
                                nearest = w.distance[d][side], w.body = by;
                            active = true;
                        }
                        w.active[d] = active;
                        w.width[d] = 0.5 * (w.distance[d][0] + w.distance[d][1]);
                        // The flow solver's control-volume width along d (core/operators/diffusion.cpp).
                        w.uniform_width[d] = is_u ? (d == 0 ? X.dc(i) : Y.w(j)) : (d == 0 ? X.w(i) : Y.dc(j));
                    }
                    if ((w.active[0] || w.active[1]) && w.body >= 0) wall_stencils_.push_back(w);
                }
        }
    }
}

double SharpForcing::face_k(const WallStencil& w) const {
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    const Field2D& k = wall_turbulence_->k;
    // The face's two cells (across it), then those beside them along its segment.
    const int di = w.is_u ? 1 : 0, dj = w.is_u ? 0 : 1;
    for (const int reach : {0, 1}) {
        double sum = 0.0, n = 0.0;
        for (const int along : {-reach, reach}) {
            const int ai = w.i + (w.is_u ? 0 : along), aj = w.j + (w.is_u ? along : 0);
            for (const auto& [ci, cj] : {std::pair{ai - di, aj - dj}, std::pair{ai, aj}})
                if (!inside_any(Vec2(X.c(ci), Y.c(cj)))) sum += k(ci, cj), n += 1.0;
            if (reach == 0) break;
        }
        if (n > 0.0) return sum / n;
    }
    return 0.0;
}

double SharpForcing::stencil_coefficient(const WallStencil& w, int d, int side, bool at_wall, double k) const {
    if (!viscous_.stress_form) return viscosity_;
    const bool normal = (d == 0) == w.is_u;  // the flux along the component's own axis: a normal stress
    if (at_wall && !normal && wall_turbulence_)
        return viscosity_ + wall_turbulence_->wall_viscosity(k, w.distance[d][side]);
    const EddyViscosity* eddy = viscous_.eddy;
    if (normal) {
        // The cell between the face and its neighbour on that side (viscous_stress.cpp).
        const int ci = w.is_u ? w.i - 1 + side : w.i, cj = w.is_u ? w.j : w.j - 1 + side;
        return 2.0 * (viscosity_ + (eddy ? eddy->cell(ci, cj) : 0.0));
    }
    const int ki = w.is_u ? w.i : w.i + side, kj = w.is_u ? w.j + side : w.j;
    return viscosity_ + (eddy ? eddy->corner(ki, kj) : 0.0);
}

void SharpForcing::apply_wall_stencils(Velocity& star, double dt,
                                       const std::function<void(const WallStencil&, int, double)>& account) {
    if (!viscous_.applied_to) throw std::logic_error("SharpForcing: cut momentum needs the step's viscous operator");
    struct Solved {
        double value;
        double rate[2][2];        // dt K / (width distance) of each part
        double wall_speed[2][2];  // the wall's velocity component on the wall parts
    };
    std::vector<Solved> solved(wall_stencils_.size());
    for (std::size_t k = 0; k < wall_stencils_.size(); ++k) {
        const WallStencil& w = wall_stencils_[k];
        Solved& r = solved[k];
        const Field2D& start = w.is_u ? viscous_.applied_to->u : viscous_.applied_to->v;
        const double u0 = start(w.i, w.j);
        // k of the face's cells, for the wall law's shear (once per stencil).
        const bool shear_wall = wall_turbulence_ && viscous_.stress_form &&
                                (w.is_u ? w.wall[1][0] || w.wall[1][1] : w.wall[0][0] || w.wall[0][1]);
        const double k_face = shear_wall ? face_k(w) : 0.0;
        double sum = (w.is_u ? star.u : star.v)(w.i, w.j), diagonal = 1.0;
        for (int d = 0; d < 2; ++d) {
            if (!w.active[d]) continue;
            const double u_minus = start(d == 0 ? w.i - 1 : w.i, d == 0 ? w.j : w.j - 1);
            const double u_plus = start(d == 0 ? w.i + 1 : w.i, d == 0 ? w.j : w.j + 1);
            const double uniform_plus = stencil_coefficient(w, d, 1, false, k_face) * (u_plus - u0) / w.uniform[d][1];
            const double uniform_minus = stencil_coefficient(w, d, 0, false, k_face) * (u0 - u_minus) / w.uniform[d][0];
            sum -= dt * (uniform_plus - uniform_minus) / w.uniform_width[d];
            for (int side = 0; side < 2; ++side) {
                double neighbour = side == 0 ? u_minus : u_plus;
                if (w.wall[d][side]) {
                    const Vec2 U = bodies_[w.wall_body[d][side]].velocity_at(w.wall_point[d][side]);
                    neighbour = w.is_u ? U.x() : U.y();
                    r.wall_speed[d][side] = neighbour;
                }
                const double rate =
                    dt * stencil_coefficient(w, d, side, w.wall[d][side], k_face) / (w.width[d] * w.distance[d][side]);
                r.rate[d][side] = rate;
                sum += rate * neighbour;
                diagonal += rate;
            }
        }
        r.value = sum / diagonal;
    }
    for (std::size_t k = 0; k < wall_stencils_.size(); ++k) {
        const WallStencil& w = wall_stencils_[k];
        const Solved& r = solved[k];
        double& u = (w.is_u ? star.u : star.v)(w.i, w.j);
        // Each wall part's flux to its own body (a face between two surfaces: the gap under a block on a slope), the
        // rest of the change (the stencil's own redistribution) to the face's body.
        double rest = r.value - u;
        for (int d = 0; d < 2; ++d)
            for (int side = 0; side < 2; ++side) {
                const int b = w.wall_body[d][side];
                if (!w.active[d] || !w.wall[d][side] || b == w.body) continue;
                const double flux = r.rate[d][side] * (r.wall_speed[d][side] - r.value);
                account(w, b, flux);
                rest -= flux;
            }
        account(w, w.body, rest);
        u = r.value;
    }
}

void SharpForcing::classify() {
    for (std::vector<FaceCut>& cache : face_cuts_) cache.clear();  // the bodies moved
    classify_component(true, u_);
    classify_component(false, v_);
    // The faces held_momentum() counts as the bodies': those the forcing sets as the bodies' (a face the body left
    // since, set from the profile in the step it opens, is the fluid's).
    for (auto [c, by] : {std::pair{&u_, &forced_by_u_}, std::pair{&v_, &forced_by_v_}}) {
        by->assign(face_keys(), -1);
        for (const std::vector<ForcedFace>* faces : {&c->solid, &c->forcing})
            for (const ForcedFace& f : *faces)
                if (!f.fresh) (*by)[face_key(f.i, f.j)] = f.body;
    }
    if (cut_momentum_) find_wall_stencils();
    find_covered_cells();
    if (ghost_ && !cut_momentum_) {  // cut momentum's convection reads the cut fluxes instead
        wall_faces_.u.fill(0.0);
        wall_faces_.v.fill(0.0);
        // Strictly inside: a face on the surface (a wall on a grid line) holds the wall's own velocity, as a
        // body-fitted wall's face does, and the flux between it and the next face lies half a cell into the fluid.
        for (auto [c, field] : {std::pair{&u_, &wall_faces_.u}, std::pair{&v_, &wall_faces_.v}}) {
            for (const std::vector<ForcedFace>* faces : {&c->solid, &c->forcing})
                for (const ForcedFace& f : *faces)
                    if (!f.fresh && f.phi < -on_surface(f.body)) (*field)(f.i, f.j) = 1.0;
        }
    }
    placed_ = true;
    placement_.computed();
}

std::vector<EnclosedMomentum> SharpForcing::held_momentum(const Velocity& vel) const {
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    std::vector<double> sums(3 * bodies_.size(), 0.0);  // x, y and moment per body
    if (placed_)
        for (std::size_t b = 0; b < bodies_.size(); ++b) {
            const Body& body = bodies_[b];
            if (!body.outline().closed()) continue;  // a plane or segment holds no fluid of its own
            const Vec2 c = body.state().centre;
            for (const bool is_u : {true, false}) {
                const std::vector<int>& by = is_u ? forced_by_u_ : forced_by_v_;
                const Field2D& field = is_u ? vel.u : vel.v;
                const auto [i0, i1, j0, j1] = faces_in_reach(b, is_u);
                for (int j = j0; j <= j1; ++j)
                    for (int i = i0; i <= i1; ++i) {
                        const int owner = by[face_key(i, j)];
                        if (owner >= 0 && owner != static_cast<int>(b)) continue;
                        const Vec2 p = is_u ? Vec2(X.f(i), Y.c(j)) : Vec2(X.c(i), Y.f(j));
                        const double dx = is_u ? X.dc(i) : X.w(i), dy = is_u ? Y.w(j) : Y.dc(j);
                        // The part of the face's control volume inside the body, its area and first moment about
                        // the centre exactly (a part taken along the normal, 1/2 - phi / w, missed the corners: a
                        // square carried at U through fluid moving with it read a force of 8 % of its drag that
                        // changed with its place in its cells, and a disk a moment); w = |n_x| dx + |n_y| dy, the
                        // volume's extent along the normal.
                        const double volume = dx * dy;
                        const Vec2 lo = is_u ? Vec2(X.c(i - 1), Y.f(j)) : Vec2(X.f(i), Y.c(j - 1));
                        const Vec2 hi = is_u ? Vec2(X.c(i), Y.f(j + 1)) : Vec2(X.f(i + 1), Y.c(j));
                        const Vec2 whole_moment = volume * (0.5 * (lo + hi) - c);
                        const Vec2 local = body.to_body(p);
                        const double phi = body.outline().signed_distance(local);
                        Outline::Part inside;
                        if (phi < 0.0) inside = {volume, whole_moment};
                        double w = 0.0;
                        const double farthest_corner = std::hypot(std::max(p.x() - lo.x(), hi.x() - p.x()),
                                                                  std::max(p.y() - lo.y(), hi.y() - p.y()));
                        if (std::abs(phi) < farthest_corner) {
                            const Vec2 n = body.direction_to_world(body.outline().nearest(local).normal);
                            w = std::abs(n.x()) * dx + std::abs(n.y()) * dy;
                            inside = body.outline().part_in_box(c, body.state().angle, lo, hi);
                        }
                        const double beta = std::clamp(inside.area / volume, 0.0, 1.0);
                        const double u = field(i, j);
                        const Vec2 e = is_u ? Vec2(1.0, 0.0) : Vec2(0.0, 1.0);
                        Vec2 linear = inside.area * u * e;
                        double angular = cross(inside.moment, u * e);
                        if (owner >= 0) {
                            // The fluid part of a forced face's volume: from the surface out to w / 2 + phi, where
                            // the profile the ghost holds (carried through the wall from U_b, over L = |phi|, at
                            // least half the extent) has the mean U_b + (U_b - u) (w / 2 + phi) / (2 L). The face
                            // holds V u at its place less that part's momentum at the part's centroid.
                            const Vec2 U = body.velocity_at(p);
                            const double Ub = is_u ? U.x() : U.y();
                            const double outer = (1.0 - beta) * w;
                            const double mean =
                                outer > 0.0 ? Ub + (Ub - u) * outer / (2.0 * std::max(-phi, 0.5 * w)) : Ub;
                            linear = (volume * u - (volume - inside.area) * mean) * e;
                            angular = cross(p - c, volume * u * e) - cross(whole_moment - inside.moment, mean * e);
                        }
                        sums[3 * b] += linear.x();
                        sums[3 * b + 1] += linear.y();
                        sums[3 * b + 2] += angular;
                    }
            }
        }
    if (grid_.size() > 1)
        MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
    std::vector<EnclosedMomentum> out(bodies_.size());
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        out[b].linear = Vec2(sums[3 * b], sums[3 * b + 1]);
        out[b].angular = sums[3 * b + 2];
    }
    return out;
}

std::pair<double, double> SharpForcing::end_distances(std::size_t b, bool is_u, int i, int j) const {
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    const Body& body = bodies_[b];
    const Vec2 second = is_u ? Vec2(X.f(i), Y.f(j + 1)) : Vec2(X.f(i + 1), Y.f(j));
    return {surface_distance(body, Vec2(X.f(i), Y.f(j)), on_surface(b)), surface_distance(body, second, on_surface(b))};
}

long long SharpForcing::face_key(int i, int j) const {
    return static_cast<long long>(j) * (grid_.nx() + 2 * kGhost) + i;
}

std::size_t SharpForcing::face_keys() const {
    return static_cast<std::size_t>(grid_.ny() + 2) * (grid_.nx() + 2 * kGhost);
}

double SharpForcing::on_surface(std::size_t b) const {
    const double tolerance = on_surface_tolerance(cell_size_[b]);
    return ghost_ ? tolerance : -tolerance;
}

bool SharpForcing::inside_any(const Vec2& X) const {
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const Body& body = bodies_[b];
        if (body.outline().signed_distance(body.to_body(X)) < on_surface(b)) return true;
    }
    return false;
}

bool SharpForcing::forced(bool is_u, int i, int j) const {
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    auto position = [&](int a, int b) { return is_u ? Vec2(X.f(a), Y.c(b)) : Vec2(X.c(a), Y.f(b)); };
    return inside_any(position(i, j)) || inside_any(position(i - 1, j)) || inside_any(position(i + 1, j)) ||
           inside_any(position(i, j - 1)) || inside_any(position(i, j + 1));
}

void SharpForcing::find_covered_cells() {
    for (const CoveredCell& c : covered_) uncovered_(c.i, c.j) = 1.0;
    covered_.clear();
    const LocalAxis& X = grid_.lx();
    const LocalAxis& Y = grid_.ly();
    const int nx = grid_.nx(), ny = grid_.ny();
    std::vector<Vec2> images;
    std::vector<char> seen(static_cast<std::size_t>(nx) * ny, 0);
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const Body& body = bodies_[b];
        const Outline& outline = body.outline();
        const double h = cell_size_[b];
        int i0 = 0, i1 = nx - 1, j0 = 0, j1 = ny - 1;
        if (outline.closed()) {
            const Vec2 c = body.state().centre;
            const double reach = outline.reach() + 2.0 * h;
            while (i0 <= i1 && X.f(i0 + 1) < c.x() - reach) ++i0;
            while (i1 >= i0 && X.f(i1) > c.x() + reach) --i1;
            while (j0 <= j1 && Y.f(j0 + 1) < c.y() - reach) ++j0;
            while (j1 >= j0 && Y.f(j1) > c.y() + reach) --j1;
        }
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                char& done = seen[static_cast<std::size_t>(j) * nx + i];
                const Vec2 centre(X.c(i), Y.c(j));
                const double phi = outline.signed_distance(body.to_body(centre));
                const double size = std::max(X.w(i), Y.w(j));
                if (done || phi > 1.5 * size || phi < -3.0 * size) continue;
                // Ghost faces: the cells left out of the pressure problem (its four corners inside: every face shut,
                // ibm/cut_faces.hpp), whose pressure the solve no longer sets; forcing faces: the cells whose four
                // faces are forced.
                auto corner_inside = [&](int a, int b) { return inside_any(Vec2(X.f(a), Y.f(b))); };
                const bool covered = ghost_ ? corner_inside(i, j) && corner_inside(i + 1, j) &&
                                                  corner_inside(i, j + 1) && corner_inside(i + 1, j + 1)
                                            : forced(true, i, j) && forced(true, i + 1, j) && forced(false, i, j) &&
                                                  forced(false, i, j + 1);
                if (!covered) continue;
                done = 1;
                const SurfacePoint s = outline.nearest(body.to_body(centre));
                const Vec2 n = body.direction_to_world(s.normal);
                const Vec2 at = body.to_world(s.position);
                const Vec2 hs = local_spacing(grid_, at);
                covered_.push_back({i, j});
                images.push_back(at + 2.5 * std::hypot(n.x() * hs.x(), n.y() * hs.y()) * n);
            }
    }
    for (const CoveredCell& c : covered_) uncovered_(c.i, c.j) = 0.0;
    covered_images_ = gathered_stencils(grid_, Staggering::cell, images, first_covered_);
}

void SharpForcing::extend_pressure(Field2D& p) const {
    // Each image point's value from the uncovered cells of its stencil: sum w p / sum w over them (one reduction).
    const std::size_t n = covered_images_.size();
    std::vector<double> sums(2 * n, 0.0);
    for (std::size_t l = 0; l < n; ++l)
        for (const StencilPoint& q : covered_images_[l]) {
            const double w = q.weight * uncovered_(q.i, q.j);
            sums[2 * l] += w * p(q.i, q.j);
            sums[2 * l + 1] += w;
        }
    if (grid_.size() > 1)
        MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
    for (std::size_t k = 0; k < covered_.size(); ++k) {
        const std::size_t l = first_covered_ + k;
        if (sums[2 * l + 1] > 0.0) p(covered_[k].i, covered_[k].j) = sums[2 * l] / sums[2 * l + 1];
    }
}

double SharpForcing::target(const ForcedFace& f, bool is_u, const Vec2& at) const {
    const Vec2 U = bodies_[f.body].velocity_at(at);
    return is_u ? U.x() : U.y();
}

std::vector<double> SharpForcing::reconstruction(const Component& c, bool is_u, const Field2D& field,
                                                 const Field2D& other, bool open) const {
    const std::vector<double> image = interpolate(grid_, c.images, field);
    if (profile_ == SharpProfile::wall_law) {
        // The velocity relative to the surface at the image point, split along the normal and the surface: the
        // tangential part follows the law of the wall down to the face, the normal part falls linearly to zero.
        const std::vector<double> crossing = interpolate(grid_, c.images_other, other);
        std::vector<double> values(c.forcing.size());
        for (std::size_t k = 0; k < c.forcing.size(); ++k) {
            const ForcedFace& f = c.forcing[k];
            const std::size_t l = c.first_image + k;
            const Vec2 Us = bodies_[f.body].velocity_at(f.surface);
            const Vec2 w = (is_u ? Vec2(image[l], crossing[l]) : Vec2(crossing[l], image[l])) - Us;
            const double wn = w.dot(f.normal);
            const Vec2 wt = w - wn * f.normal;
            const double speed = wt.norm();
            const double y = open ? f.open_phi : f.phi;
            const double ratio = speed > 0.0 ? wall_profile_(speed, f.image_distance, y) / speed : 0.0;
            const Vec2 u = Us + ratio * wt + (y / f.image_distance) * wn * f.normal;
            values[k] = is_u ? u.x() : u.y();
        }
        return values;
    }
    const std::vector<double> image2 =
        c.images2.empty() ? std::vector<double>(image.size(), 0.0) : interpolate(grid_, c.images2, field);
    std::vector<double> values(c.forcing.size());
    for (std::size_t k = 0; k < c.forcing.size(); ++k) {
        const ForcedFace& f = c.forcing[k];
        const double Us = target(f, is_u, f.surface);
        const std::size_t l = c.first_image + k;
        if (open) {
            values[k] = Us + f.open_weight * (image[l] - Us) + f.open_weight2 * (image2[l] - Us);
            continue;
        }
        // The face's own value u enters the image's: u = U_s + w (I' + s u - U_s) + ..., solved for u.
        const double others = image[l] - c.self[k] * field(f.i, f.j);
        values[k] = (Us + f.weight * (others - Us) + f.weight2 * (image2[l] - Us)) / (1.0 - f.weight * c.self[k]);
    }
    return values;
}

void SharpForcing::reconstruct(Component& c, bool is_u, Field2D& field, const Field2D& other, int sweeps) const {
    for (int s = 0; s < sweeps; ++s) {
        const std::vector<double> values = reconstruction(c, is_u, field, other);
        for (std::size_t k = 0; k < c.forcing.size(); ++k) field(c.forcing[k].i, c.forcing[k].j) = values[k];
    }
}

void SharpForcing::carry_open_flux(const Component& c, bool is_u, const std::vector<double>& predicted,
                                   const Field2D& forced, const std::vector<double>& profile, double dt) {
    Field2D& offset = is_u ? open_flux_.u : open_flux_.v;
    std::vector<OffsetFace>& faces = is_u ? offset_u_ : offset_v_;
    std::unordered_set<long long> was_cut;  // in the last step (the list is in the checkpoint)
    for (const OffsetFace& f : faces) was_cut.insert(face_key(f.i, f.j));
    std::vector<double> carried(c.forcing.size(), 0.0);
    for (std::size_t k = 0; k < c.forcing.size(); ++k) {
        const ForcedFace& f = c.forcing[k];
        if (!f.cut) continue;
        const Body& body = bodies_[f.body];
        const double to_profile = profile[k] - forced(f.i, f.j);
        if (!body.moves()) {
            carried[k] = to_profile;
            continue;
        }
        const Vec2 h = local_spacing(grid_, f.position);
        const Vec2 U = body.velocity_at(f.surface);
        if (!was_cut.contains(face_key(f.i, f.j))) {
            // Just cut: a face that a surface advancing along its normal covers carries on its own prediction as a
            // fluid face; one a receding surface uncovers (a ghost's prediction is no flow's), or one on the line of
            // a side that a corner slides past, starts from the profile. The tolerance keeps a side sliding along
            // its own line (U . n = 0 but for round-off) on one rule on both sides of a symmetric body.
            const bool own = U.dot(f.normal) > 1e-6 * U.norm();
            carried[k] = own ? predicted[k] - forced(f.i, f.j) : to_profile;
            continue;
        }
        // nu + nu_t at the face: the mean of its two cells' eddy viscosity (k-epsilon).
        const Field2D* eddy = viscous_.eddy ? &viscous_.eddy->cell : nullptr;
        const double nu_t =
            eddy ? 0.5 * ((*eddy)(f.i, f.j) + (is_u ? (*eddy)(f.i - 1, f.j) : (*eddy)(f.i, f.j - 1))) : 0.0;
        const double rate = (viscosity_ + nu_t) * (2.0 / (h.x() * h.x()) + 2.0 / (h.y() * h.y())) +
                            std::abs(U.x()) / h.x() + std::abs(U.y()) / h.y();
        carried[k] = (offset(f.i, f.j) + rate * dt * to_profile) / (1.0 + rate * dt);
    }
    for (const OffsetFace& f : faces) offset(f.i, f.j) = 0.0;
    faces.clear();
    for (std::size_t k = 0; k < c.forcing.size(); ++k) {
        const ForcedFace& f = c.forcing[k];
        if (!f.cut) continue;
        offset(f.i, f.j) = carried[k];
        faces.push_back({f.i, f.j});
    }
}

std::vector<double> SharpForcing::open_flux_state() const {
    // (component, global i, global j, offset) of every rank's cut ghost faces.
    std::vector<double> mine;
    for (int component = 0; component < 2; ++component)
        for (const OffsetFace& f : component == 0 ? offset_u_ : offset_v_)
            mine.insert(mine.end(), {static_cast<double>(component), static_cast<double>(f.i + grid_.lx().offset),
                                     static_cast<double>(f.j + grid_.ly().offset),
                                     (component == 0 ? open_flux_.u : open_flux_.v)(f.i, f.j)});
    std::size_t first = 0;
    return gathered(grid_, mine, first);
}

void SharpForcing::restore_open_flux(const std::vector<double>& state) {
    if (state.size() % 4 != 0) throw std::runtime_error("the checkpoint's open-flux state has a partial entry");
    for (const OffsetFace& f : offset_u_) open_flux_.u(f.i, f.j) = 0.0;
    for (const OffsetFace& f : offset_v_) open_flux_.v(f.i, f.j) = 0.0;
    offset_u_.clear();
    offset_v_.clear();
    const int nx = grid_.nx(), ny = grid_.ny();
    for (std::size_t k = 0; k < state.size(); k += 4) {
        const bool is_u = state[k] == 0.0;
        const int i = static_cast<int>(state[k + 1]) - grid_.lx().offset;
        const int j = static_cast<int>(state[k + 2]) - grid_.ly().offset;
        if (i < 0 || j < 0 || i >= nx || j >= ny) continue;  // another rank's (the forced faces are owned ones)
        (is_u ? open_flux_.u : open_flux_.v)(i, j) = state[k + 3];
        (is_u ? offset_u_ : offset_v_).push_back({i, j});
    }
}

bool SharpForcing::any_moves() const {
    return std::any_of(bodies_.begin(), bodies_.end(), [](const Body& b) { return b.moves(); });
}

bool SharpForcing::classified() const { return !placement_.stale(any_moves()); }

void SharpForcing::begin_step() {
    if (!classified()) classify();
}

void SharpForcing::apply(Velocity& star, double dt) {
    if (!classified()) classify();
    std::vector<double> sums(3 * bodies_.size(), 0.0);  // momentum rate x, y and torque rate per body
    auto account = [&](const ForcedFace& f, bool is_u, double change) {
        const double rate = change * f.volume / dt;
        const Vec2 m = is_u ? Vec2(rate, 0.0) : Vec2(0.0, rate);
        sums[3 * f.body] += m.x();
        sums[3 * f.body + 1] += m.y();
        sums[3 * f.body + 2] += cross(f.position - bodies_[f.body].state().centre, m);
    };
    if (cut_momentum_)
        apply_wall_stencils(star, dt, [&](const WallStencil& w, int body, double change) {
            const LocalAxis& X = grid_.lx();
            const LocalAxis& Y = grid_.ly();
            const Vec2 at = w.is_u ? Vec2(X.f(w.i), Y.c(w.j)) : Vec2(X.c(w.i), Y.f(w.j));
            const double volume = w.is_u ? X.dc(w.i) * Y.w(w.j) : X.w(w.i) * Y.dc(w.j);
            account(ForcedFace{w.i, w.j, body, volume, at, 0.0, at, Vec2(0.0, 0.0)}, w.is_u, change);
        });
    for (auto [c, is_u] : {std::pair{&u_, true}, std::pair{&v_, false}}) {
        Field2D& field = is_u ? star.u : star.v;
        for (const ForcedFace& f : c->solid) {
            const double value = target(f, is_u, f.position);
            account(f, is_u, value - field(f.i, f.j));
            field(f.i, f.j) = value;
        }
        std::vector<double> before(c->forcing.size());
        for (std::size_t k = 0; k < before.size(); ++k) before[k] = field(c->forcing[k].i, c->forcing[k].j);
        reconstruct(*c, is_u, field, is_u ? star.v : star.u, config_.sharp_sweeps);
        for (std::size_t k = 0; k < before.size(); ++k) {
            const ForcedFace& f = c->forcing[k];
            account(f, is_u, field(f.i, f.j) - before[k]);
        }
        if (ghost_)
            carry_open_flux(*c, is_u, before, field, reconstruction(*c, is_u, field, is_u ? star.v : star.u, true), dt);
    }
    if (grid_.size() > 1)
        MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        result_[b].momentum_rate = Vec2(sums[3 * b], sums[3 * b + 1]);
        result_[b].torque_rate = sums[3 * b + 2];
    }
}

void SharpForcing::measure_slip(const Velocity& vel) {
    if (!placed_) return;
    // Per body: the largest and the summed squared departure of the forced faces from what the forcing would set
    // them to now, and the count.
    std::vector<double> largest(bodies_.size(), 0.0), sums(2 * bodies_.size(), 0.0);
    auto record = [&](int b, double slip) {
        largest[b] = std::max(largest[b], std::abs(slip));
        sums[2 * b] += slip * slip;
        sums[2 * b + 1] += 1.0;
    };
    for (auto [c, is_u] : {std::pair{&u_, true}, std::pair{&v_, false}}) {
        const Field2D& field = is_u ? vel.u : vel.v;
        for (const ForcedFace& f : c->solid) record(f.body, field(f.i, f.j) - target(f, is_u, f.position));
        const std::vector<double> values = reconstruction(*c, is_u, field, is_u ? vel.v : vel.u);
        for (std::size_t k = 0; k < c->forcing.size(); ++k)
            record(c->forcing[k].body, field(c->forcing[k].i, c->forcing[k].j) - values[k]);
    }
    if (grid_.size() > 1) {
        MPI_Allreduce(MPI_IN_PLACE, largest.data(), static_cast<int>(largest.size()), MPI_DOUBLE, MPI_MAX,
                      grid_.comm());
        MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM, grid_.comm());
    }
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        result_[b].max_slip = largest[b];
        result_[b].rms_slip = sums[2 * b + 1] > 0.0 ? std::sqrt(sums[2 * b] / sums[2 * b + 1]) : 0.0;
    }
}

std::size_t SharpForcing::solid_faces() const { return u_.solid.size() + v_.solid.size(); }
std::size_t SharpForcing::forcing_faces() const { return u_.forcing.size() + v_.forcing.size(); }

}  // namespace chute
