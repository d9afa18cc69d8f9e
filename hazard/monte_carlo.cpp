#include "monte_carlo.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace chute {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr int kScalars = 13;  // a trajectory's outcome packed as doubles

std::vector<double> evenly(double a, double b, int n) {
    std::vector<double> x(n);
    for (int i = 0; i < n; ++i) x[i] = a + (b - a) * (i + 0.5) / n;  // station centres: none on the ends
    return x;
}

}  // namespace

HazardResults run_hazard(const HazardCase& c, MPI_Comm comm, bool progress) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    const auto started = std::chrono::steady_clock::now();
    const SlopeProfile profile = c.profile();
    HazardResults out;
    out.stations = evenly(profile.x_min(), profile.x_max(), c.stations);
    std::vector<double> watched = out.stations;  // the stations, then the collectors
    for (const Collector& k : c.collectors) watched.push_back(k.x);
    std::vector<int> order(watched.size());  // the integrator wants them increasing
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return watched[a] < watched[b]; });
    std::vector<double> sorted(watched.size());
    for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = watched[order[i]];

    const int S = c.stations, C = static_cast<int>(c.collectors.size());
    const int stride = kScalars + 4 * S + 3 * C;
    std::vector<double> mine;   // this rank's trajectories, `stride` doubles each
    std::vector<double> paths;  // rows of 6
    TrajectoryIntegrator integrator(profile, c.materials, c.water, c.settings);
    long done = 0;
    auto last_print = started;
    for (long i = rank; i < c.trajectories; i += size) {
        std::mt19937_64 rng = trajectory_rng(c.seed, static_cast<unsigned long long>(i));
        HazardBlock block;
        block.size = c.block.size.sample(rng);
        block.density = c.block.density.sample(rng);
        const double x0 = c.release.x.sample(rng), h0 = c.release.height.sample(rng);
        const Vec2 release(x0, profile.height_at(x0) + h0);
        const Vec2 v0(c.release.velocity_x.sample(rng), c.release.velocity_z.sample(rng));
        const bool keep_path = i < c.paths;
        const TrajectoryResult r = integrator.run(block, release, v0, sorted, rng, keep_path);

        std::vector<double> row{static_cast<double>(i),
                                block.size,
                                block.density,
                                release.x(),
                                release.y(),
                                v0.x(),
                                v0.y(),
                                static_cast<double>(r.end),
                                r.t,
                                r.position.x(),
                                r.position.y(),
                                r.max_speed,
                                static_cast<double>(r.impacts.size())};
        row.resize(stride, nan);
        for (std::size_t j = 0; j < order.size(); ++j) {
            const StationCrossing& s = r.stations[j];
            if (s.crossings == 0) continue;
            const int w = order[j];
            if (w < S) {
                row[kScalars + w] = s.speed;
                row[kScalars + S + w] = s.kinetic_energy;
                row[kScalars + 2 * S + w] = s.rotational_energy;
                row[kScalars + 3 * S + w] = s.height;
            } else {
                const int k = w - S;
                row[kScalars + 4 * S + k] = s.speed;
                row[kScalars + 4 * S + C + k] = s.kinetic_energy + s.rotational_energy;
                row[kScalars + 4 * S + 2 * C + k] = s.height;
            }
        }
        mine.insert(mine.end(), row.begin(), row.end());
        if (keep_path)
            for (const PathSample& p : r.path)
                paths.insert(paths.end(), {static_cast<double>(i), p.t, p.position.x(), p.position.y(),
                                           p.velocity.norm(), p.sliding ? 1.0 : 0.0});
        ++done;
        const auto now = std::chrono::steady_clock::now();
        if (progress && rank == 0 && now - last_print > std::chrono::seconds(2)) {
            last_print = now;
            const double s = std::chrono::duration<double>(now - started).count();
            const long total = done * size;
            std::printf("hazard: %ld of %ld trajectories, %.1f s, about %.0f s left\n", total, c.trajectories, s,
                        s * (c.trajectories - total) / std::max(1L, total));
            std::fflush(stdout);
        }
    }

    // Rank 0 gathers the rows and the paths, and puts them in index order.
    const auto gather = [&](const std::vector<double>& local) {
        int n = static_cast<int>(local.size());
        std::vector<int> counts(size), offsets(size, 0);
        MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
        for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
        std::vector<double> all(rank == 0 ? offsets[size - 1] + counts[size - 1] : 0);
        MPI_Gatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, comm);
        return all;
    };
    const std::vector<double> rows = gather(mine), all_paths = gather(paths);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    MPI_Allreduce(MPI_IN_PLACE, &out.seconds, 1, MPI_DOUBLE, MPI_MAX, comm);
    if (rank != 0) return out;

    const long N = c.trajectories;
    out.outcomes.resize(N);
    out.speed.assign(N * S, nan);
    out.kinetic_energy.assign(N * S, nan);
    out.rotational_energy.assign(N * S, nan);
    out.height.assign(N * S, nan);
    out.collector_speed.assign(N * C, nan);
    out.collector_energy.assign(N * C, nan);
    out.collector_height.assign(N * C, nan);
    for (std::size_t at = 0; at < rows.size(); at += stride) {
        const double* row = &rows[at];
        const long i = static_cast<long>(row[0]);
        TrajectoryOutcome& o = out.outcomes[i];
        o.size = row[1], o.density = row[2];
        o.release = Vec2(row[3], row[4]);
        o.release_velocity = Vec2(row[5], row[6]);
        o.end = static_cast<TrajectoryEnd>(static_cast<int>(row[7]));
        o.time = row[8];
        o.stop = Vec2(row[9], row[10]);
        o.max_speed = row[11];
        o.impacts = static_cast<int>(row[12]);
        for (int s = 0; s < S; ++s) {
            out.speed[i * S + s] = row[kScalars + s];
            out.kinetic_energy[i * S + s] = row[kScalars + S + s];
            out.rotational_energy[i * S + s] = row[kScalars + 2 * S + s];
            out.height[i * S + s] = row[kScalars + 3 * S + s];
        }
        for (int k = 0; k < C; ++k) {
            out.collector_speed[i * C + k] = row[kScalars + 4 * S + k];
            out.collector_energy[i * C + k] = row[kScalars + 4 * S + C + k];
            out.collector_height[i * C + k] = row[kScalars + 4 * S + 2 * C + k];
        }
    }
    for (std::size_t at = 0; at < all_paths.size(); at += 6)
        out.paths.push_back({all_paths[at], all_paths[at + 1], all_paths[at + 2], all_paths[at + 3], all_paths[at + 4],
                             all_paths[at + 5]});
    std::stable_sort(out.paths.begin(), out.paths.end(),
                     [](const auto& a, const auto& b) { return a[0] < b[0]; });  // each path's rows stay in time order
    return out;
}

}  // namespace chute
