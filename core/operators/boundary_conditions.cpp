#include "boundary_conditions.hpp"

#include <mpi.h>

#include <cmath>

namespace chute {

namespace {
bool is_x_side(Side s) { return s == Side::left || s == Side::right; }
// Sign of the outward normal along its axis: -1 on left/bottom, +1 on right/top.
double outward_sign(Side s) { return (s == Side::left || s == Side::bottom) ? -1.0 : 1.0; }

// Mean over [s0, s1] of the parabola 4 U (s - a)(b - s) / (b - a)^2.
double parabola_mean(double U, double a, double b, double s0, double s1) {
    const double L2 = (b - a) * (b - a);
    auto F = [&](double s) { return 4.0 * U / L2 * (0.5 * (a + b) * s * s - s * s * s / 3.0 - a * b * s); };
    return (F(s1) - F(s0)) / (s1 - s0);
}
}  // namespace

BoundaryConditions::BoundaryConditions(const Grid& grid, const std::array<BoundaryConfig, 4>& config)
    : grid_(grid), config_(config) {
    for (Side s : kSides) {
        const auto& c = config_[static_cast<int>(s)];
        dirichlet_[static_cast<int>(s)] = c.type == BoundaryType::outflow && c.outflow == OutflowKind::zero_stress;
    }
    u_first_ = (grid_.touches(Side::left) && !grid_.x_axis().periodic()) ? 1 : 0;
    v_first_ = (grid_.touches(Side::bottom) && !grid_.y_axis().periodic()) ? 1 : 0;
}

bool BoundaryConditions::pure_neumann() const {
    for (bool d : dirichlet_)
        if (d) return false;
    return true;
}

double BoundaryConditions::inflow_normal(Side s, int k) const {
    const auto& c = config_[static_cast<int>(s)];
    if (c.profile == InflowProfile::uniform) return is_x_side(s) ? c.velocity[0] : c.velocity[1];
    // Parabolic profile across the side, given as the speed into the domain.
    const Axis& along = is_x_side(s) ? grid_.y_axis() : grid_.x_axis();
    const int g = k + (is_x_side(s) ? grid_.ly().offset : grid_.lx().offset);
    const double into = parabola_mean(c.peak, along.start(), along.end(), along.line(g), along.line(g + 1));
    return -outward_sign(s) * into;
}

// Boundary-face normal velocity on wall, slip and inflow sides (outflow faces are left as they are).
void BoundaryConditions::apply_normal(Velocity& vel) const {
    const int nx = grid_.nx(), ny = grid_.ny();
    for (Side s : kSides) {
        const auto& c = config_[static_cast<int>(s)];
        if (!grid_.touches(s) || c.type == BoundaryType::periodic || c.type == BoundaryType::outflow) continue;
        const bool x_side = is_x_side(s);
        Field2D& f = x_side ? vel.u : vel.v;
        const int face = (s == Side::left || s == Side::bottom) ? 0 : (x_side ? nx : ny);
        const int n_along = x_side ? ny : nx;
        for (int k = -kGhost; k < n_along + kGhost; ++k) {
            double value = 0.0;
            if (c.type == BoundaryType::wall) value = x_side ? c.velocity[0] : c.velocity[1];
            if (c.type == BoundaryType::inflow) value = inflow_normal(s, k);
            (x_side ? f(face, k) : f(k, face)) = value;
        }
    }
}

// Ghost columns beyond the left and right sides (all rows, so corners see current values).
void BoundaryConditions::apply_ghosts_x(Velocity& vel) const {
    const int nx = grid_.nx(), ny = grid_.ny();
    for (Side s : {Side::left, Side::right}) {
        const auto& c = config_[static_cast<int>(s)];
        if (!grid_.touches(s) || c.type == BoundaryType::periodic) continue;
        const bool low = s == Side::left;
        const double ut = c.type == BoundaryType::wall || c.type == BoundaryType::inflow ? c.velocity[1] : 0.0;
        const bool dirichlet_t = c.type == BoundaryType::wall || c.type == BoundaryType::inflow;
        const bool outflow = c.type == BoundaryType::outflow;
        for (int j = -kGhost; j < ny + kGhost; ++j)
            for (int g = 1; g <= kGhost; ++g) {
                // Normal component: faces beyond the boundary face b.
                // (on the high side the boundary face already sits in the first ghost slot).
                const int b = low ? 0 : nx;
                const int out = low ? b - g : b + g, in = low ? b + g : b - g;
                if (low || g < kGhost) vel.u(out, j) = outflow ? vel.u(b, j) : 2.0 * vel.u(b, j) - vel.u(in, j);
                // Tangential component: ghost cell g mirrors interior cell g-1 about the boundary.
                const int gc = low ? -g : nx - 1 + g, ic = low ? g - 1 : nx - g;
                vel.v(gc, j) = dirichlet_t ? 2.0 * ut - vel.v(ic, j) : vel.v(ic, j);
            }
    }
}

void BoundaryConditions::apply_ghosts_y(Velocity& vel) const {
    const int nx = grid_.nx(), ny = grid_.ny();
    for (Side s : {Side::bottom, Side::top}) {
        const auto& c = config_[static_cast<int>(s)];
        if (!grid_.touches(s) || c.type == BoundaryType::periodic) continue;
        const bool low = s == Side::bottom;
        const double ut = c.type == BoundaryType::wall || c.type == BoundaryType::inflow ? c.velocity[0] : 0.0;
        const bool dirichlet_t = c.type == BoundaryType::wall || c.type == BoundaryType::inflow;
        const bool outflow = c.type == BoundaryType::outflow;
        for (int g = 1; g <= kGhost; ++g)
            for (int i = -kGhost; i < nx + kGhost; ++i) {
                const int b = low ? 0 : ny;
                const int out = low ? b - g : b + g, in = low ? b + g : b - g;
                if (low || g < kGhost) vel.v(i, out) = outflow ? vel.v(i, b) : 2.0 * vel.v(i, b) - vel.v(i, in);
                const int gc = low ? -g : ny - 1 + g, ic = low ? g - 1 : ny - g;
                vel.u(i, gc) = dirichlet_t ? 2.0 * ut - vel.u(i, ic) : vel.u(i, ic);
            }
    }
}

void BoundaryConditions::apply(Velocity& vel) const {
    apply_normal(vel);
    apply_ghosts_x(vel);
    apply_ghosts_y(vel);
}

void BoundaryConditions::set_outflow(const Velocity& old, Velocity& next, double dt) const {
    apply_normal(next);
    const int nx = grid_.nx(), ny = grid_.ny();
    const auto& lx = grid_.lx();
    const auto& ly = grid_.ly();

    // Mean outward speed on each side (global), the convection speed of the convective condition.
    std::array<double, 8> sums{};  // flux and length per side
    for (Side s : kSides) {
        const auto& c = config_[static_cast<int>(s)];
        if (!grid_.touches(s) || c.type != BoundaryType::outflow) continue;
        const int k = static_cast<int>(s);
        const double sign = outward_sign(s);
        if (is_x_side(s)) {
            const int b = s == Side::left ? 0 : nx;
            for (int j = 0; j < ny; ++j) {
                sums[2 * k] += sign * old.u(b, j) * ly.w(j);
                sums[2 * k + 1] += ly.w(j);
            }
        } else {
            const int b = s == Side::bottom ? 0 : ny;
            for (int i = 0; i < nx; ++i) {
                sums[2 * k] += sign * old.v(i, b) * lx.w(i);
                sums[2 * k + 1] += lx.w(i);
            }
        }
    }
    MPI_Allreduce(MPI_IN_PLACE, sums.data(), 8, MPI_DOUBLE, MPI_SUM, grid_.comm());

    double convective_length = 0.0;
    for (Side s : kSides) {
        const auto& c = config_[static_cast<int>(s)];
        if (c.type != BoundaryType::outflow) continue;
        const int k = static_cast<int>(s);
        if (c.outflow == OutflowKind::convective) convective_length += sums[2 * k + 1];
        if (!grid_.touches(s)) continue;
        const double Uc = std::max(0.0, sums[2 * k] / sums[2 * k + 1] - outward_sign(s) * frame_[is_x_side(s) ? 0 : 1]);
        const bool convective = c.outflow == OutflowKind::convective;
        switch (s) {
            case Side::right:
                for (int j = -kGhost; j < ny + kGhost; ++j)
                    next.u(nx, j) = convective
                                        ? old.u(nx, j) - dt * Uc * (old.u(nx, j) - old.u(nx - 1, j)) / lx.w(nx - 1)
                                        : next.u(nx - 1, j);
                break;
            case Side::left:
                for (int j = -kGhost; j < ny + kGhost; ++j)
                    next.u(0, j) =
                        convective ? old.u(0, j) + dt * Uc * (old.u(1, j) - old.u(0, j)) / lx.w(0) : next.u(1, j);
                break;
            case Side::top:
                for (int i = -kGhost; i < nx + kGhost; ++i)
                    next.v(i, ny) = convective
                                        ? old.v(i, ny) - dt * Uc * (old.v(i, ny) - old.v(i, ny - 1)) / ly.w(ny - 1)
                                        : next.v(i, ny - 1);
                break;
            case Side::bottom:
                for (int i = -kGhost; i < nx + kGhost; ++i)
                    next.v(i, 0) =
                        convective ? old.v(i, 0) + dt * Uc * (old.v(i, 1) - old.v(i, 0)) / ly.w(0) : next.v(i, 1);
                break;
        }
    }

    // With Neumann pressure everywhere the projection is solvable only if no net volume leaves the domain:
    // spread the imbalance uniformly over the convective outflow faces.
    if (!pure_neumann() || convective_length == 0.0) return;
    const double shift = net_outflux(next) / convective_length;
    for (Side s : kSides) {
        const auto& c = config_[static_cast<int>(s)];
        if (!grid_.touches(s) || c.type != BoundaryType::outflow || c.outflow != OutflowKind::convective) continue;
        const double sign = outward_sign(s);
        if (is_x_side(s)) {
            const int b = s == Side::left ? 0 : nx;
            for (int j = -kGhost; j < ny + kGhost; ++j) next.u(b, j) -= sign * shift;
        } else {
            const int b = s == Side::bottom ? 0 : ny;
            for (int i = -kGhost; i < nx + kGhost; ++i) next.v(i, b) -= sign * shift;
        }
    }
}

double BoundaryConditions::net_outflux(const Velocity& vel) const {
    const int nx = grid_.nx(), ny = grid_.ny();
    double flux = 0.0;
    for (Side s : kSides) {
        if (!grid_.touches(s) || config_[static_cast<int>(s)].type == BoundaryType::periodic) continue;
        const double sign = outward_sign(s);
        if (is_x_side(s)) {
            const int b = s == Side::left ? 0 : nx;
            for (int j = 0; j < ny; ++j) flux += sign * vel.u(b, j) * grid_.ly().w(j);
        } else {
            const int b = s == Side::bottom ? 0 : ny;
            for (int i = 0; i < nx; ++i) flux += sign * vel.v(i, b) * grid_.lx().w(i);
        }
    }
    MPI_Allreduce(MPI_IN_PLACE, &flux, 1, MPI_DOUBLE, MPI_SUM, grid_.comm());
    return flux;
}

void BoundaryConditions::apply_pressure(Field2D& p) const {
    const int nx = grid_.nx(), ny = grid_.ny();
    for (Side s : {Side::left, Side::right}) {
        if (!grid_.touches(s) || config_[static_cast<int>(s)].type == BoundaryType::periodic) continue;
        const double sign = pressure_dirichlet(s) ? -1.0 : 1.0;
        const bool low = s == Side::left;
        for (int j = -kGhost; j < ny + kGhost; ++j)
            for (int g = 1; g <= kGhost; ++g) p(low ? -g : nx - 1 + g, j) = sign * p(low ? g - 1 : nx - g, j);
    }
    for (Side s : {Side::bottom, Side::top}) {
        if (!grid_.touches(s) || config_[static_cast<int>(s)].type == BoundaryType::periodic) continue;
        const double sign = pressure_dirichlet(s) ? -1.0 : 1.0;
        const bool low = s == Side::bottom;
        for (int g = 1; g <= kGhost; ++g)
            for (int i = -kGhost; i < nx + kGhost; ++i) p(i, low ? -g : ny - 1 + g) = sign * p(i, low ? g - 1 : ny - g);
    }
}

}  // namespace chute
