#include "implicit_diffusion.hpp"

#include <mpi.h>

#include <algorithm>

namespace chute {

namespace {
// How the correction du behaves in the ghost row beyond a side, for the component tangential to it:
// -1 odd (wall, inflow: u_t prescribed), +1 even (slip, outflow: du_t/dn = 0), 0 periodic or a neighbour patch.
int ghost_mirror(const Grid& grid, const BoundaryConditions& bc, Side s) {
    if (!grid.touches(s)) return 0;
    const BoundaryType type = bc.config(s).type;
    if (type == BoundaryType::periodic) return 0;
    return (type == BoundaryType::wall || type == BoundaryType::inflow) ? -1 : +1;
}
}  // namespace

double implicit_rate_u(const Grid& grid, double nu, const EddyViscosity& eddy, const Velocity& vel, int i, int j) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    const Field2D& u = vel.u;
    const double aw = 2.0 * (nu + eddy.cell(i - 1, j)) * Y.w(j) / X.w(i - 1);
    const double ae = 2.0 * (nu + eddy.cell(i, j)) * Y.w(j) / X.w(i);
    const double as = (nu + eddy.corner(i, j)) * X.dc(i) / Y.dc(j);
    const double an = (nu + eddy.corner(i, j + 1)) * X.dc(i) / Y.dc(j + 1);
    const double c = u(i, j);
    return (ae * (u(i + 1, j) - c) - aw * (c - u(i - 1, j)) + an * (u(i, j + 1) - c) - as * (c - u(i, j - 1))) /
           (X.dc(i) * Y.w(j));
}

double implicit_rate_v(const Grid& grid, double nu, const EddyViscosity& eddy, const Velocity& vel, int i, int j) {
    const auto& X = grid.lx();
    const auto& Y = grid.ly();
    const Field2D& v = vel.v;
    const double as = 2.0 * (nu + eddy.cell(i, j - 1)) * X.w(i) / Y.w(j - 1);
    const double an = 2.0 * (nu + eddy.cell(i, j)) * X.w(i) / Y.w(j);
    const double aw = (nu + eddy.corner(i, j)) * Y.dc(j) / X.dc(i);
    const double ae = (nu + eddy.corner(i + 1, j)) * Y.dc(j) / X.dc(i + 1);
    const double c = v(i, j);
    return (an * (v(i, j + 1) - c) - as * (c - v(i, j - 1)) + ae * (v(i + 1, j) - c) - aw * (c - v(i - 1, j))) /
           (X.w(i) * Y.dc(j));
}

ImplicitDiffusion::ImplicitDiffusion(const Grid& grid, const BoundaryConditions& bc, double tolerance)
    : grid_(grid), bc_(bc), tolerance_(tolerance) {
    int offsets[5][2] = {{0, 0}, {-1, 0}, {1, 0}, {0, -1}, {0, 1}};  // centre, west, east, south, north
    HYPRE_StructStencilCreate(2, 5, &stencil_);
    for (int e = 0; e < 5; ++e) HYPRE_StructStencilSetElement(stencil_, e, offsets[e]);
    create(u_, true);
    create(v_, false);
}

ImplicitDiffusion::~ImplicitDiffusion() {
    destroy(u_);
    destroy(v_);
    HYPRE_StructStencilDestroy(stencil_);
}

