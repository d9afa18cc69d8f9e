#include "immersed_boundary.hpp"

#include <mpi.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include "direct_forcing.hpp"
#include "sharp_forcing.hpp"

namespace chute {

namespace {

// Two arrays the same bit for bit.
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// The sharp interface's profile (numerics.ibm.sharp_profile). Automatic: quadratic in laminar runs; with a
// wall-function model the law of the wall on forcing faces, and on ghost faces the mirror (the law of the wall has no
// value inside; the wall law then acts through the eddy viscosity beside the surface, ImmersedWall).
SharpProfile sharp_profile(const ImmersedBoundarySettings& settings) {
    using P = IbmConfig::SharpProfileChoice;
    switch (settings.ibm.sharp_profile) {
        case P::linear:
            return SharpProfile::linear;
        case P::quadratic:
            return SharpProfile::quadratic;
        case P::wall_law:
            if (!settings.wall_profile)
                throw std::invalid_argument(
                    "numerics.ibm.sharp_profile: wall_law needs a turbulence model with wall functions "
                    "(turbulence.model: k_epsilon)");
            return SharpProfile::wall_law;
        case P::mirror:
            if (settings.ibm.sharp_faces != IbmConfig::SharpFaces::ghost)
                throw std::invalid_argument(
                    "numerics.ibm.sharp_profile: mirror sets the faces inside the body from their mirror images; it "
                    "needs numerics.ibm.sharp_faces: ghost");
            return SharpProfile::mirror;
        case P::automatic:
            break;
    }
    if (!settings.wall_profile) return SharpProfile::quadratic;
    return settings.ibm.sharp_faces == IbmConfig::SharpFaces::ghost ? SharpProfile::mirror : SharpProfile::wall_law;
}

}  // namespace

ImmersedBoundary::ImmersedBoundary(const Grid& grid, const ImmersedBoundarySettings& settings,
                                   std::vector<Body>& bodies)
    : grid_(grid),
      settings_(settings),
      bodies_(bodies),
      diffused_(grid),
      walls_(grid, bodies, settings.image_distance,
             settings.ibm.interface == Interface::sharp && settings.ibm.sharp_faces == IbmConfig::SharpFaces::ghost
                 ? NearWall::surface
                 : NearWall::band),
      start_momentum_(bodies.size()),
      start_centre_(bodies.size(), Vec2::Zero()),
      step_forcing_(bodies.size()),
      wrench_(bodies.size()),
      coupling_(bodies.size()),
      kept_response_(bodies.size()) {
    if (walls_.near_wall() == NearWall::surface) cut_ = std::make_unique<CutFaces>(grid, bodies_);
    if (settings.ibm.interface == Interface::sharp) {
        auto sharp = std::make_unique<SharpForcing>(grid, settings.ibm, bodies_, settings.image_distance,
                                                    sharp_profile(settings), settings.viscosity, settings.wall_profile);
        sharp_ = sharp.get();
        forcing_ = std::move(sharp);
    } else
        forcing_ = std::make_unique<DirectForcing>(grid, settings.ibm, bodies_);
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        stress_.push_back(std::make_unique<SurfaceStress>(grid, settings.ibm, bodies_[b], forcing_->marker_spacing(b)));
}

void ImmersedBoundary::begin_step(const Velocity& start) {
    for (BodyForcing& f : step_forcing_) f = BodyForcing{};
    forcing_->begin_step();
    // The first step (and the first after a restart): the pressure problem is cut before the flow predicts, so that
    // the step's Poisson starting guess is hypre's, as in every later step (the direct solve takes none).
    if (cut_ && flow_ && !pressure_boundary_set_) {
        cut_->update();
        set_pressure_boundary();
    }
    if (sharp_ && flow_ && !bodies_.empty()) {
        sharp_->extend_pressure(flow_->pressure());
        flow_->refresh_ghosts();
    }
    // The momentum the bodies' regions hold at the start of the step: ghost faces, every body's (SharpForcing::
    // held_momentum, the forcing placed where the bodies are now); otherwise each free body's, over the faces inside.
    for (std::size_t b = 0; b < bodies_.size(); ++b) start_centre_[b] = bodies_[b].state().centre;
    if (cut_)
        start_momentum_ = sharp_->held_momentum(start);
    else
        for (std::size_t b = 0; b < bodies_.size(); ++b)
            if (bodies_[b].free()) start_momentum_[b] = enclosed_momentum(grid_, start, bodies_[b]);
}

void ImmersedBoundary::attach(FlowSolver& flow) {
    flow_ = &flow;
    // Ghost faces hold mirrored values: the convective flux beside them is the wall's (core/operators/convection.hpp).
    if (cut_) flow_->set_wall_faces(&sharp_->wall_faces());
}

void ImmersedBoundary::impose(Velocity& predicted, double dt) {
    if (bodies_.empty()) return;
    if (sharp_ && flow_) {
        // The viscous operator the flow solver applied to u* (cut momentum replaces it beside the surface): with
        // implicit diffusion to u* itself, as the solve left it; explicit, to u^n.
        const bool implicit = flow_->implicit_diffusion();
        if (sharp_->cut_momentum() && implicit) diffused_ = predicted;
        sharp_->set_viscous_operator({flow_->turbulent() ? &std::as_const(*flow_).eddy_viscosity() : nullptr,
                                      flow_->turbulent() || implicit,
                                      implicit ? &diffused_ : &std::as_const(*flow_).velocity()});
        sharp_->set_wall_turbulence(wall_turbulence_ ? &*wall_turbulence_ : nullptr);
    }
    forcing_->apply(predicted, dt);
    // Ghost faces: the pressure problem follows the surfaces where they are now, through the open fraction of each
    // face (ibm/cut_faces.hpp). With a moving body its matrix and multigrid hierarchy are rebuilt every step: PCG then
    // takes 6 iterations where a hierarchy kept from an earlier step took 14-26 (the moving square: 9.3 s against
    // 10.6 s for 100 steps), and a restart repeats the straight run bit for bit. Not when what the matrix is made of
    // is the same bit for bit (a body keeping its place on a grid that translates with it): the same matrix.
    if (cut_ && flow_ && (cut_->update() || !pressure_boundary_set_)) {
        std::vector<double> inputs = pressure_inputs();
        if (!pressure_boundary_set_ || !on_every_rank(same_bits(inputs, pressure_inputs_))) {
            set_pressure_boundary();
            pressure_inputs_ = std::move(inputs);
        }
    }
    // A further pass of the step forces the projected velocity again: the fluid receives the momentum of
    // every pass, and the slip left is the last pass's.
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const BodyForcing& pass = forcing_->forcing()[b];
        step_forcing_[b].momentum_rate += pass.momentum_rate;
        step_forcing_[b].torque_rate += pass.torque_rate;
        step_forcing_[b].max_slip = pass.max_slip;
        step_forcing_[b].rms_slip = pass.rms_slip;
    }
}

