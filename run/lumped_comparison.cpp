#include "lumped_comparison.hpp"

#include <cstdio>
#include <exception>
#include <string>

#include "hdf5_file.hpp"
#include "lumped_model.hpp"

namespace chute {

void write_lumped_comparison(const CaseConfig& config, const std::vector<Body>& bodies, const FreeBodies& free_bodies,
                             const std::filesystem::path& out_dir) {
    const Vec2 g(config.gravity[0], config.gravity[1]);
    const Vec2 across = g.norm() > 0.0 ? Vec2(perp(g).normalized()) : Vec2(Vec2::UnitX());
    for (const Body& body : bodies) {
        if (!body.free()) continue;
        const Vec2 d = rotated(across, -body.state().angle);  // body frame
        const double width = (body.outline().support_point(d) - body.outline().support_point(-d)).dot(d);
        LumpedModelConfig model;
        model.volume = body.area() * config.depth;
        model.mass = body.config().density * model.volume;
        model.frontal_area = width * config.depth;
        model.gravity = g;
        model.drag_coefficient = config.lumped.drag_coefficient;
        model.added_mass_coefficient = config.lumped.added_mass_coefficient;
        model.current = Vec2(config.initial_velocity[0], config.initial_velocity[1]);
        std::string text = "model,t,x,y,u,v\n";
        char row[256];
        for (int kind = 0; kind < 2; ++kind) {
            model.fluid_density = kind == 0 ? 0.0 : config.density;
            LumpedTrajectory run;
            try {
                run = run_lumped_model(model, body.outline(), body.state(), free_bodies.obstacles(), config.contact,
                                       config.end_time, config.end_time / 1000.0);
            } catch (const std::exception& e) {
                // A side output: the run goes on without it (CVODE refuses, for one, a time.end of 5e-324 s).
                std::fprintf(stderr, "chute: warning: lumped_%s.csv not written: %s\n", body.name().c_str(), e.what());
                text.clear();
                break;
            }
            for (const LumpedSample& s : run.samples) {
                std::snprintf(row, sizeof row, "%d,%.9g,%.9g,%.9g,%.9g,%.9g\n", kind, s.t, s.position.x(),
                              s.position.y(), s.velocity.x(), s.velocity.y());
                text += row;
            }
        }
        if (!text.empty()) write_text_atomically(out_dir / ("lumped_" + body.name() + ".csv"), text);
    }
}

}  // namespace chute