// The unknowns of one component are its owned faces minus boundary faces: u faces [u_first, nx) x [0, ny),
// v faces [0, nx) x [v_first, ny). In a periodic direction every face is an unknown.
void ImplicitDiffusion::create(Component& c, bool is_u) {
    const int ox = grid_.lx().offset, oy = grid_.ly().offset;
    c.first = is_u ? bc_.u_first() : bc_.v_first();
    c.lower = {ox + (is_u ? c.first : 0), oy + (is_u ? 0 : c.first)};
    c.upper = {ox + grid_.nx() - 1, oy + grid_.ny() - 1};
    c.cells = (c.upper[0] - c.lower[0] + 1) * (c.upper[1] - c.lower[1] + 1);
    MPI_Comm comm = grid_.comm();
    HYPRE_StructGridCreate(comm, 2, &c.grid);
    HYPRE_StructGridSetExtents(c.grid, c.lower.data(), c.upper.data());
    int periodic[2] = {grid_.x_axis().periodic() ? grid_.global_nx() : 0,
                       grid_.y_axis().periodic() ? grid_.global_ny() : 0};
    HYPRE_StructGridSetPeriodic(c.grid, periodic);
    HYPRE_StructGridAssemble(c.grid);
    HYPRE_StructMatrixCreate(comm, c.grid, stencil_, &c.matrix);
    HYPRE_StructMatrixSetSymmetric(c.matrix, 1);
    HYPRE_StructMatrixInitialize(c.matrix);
    HYPRE_StructVectorCreate(comm, c.grid, &c.b);
    HYPRE_StructVectorCreate(comm, c.grid, &c.x);
    HYPRE_StructVectorInitialize(c.b);
    HYPRE_StructVectorInitialize(c.x);
    HYPRE_StructPCGCreate(comm, &c.pcg);
    HYPRE_StructPCGSetTol(c.pcg, tolerance_);
    HYPRE_StructPCGSetMaxIter(c.pcg, kMaxIterations);
    HYPRE_StructPCGSetTwoNorm(c.pcg, 1);
    // Jacobi (diagonal) preconditioning: one PFMG V-cycle took as many PCG iterations (6.2 against 5.5 on the
    // free-fall case) and its set-up, redone every step as the values change, doubled the step's cost.
    HYPRE_StructPCGSetPrecond(c.pcg, HYPRE_StructDiagScale, HYPRE_StructDiagScaleSetup, nullptr);
    c.values.resize(5 * static_cast<std::size_t>(c.cells));
    c.rhs.resize(c.cells);
    c.solution.resize(c.cells);
}

void ImplicitDiffusion::destroy(Component& c) {
    if (c.pcg) HYPRE_StructPCGDestroy(c.pcg);
    if (c.b) HYPRE_StructVectorDestroy(c.b);
    if (c.x) HYPRE_StructVectorDestroy(c.x);
    if (c.matrix) HYPRE_StructMatrixDestroy(c.matrix);
    if (c.grid) HYPRE_StructGridDestroy(c.grid);
}

int ImplicitDiffusion::apply(double nu, const EddyViscosity& eddy, double dt, Velocity& vel) {
    return std::max(solve<true>(u_, nu, eddy, dt, vel), solve<false>(v_, nu, eddy, dt, vel));
}

void ImplicitDiffusion::set_solid_cells(const SolidCells* solid) {
    solid_ = solid && !solid->empty() ? solid : nullptr;
    u_.holes_mapped = v_.holes_mapped = false;
}

