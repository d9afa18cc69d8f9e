#include "line_motion.hpp"

namespace chute {

namespace {

// One component along the axis: `centred` (cells along the axis: u for y lines, v for x lines) or on the axis's
// lines. `at(f, along, across)` reads a field with the axis's index first.
template <class At>
void move_component(const Axis& old_axis, const Axis& new_axis, const LocalAxis& local, int n_across,
                    const std::vector<double>& counted, bool centred, const Field2D& face, Field2D& target,
                    const std::vector<Field2D*>& rescaled, At&& at) {
    const int cells = new_axis.cells();
    const bool periodic = new_axis.periodic();
    // The swept displacement of line k beyond what the fluxes counted (m); 0 beyond the lines' range.
    auto wrap = [&](int k) { return periodic ? ((k % cells) + cells) % cells : k; };
    auto swept = [&](int k) {
        if (!periodic && (k <= 0 || k >= cells)) return 0.0;
        const int g = wrap(k);
        return (new_axis.line(g) - old_axis.line(g)) - counted[g];
    };
    for (int k = 0; k < local.n; ++k) {
        const int g = local.offset + k;
        double before_extent, after_extent, low_swept, high_swept;
        double low_face, high_face;  // per across index: computed below
        if (centred) {
            // Cell g from line g to line g + 1; its faces are those lines.
            before_extent = old_axis.width(g);
            after_extent = new_axis.width(g);
            low_swept = swept(g);
            high_swept = swept(g + 1);
        } else {
            if (!periodic && (g == 0 || g == cells)) continue;  // a boundary face
            // From the centre of cell g - 1 to that of cell g; its faces are those centres, which move by the mean of
            // their lines.
            before_extent = old_axis.centre(g) - old_axis.centre(g - 1);
            after_extent = new_axis.centre(g) - new_axis.centre(g - 1);
            low_swept = 0.5 * (swept(g - 1) + swept(g));
            high_swept = 0.5 * (swept(g) + swept(g + 1));
        }
        const double scale = before_extent / after_extent;
        for (Field2D* r : rescaled)
            for (int m = 0; m < n_across; ++m) at(*r, k, m) *= scale;
        if (scale == 1.0 && low_swept == 0.0 && high_swept == 0.0) continue;
        // Linear weights of the face values: at line g between the centres of cells g - 1 and g, or at the centre
        // of cell g - 1 (g) between lines g - 1 and g (g and g + 1): the midpoint.
        const double low_weight =
            centred ? (old_axis.line(g) - old_axis.centre(g - 1)) / (old_axis.centre(g) - old_axis.centre(g - 1)) : 0.5;
        const double high_weight =
            centred ? (old_axis.line(g + 1) - old_axis.centre(g)) / (old_axis.centre(g + 1) - old_axis.centre(g)) : 0.5;
        for (int m = 0; m < n_across; ++m) {
            low_face = at(face, k - 1, m) + low_weight * (at(face, k, m) - at(face, k - 1, m));
            high_face = at(face, k, m) + high_weight * (at(face, k + 1, m) - at(face, k, m));
            double& value = at(target, k, m);
            value = (before_extent * value - low_face * low_swept + high_face * high_swept) / after_extent;
        }
    }
}

}  // namespace

void move_momentum_with_lines(const Grid& grid, int axis, const std::vector<double>& before,
                              const std::vector<double>& counted, const Velocity& face, Velocity& target,
                              const std::vector<Velocity*>& rescaled) {
    const Axis& now = axis == 0 ? grid.x_axis() : grid.y_axis();
    const Axis old_axis(before, now.periodic());
    const LocalAxis& local = axis == 0 ? grid.lx() : grid.ly();
    const int n_across = axis == 0 ? grid.ny() : grid.nx();
    auto at = [axis](auto& f, int along, int across) -> decltype(auto) {
        if (axis == 0) return f(along, across);
        return f(across, along);
    };
    std::vector<Field2D*> ru, rv;
    for (Velocity* r : rescaled) {
        ru.push_back(&r->u);
        rv.push_back(&r->v);
    }
    // u is on the x lines and centred along y; v the other way round.
    move_component(old_axis, now, local, n_across, counted, axis == 1, face.u, target.u, ru, at);
    move_component(old_axis, now, local, n_across, counted, axis == 0, face.v, target.v, rv, at);
}

}  // namespace chute