void ImmersedBoundary::set_pressure_boundary() {
    ++pressure_matrix_;
    flow_->set_pressure_boundary({&cut_->open_cells(), &cut_->aperture_u(), &cut_->aperture_v(), &cut_->body_velocity(),
                                  &sharp_->open_flux(), sharp_->cut_momentum()});
    pressure_boundary_set_ = true;
}

ImmersedBoundary::NamedArrays ImmersedBoundary::checkpoint_arrays() const {
    if (!cut_) return {};
    return {{"open_flux", sharp_->open_flux_state()}};
}

void ImmersedBoundary::restored(const NamedArrays& arrays) {
    if (!cut_) return;
    // A checkpoint written before the open flux was carried has none: the run goes on without (not bit for bit).
    if (const auto it = arrays.find("open_flux"); it != arrays.end()) sharp_->restore_open_flux(it->second);
}

void ImmersedBoundary::place(double t) {
    for (Body& b : bodies_) b.move_to(t);
}

Wrench ImmersedBoundary::interface_wrench(std::size_t b, const Velocity& vel, double dt) const {
    const double rho = settings_.density, depth = settings_.depth;
    const BodyForcing& forcing = step_forcing_[b];
    // The fluid momentum inside the body: on the diffuse interface over a smeared outline, now against the start of
    // the step. Ghost faces: the momentum the body's region holds (SharpForcing::held_momentum) now against the start
    // of the step, so that the force is the momentum the fluid gained, to round-off over any number of steps.
    const EnclosedMomentum P = cut_ ? sharp_->held_momentum(vel)[b] : enclosed_momentum(grid_, vel, bodies_[b]);
    // Both moments about the body's centre now: the start's was taken about the centre then.
    EnclosedMomentum P0 = start_momentum_[b];
    P0.angular -= cross(bodies_[b].state().centre - start_centre_[b], P0.linear);
    Wrench w;
    w.force = rho * depth * (-forcing.momentum_rate + (P.linear - P0.linear) / dt);
    w.torque = rho * depth * (-forcing.torque_rate + (P.angular - P0.angular) / dt);
    if (cut_ && flow_) {
        // Ghost faces: the forcing meets the pressure only through the predicted velocity, i.e. the step's starting
        // pressure p^{n-1/2}; the projection's increment p^{n+1/2} - p^{n-1/2} acts on the body in this step through
        // the cut cells' shut parts (CutFaces::pressure_wrenches). Without it the body answered the pressure one
        // step late: a start or an impact lost its pressure impulse (the study's block started at 2.2 m/s in still
        // water kept 2.04 m/s where its added mass takes it to 1.40), and a block nearing the bed oscillated and
        // diverged (docs/validation.md, "Sharp interface", seventh step). On a body at rest in a steady flow the
        // increment vanishes; on one moving through the water it is the pressure's shift with the body over the step
        // (the study's block at 2.24 m/s: -11 N/m of 1300).
        const Wrench now = cut_->pressure_wrenches(flow_->pressure(), rho, depth)[b];
        const Wrench before = cut_->pressure_wrenches(flow_->previous_pressure(), rho, depth)[b];
        w.force += now.force - before.force;
        w.torque += now.torque - before.torque;
    }
    return w;
}