// The rows along the holes, from the fill's own description of each hole face (SolidCells::hole_face).
template <bool is_u>
void ImplicitDiffusion::map_holes(Component& c) {
    c.holes_mapped = true;
    c.hole.assign(solid_ ? c.cells : 0, 0);
    c.neighbour.assign(solid_ ? c.cells : 0, {-1.0, -1.0, -1.0, -1.0});
    if (!solid_) return;
    const int component = is_u ? 0 : 1;
    // The hole face at (a, b) (global indices along and across the component), if any.
    auto face_at = [&](int a, int b) {
        const int gi = is_u ? a : b, gj = is_u ? b : a;
        for (const SolidBlock& block : solid_->blocks()) {
            const SolidCells::HoleFace f = solid_->hole_face(block, component, gi, gj);
            if (f.kind != SolidCells::HoleFace::Kind::outside) return f;
        }
        return SolidCells::HoleFace{};
    };
    const int a0 = is_u ? c.lower[0] : c.lower[1], a1 = is_u ? c.upper[0] : c.upper[1];
    const int b0 = is_u ? c.lower[1] : c.lower[0], b1 = is_u ? c.upper[1] : c.upper[0];
    const int count_a = a1 - a0 + 1, count_b = b1 - b0 + 1;
    using Kind = SolidCells::HoleFace::Kind;
    for (int b = b0; b <= b1; ++b)
        for (int a = a0; a <= a1; ++a) {
            const std::size_t k = is_u ? static_cast<std::size_t>(b - b0) * count_a + (a - a0)
                                       : static_cast<std::size_t>(a - a0) * count_b + (b - b0);
            if (face_at(a, b).kind != Kind::outside) {
                c.hole[k] = 1;
                continue;
            }
            const std::array<int, 2> self = is_u ? std::array<int, 2>{a, b} : std::array<int, 2>{b, a};
            const std::array<std::array<int, 2>, 4> around = {{{a - 1, b}, {a + 1, b}, {a, b - 1}, {a, b + 1}}};
            for (int n = 0; n < 4; ++n) {
                const SolidCells::HoleFace f = face_at(around[n][0], around[n][1]);
                if (f.kind == Kind::outside) continue;
                double factor = 0.0;
                if (f.mirror == self && f.kind == Kind::odd_mirror) factor = 1.0;
                if (f.mirror == self && f.kind == Kind::scaled_mirror) factor = f.inner / f.outer;
                c.neighbour[k][n] = factor;
            }
        }
}

