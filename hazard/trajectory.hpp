#pragma once
// One block down a slope profile: the wet lumped model of the hazard analysis.
//
// The block is a cube of side a (the study's square prism of depth a: the equations per unit mass are the same)
// reduced to a point at its lowest face (RocFall's lumped mass). In flight it obeys the Beranger et al. (1998)
// model of rigidbody/lumped_model.hpp where it is under the water level (gravity, buoyancy, drag C_D, added mass
// C_a) and gravity alone above it, integrated by SUNDIALS CVODE, whose root finding stops it at the ground, at
// the water level and at the profile's ends; near the ground in water the squeezed water brakes its motion normal
// to the ground (ground_effect.hpp). Slides are solved in closed form (slide_motion.hpp). At the ground the wet
// rebound law (wet_rebound.hpp) acts on the velocity against the segment, its angle perturbed by the material's
// roughness:
//   v_n' = -e_n v_n,  v_t' = e_t v_t.
// A rebound slower than the sliding speed normal to the segment turns into a slide: Coulomb friction on the
// buoyant weight, drag and added mass in water, along the segment; at a convex vertex it takes off, at a
// concave one it keeps the velocity along the new segment; where the speed drops to zero and the friction holds
// the weight, it stops. Rotation is tracked as a lumped model can (RocFall's lumped mass): the spin of a block
// rolling off at each impact, omega = v_t' / (a / 2), kept in flight (in water too: no rotational drag is
// modelled), none while sliding (the slide is Coulomb friction, not rolling); it reports rotational energy and
// does not act back on the translation.
#include <sundials/sundials_context.h>
#include <sundials/sundials_nonlinearsolver.h>
#include <sundials/sundials_nvector.h>

#include <random>
#include <vector>

#include "ground_effect.hpp"
#include "lumped_model.hpp"
#include "material.hpp"
#include "slope_profile.hpp"
#include "wet_rebound.hpp"

namespace chute {

struct HazardBlock {
    double size = 0.3;        // m, side a
    double density = 2650.0;  // kg/m^3
    double mass() const { return density * size * size * size; }
    double moment_of_inertia() const { return mass() * size * size / 6.0; }  // cube about an axis of a face
};

struct WaterProperties {
    double density = 1000.0;    // kg/m^3
    double viscosity = 1.0e-3;  // Pa s
};

struct TrajectorySettings {
    double gravity = 9.81;
    double drag_coefficient = 2.0, added_mass_coefficient = 0.5;  // Beranger et al. (1998), as the study took them
    WetRebound wet_rebound;
    GroundEffect ground_effect;  // in water only (ground_effect.hpp)
    double sliding_speed = 0.1;  // m/s: a rebound slower than this normal to the ground turns into a slide
    double end_time = 600.0;     // s
    int max_impacts = 10000;     // past this, the block slides
    double relative_tolerance = 1e-8, absolute_tolerance = 1e-10;
};

enum class TrajectoryEnd { rest, past_end, past_start, time_limit };

// The state of the block where it crosses a station x (the largest over several crossings).
struct StationCrossing {
    int crossings = 0;
    double speed = 0.0, kinetic_energy = 0.0, rotational_energy = 0.0;
    double height = 0.0;  // of the block's lowest point above the ground (normal to it)
};

struct Impact {
    double t = 0.0;
    Vec2 position = Vec2::Zero(), velocity_before = Vec2::Zero(), velocity_after = Vec2::Zero();
    bool wet = false;
    double stokes = 0.0;  // infinite in air
    double travel = 0.0;  // block sizes from where the flight began (wet_rebound.hpp)
    double normal_restitution = 0.0, tangential_restitution = 0.0;
    double push = 0.0;  // m/s down the slope: the wake's push on a slope (wet_rebound.hpp)
};

// The top of a bounce: where the block stops rising from the ground under it.
struct Apex {
    double t = 0.0;
    Vec2 position = Vec2::Zero();
    double height = 0.0;  // above the ground, normal to it
};

struct PathSample {
    double t;
    Vec2 position, velocity;
    bool sliding;
};

struct TrajectoryResult {
    TrajectoryEnd end = TrajectoryEnd::time_limit;
    double t = 0.0;
    Vec2 position = Vec2::Zero(), velocity = Vec2::Zero();  // where it stopped or left
    double max_speed = 0.0;
    std::vector<Impact> impacts;
    std::vector<Apex> apexes;
    std::vector<StationCrossing> stations;  // one per station given
    std::vector<PathSample> path;           // every integration step, if asked for
};

// Runs trajectories on one profile; keeps its CVODE memory from one to the next (not thread-safe).
class TrajectoryIntegrator {
public:
    TrajectoryIntegrator(const SlopeProfile& profile, const std::vector<Material>& materials,
                         const WaterProperties& water, const TrajectorySettings& settings);
    ~TrajectoryIntegrator();
    TrajectoryIntegrator(const TrajectoryIntegrator&) = delete;
    TrajectoryIntegrator& operator=(const TrajectoryIntegrator&) = delete;

    // `stations`: x positions (increasing) where crossings are recorded. `rng` draws the per-impact
    // coefficients and roughness.
    TrajectoryResult run(const HazardBlock& block, const Vec2& position, const Vec2& velocity,
                         const std::vector<double>& stations, std::mt19937_64& rng, bool record_path = false);

    const SlopeProfile& profile() const { return profile_; }
    // The flight model at a height z (wet below the water level): the lumped model's constants.
    LumpedModelConfig flight_model(const HazardBlock& block, bool wet) const;

    struct Flight;  // what CVODE integrates, internal

private:
    struct Run;  // one trajectory's state while it runs

    // (Re)starts CVODE on a flight from x at velocity v.
    void start(const Flight& flight, double t, const Vec2& x, const Vec2& v);
    // A flight from `from` (just above the ground if it starts on it); at the water level (`crossing`) in the
    // medium the block is going into.
    void fly(Run& run, const Vec2& from, const Vec2& v, double spin, bool crossing = false);
    // The stations crossed in CVODE's last step, from x0 to x1 (its interpolant gives the state at each).
    void record_flight_crossings(Run& run, double t0, double x0, double x1);
    // An impact at x: the rebound law, then a flight or a slide. False if the trajectory is over.
    bool impact(Run& run, const Vec2& x, const Vec2& v);
    // A slide from s along segment k at velocity v along its tangent, in closed form (slide_motion.hpp), from event
    // to event: the segment's end (a take-off at a convex vertex, the next segment at a concave one), the water
    // level, rest. True if it ends in a take-off (the flight started), false if the trajectory is over.
    bool slide(Run& run, int k, double s, double v, bool new_slide);

    const SlopeProfile& profile_;
    const std::vector<Material>& materials_;
    WaterProperties water_;
    TrajectorySettings settings_;
    SUNContext context_ = nullptr;
    void* cvode_ = nullptr;
    N_Vector y_ = nullptr, dky_ = nullptr;
    SUNNonlinearSolver solver_ = nullptr;
    int roots_ = -1;  // the number CVODE was set up with
};

}  // namespace chute