Wrench ImmersedBoundary::hydrodynamic_wrench(std::size_t b, const Velocity& vel, double dt) {
    wrench_[b] = interface_wrench(b, vel, dt);  // at the predicted place
    if (cut_ && flow_) {
        const double rho = settings_.density, depth = settings_.depth;
        const Body& body = bodies_[b];
        if (body.free()) {
            Coupling c;
            const BodyState& s = body.state();
            const auto& locked = body.config().motion.locked;
            for (int k = 0; k < 3; ++k) {
                if (locked[k]) continue;
                c.motions.push_back(k);
                c.unit.push_back(
                    cut_->shut_velocity(b, {k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0}, k == 2 ? 1.0 : 0.0, s.centre));
            }
            c.response = &response(b, c.unit);
            for (std::size_t l = 0; l < c.motions.size(); ++l) {
                const Wrench push = cut_->pressure_wrenches(c.response->pressure[l], rho, depth)[b];
                c.added_mass.col(c.motions[l]) = -Eigen::Vector3d(push.force.x(), push.force.y(), push.torque);
            }
            c.imposed = Eigen::Vector3d(s.velocity.x(), s.velocity.y(), s.angular_velocity);
            coupling_[b] = std::move(c);
        }
    }
    return wrench_[b];
}

std::vector<double> ImmersedBoundary::pressure_inputs() const {
    std::vector<double> in;
    for (const Field2D* f : {&cut_->aperture_u(), &cut_->aperture_v(), &cut_->open_cells()})
        in.insert(in.end(), f->raw().begin(), f->raw().end());
    for (const Axis* a : {&grid_.x_axis(), &grid_.y_axis()})
        for (int k = 0; k < a->cells(); ++k) in.push_back(a->width(k));
    return in;
}

bool ImmersedBoundary::on_every_rank(bool holds) const {
    int all = holds;
    MPI_Allreduce(MPI_IN_PLACE, &all, 1, MPI_INT, MPI_LAND, grid_.comm());
    return all != 0;
}