// One component, written for u; v is the same with x and y exchanged (the lambdas below swap them).
template <bool is_u>
int ImplicitDiffusion::solve(Component& c, double nu, const EddyViscosity& eddy, double dt, Velocity& vel) {
    const LocalAxis& A = is_u ? grid_.lx() : grid_.ly();  // along the component
    const LocalAxis& B = is_u ? grid_.ly() : grid_.lx();  // across it
    const int na = is_u ? grid_.nx() : grid_.ny(), nb = is_u ? grid_.ny() : grid_.nx();
    Field2D& f = is_u ? vel.u : vel.v;
    // (a, b): index along and across the component; field, cell and corner arrays are (i, j).
    auto at = [&](Field2D& g, int a, int b) -> double& {
        if constexpr (is_u)
            return g(a, b);
        else
            return g(b, a);
    };
    auto cell = [&](int a, int b) { return nu + (is_u ? eddy.cell(a, b) : eddy.cell(b, a)); };
    auto corner = [&](int a, int b) { return nu + (is_u ? eddy.corner(a, b) : eddy.corner(b, a)); };
    const Side low_a = is_u ? Side::left : Side::bottom, high_a = is_u ? Side::right : Side::top;
    const Side low_b = is_u ? Side::bottom : Side::left, high_b = is_u ? Side::top : Side::right;
    const bool periodic_a = is_u ? grid_.x_axis().periodic() : grid_.y_axis().periodic();
    // Boundary faces along the component are not unknowns: du = 0 there.
    const bool wall_low_a = grid_.touches(low_a) && !periodic_a;
    const bool wall_high_a = grid_.touches(high_a) && !periodic_a;
    const int mirror_low_b = ghost_mirror(grid_, bc_, low_b), mirror_high_b = ghost_mirror(grid_, bc_, high_b);

    // Position of face (a, b) in hypre's box order, x fastest: along the component for u, across it for v.
    const int count_a = na - c.first;
    auto box_index = [&](int a, int b) {
        return is_u ? static_cast<std::size_t>(b) * count_a + (a - c.first)
                    : static_cast<std::size_t>(a - c.first) * nb + b;
    };
    if (!c.holes_mapped) map_holes<is_u>(c);
    for (int b = 0; b < nb; ++b)
        for (int a = c.first; a < na; ++a) {
            const std::size_t k = box_index(a, b);
            const double volume = A.dc(a) * B.w(b);
            if (!c.hole.empty() && c.hole[k]) {  // a hole's face: du = 0
                double* v = &c.values[5 * k];
                v[0] = volume;
                v[1] = v[2] = v[3] = v[4] = 0.0;
                c.rhs[k] = 0.0;
                c.solution[k] = 0.0;
                continue;
            }
            // Coefficients dt * flux area * nu_e / distance of the four neighbours.
            const double aw = dt * 2.0 * cell(a - 1, b) * B.w(b) / A.w(a - 1);
            const double ae = dt * 2.0 * cell(a, b) * B.w(b) / A.w(a);
            const double as = dt * corner(a, b) * A.dc(a) / B.dc(b);
            const double an = dt * corner(a, b + 1) * A.dc(a) / B.dc(b + 1);
            // Right-hand side dt * V * L(u_E).
            const double ua = at(f, a, b);
            const double flux = ae * (at(f, a + 1, b) - ua) - aw * (ua - at(f, a - 1, b)) +
                                an * (at(f, a, b + 1) - ua) - as * (ua - at(f, a, b - 1));
            c.rhs[k] = flux;
            // Matrix V + dt K with the homogeneous conditions folded in.
            double diag = volume + aw + ae + as + an;
            double w = -aw, e = -ae, s = -as, n = -an;
            if (wall_low_a && a == 1) w = 0.0;
            if (wall_high_a && a == na - 1) e = 0.0;
            if (mirror_low_b != 0 && b == 0) {
                diag -= mirror_low_b * as;  // du_ghost = mirror * du: -as (mirror du - du)
                s = 0.0;
            }
            if (mirror_high_b != 0 && b == nb - 1) {
                diag -= mirror_high_b * an;
                n = 0.0;
            }
            if (!c.neighbour.empty()) {
                const std::array<double, 4>& h = c.neighbour[k];
                double* coupling[4] = {&w, &e, &s, &n};
                const double coefficient[4] = {aw, ae, as, an};
                for (int q = 0; q < 4; ++q)
                    if (h[q] >= 0.0) {
                        diag += h[q] * coefficient[q];
                        *coupling[q] = 0.0;
                    }
            }
            double* v = &c.values[5 * k];
            v[0] = diag;
            if constexpr (is_u) {  // stencil order: west, east, south, north in (x, y)
                v[1] = w, v[2] = e, v[3] = s, v[4] = n;
            } else {  // for v, "along" is y: south/north are a-1/a+1, west/east are b-1/b+1
                v[1] = s, v[2] = n, v[3] = w, v[4] = e;
            }
            c.solution[k] = 0.0;
        }
    int entries[5] = {0, 1, 2, 3, 4};
    HYPRE_StructMatrixSetBoxValues(c.matrix, c.lower.data(), c.upper.data(), 5, entries, c.values.data());
    HYPRE_StructMatrixAssemble(c.matrix);
    HYPRE_StructVectorSetBoxValues(c.b, c.lower.data(), c.upper.data(), c.rhs.data());
    HYPRE_StructVectorSetBoxValues(c.x, c.lower.data(), c.upper.data(), c.solution.data());
    HYPRE_StructVectorAssemble(c.b);
    HYPRE_StructVectorAssemble(c.x);
    // The values change every step, the structure does not: PCG's set-up (work vectors, matrix-vector
    // plan) is done once, and Jacobi needs none of its own.
    if (!c.set_up) HYPRE_StructPCGSetup(c.pcg, c.matrix, c.b, c.x);
    c.set_up = true;
    HYPRE_StructPCGSolve(c.pcg, c.matrix, c.b, c.x);
    int iterations = 0;
    HYPRE_StructPCGGetNumIterations(c.pcg, &iterations);
    HYPRE_ClearAllErrors();
    HYPRE_StructVectorGetBoxValues(c.x, c.lower.data(), c.upper.data(), c.solution.data());
    // Add du (hypre order: x fastest).
    std::size_t q = 0;
    const int ox0 = c.lower[0] - grid_.lx().offset, oy0 = c.lower[1] - grid_.ly().offset;
    for (int j = oy0; j < grid_.ny(); ++j)
        for (int i = ox0; i < grid_.nx(); ++i) f(i, j) += c.solution[q++];
    return iterations;
}

}  // namespace chute
