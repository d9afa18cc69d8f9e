#pragma once
// The Monte Carlo run of a hazard case: N blocks, each with its own draws (size, density, release point and
// velocity, and in its trajectory every impact's coefficients and roughness) from the random stream of its index
// (distribution.hpp: trajectory_rng), so that a seed gives the same N trajectories on any number of MPI ranks.
// Rank r runs the indices r, r + size, ...; rank 0 gathers every outcome in index order.
#include <mpi.h>

#include <vector>

#include "hazard_case.hpp"

namespace chute {

// One trajectory's draws and outcome.
struct TrajectoryOutcome {
    double size = 0.0, density = 0.0;
    Vec2 release = Vec2::Zero(), release_velocity = Vec2::Zero();
    TrajectoryEnd end = TrajectoryEnd::rest;
    double time = 0.0;
    Vec2 stop = Vec2::Zero();  // where it came to rest or left the profile
    double max_speed = 0.0;
    int impacts = 0;
};

struct HazardResults {
    std::vector<double> stations;  // x of the envelope stations, evenly over the profile
    std::vector<TrajectoryOutcome> outcomes;
    // trajectories x stations (row-major); NaN where the block did not cross the station.
    std::vector<double> speed, kinetic_energy, rotational_energy, height;
    // trajectories x collectors: speed, kinetic energy and height as the block crossed it; NaN: not crossed.
    std::vector<double> collector_speed, collector_energy, collector_height;
    // The first `paths` trajectories whole: rows (trajectory, t, x, z, speed, sliding).
    std::vector<std::array<double, 6>> paths;
    double seconds = 0.0;  // wall time of the trajectories (all ranks)
};

// On rank 0 the gathered results; on the others, only `seconds`. `progress`: rank 0 prints a progress line.
HazardResults run_hazard(const HazardCase& c, MPI_Comm comm, bool progress = false);

}  // namespace chute