const FlowSolver::BodyResponse& ImmersedBoundary::response(std::size_t b, const std::vector<Velocity>& unit) {
    // A response is solved from zero, not from the last step's: a restart then repeats the straight run bit for bit.
    // A body that keeps its place on a grid translating with it (run/following_frame.hpp: the lines move exactly,
    // without round-off) and does not turn has the same cut faces, matrix and right-hand sides every step, and the
    // solve, a function of those alone, the same answer: it is kept (the study's free fall on its window, a third of
    // the step; docs/performance.md). Kept only when the matrix is the one it was solved with and the unit motions'
    // shut-face velocities are the same bit for bit, so that the kept response is the one a restart solves afresh.
    std::optional<KeptResponse>& kept = kept_response_[b];
    bool same = kept && kept->matrix == pressure_matrix_ && kept->unit.size() == unit.size();
    for (std::size_t k = 0; same && k < unit.size(); ++k)
        same = same_bits(kept->unit[k].u.raw(), unit[k].u.raw()) && same_bits(kept->unit[k].v.raw(), unit[k].v.raw());
    if (!on_every_rank(same)) {
        kept = KeptResponse{pressure_matrix_, unit, flow_->cut_response(unit)};
        ++responses_solved_;
    }
    return kept->response;
}

std::optional<Eigen::Matrix3d> ImmersedBoundary::added_mass(std::size_t b) const {
    if (!coupling_[b]) return std::nullopt;
    return coupling_[b]->added_mass;
}

void ImmersedBoundary::body_moved(std::size_t b, double dt) {
    if (!coupling_[b]) return;
    const Coupling& c = *coupling_[b];
    const BodyState& s = bodies_[b].state();
    const Eigen::Vector3d change = Eigen::Vector3d(s.velocity.x(), s.velocity.y(), s.angular_velocity) - c.imposed;
    std::vector<double> along;
    for (std::size_t l = 0; l < c.motions.size(); ++l) {
        along.push_back(change[c.motions[l]]);
        cut_->add_shut_velocity(c.unit[l], along.back());
    }
    flow_->add_body_response(*c.response, along, dt);
    // The wrench of the flow as it now is (measure (a)): its pressure changed by the response, -M d(motion) / dt.
    const Eigen::Vector3d push = -c.added_mass * change / dt;
    wrench_[b].force += Vec2(push[0], push[1]);
    wrench_[b].torque += push[2];
}

std::vector<BodyForces> ImmersedBoundary::measure(const Velocity& vel, const Field2D& p,
                                                  const WallTurbulence* turbulence) {
    std::vector<BodyForces> out(bodies_.size());
    const double rho = settings_.density, depth = settings_.depth;
    forcing_->measure_slip(vel);
    const double dt = flow_ ? flow_->previous_dt() : 0.0;  // the step just taken (0 before the first)
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const Body& body = bodies_[b];
        const BodyForcing& f = step_forcing_[b];
        BodyForces& r = out[b];
        if (body.free()) {
            r.forcing = wrench_[b].force;
            r.forcing_torque = wrench_[b].torque;
        } else if (cut_ && dt > 0.0) {
            // Ghost faces: the free body's measure, so that a fixed, a prescribed and a free body read the same force.
            // The rigid-body form below took the faces inside as moving with the body, where they hold mirror images:
            // the block moved through still water rippled by 21 % as it crossed cells, with this measure by 11 %
            // (docs/validation.md, "Sharp interface", eighth step).
            const Wrench w = interface_wrench(b, vel, dt);
            r.forcing = w.force;
            r.forcing_torque = w.torque;
        } else {
            r.forcing = rho * depth * (-f.momentum_rate + body.area() * body.state().acceleration);
            r.forcing_torque = rho * depth * (-f.torque_rate + body.polar_moment() * body.state().angular_acceleration);
        }
        // The sharp interface measures its slip after the projection (measure_slip), the diffuse one in its iteration.
        r.max_slip = sharp_ ? forcing_->forcing()[b].max_slip : f.max_slip;
        r.rms_slip = sharp_ ? forcing_->forcing()[b].rms_slip : f.rms_slip;
        r.surface = stress_[b]->compute(vel, p, rho, settings_.viscosity, depth, turbulence);
    }
    return out;
}

}  // namespace chute
