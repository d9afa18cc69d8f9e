// bench_step: cost of one time step of the flow solver, and of a bare Poisson solve, per cell.
//
//   mpirun -np R bench_step [options] [N ...]        (default N: 256 512 1024)
//
// Case: the lid-driven cavity at Re = 1000 (unit square, walls, lid [1, 0], nu = 1e-3, central
// convection, CFL 0.5, Poisson tolerance 1e-8) on an N x N uniform grid. For each N: `--warmup` steps
// (default 50), then at least `--min-steps` steps (default 20) and `--min-seconds` of wall time
// (default 2 s) are timed. The step is FlowSolver::advance() alone (the run loop's per-step diagnostics,
// kinetic energy and max |div u|, are timed separately). Then a Poisson solve from a zero guess to 1e-8
// (PoissonSolver on the same grid, all-Neumann like the projection, random zero-mean right-hand side) is
// timed, best of `--poisson-repeats` (default 3), for comparison with STACK.md.
// `--kernels` adds a table of the step's parts timed one by one (convection, diffusion, ...), each from cold
// caches, as within a step (the Poisson solve in between streams far more data than the last-level cache).
// `--body` adds the carriers' cost: the same cavity with a square of side 0.25 at its centre, turned 22.5 degrees (no
// side on a grid line), held fixed or oscillating and turning (x = 0.5 + 0.05 sin(2 pi t), angle 22.5 + 20 sin(2 pi
// t) degrees: every step moves it across the cells), on each immersed carrier: the diffuse interface and the sharp
// one with forcing and with ghost faces (numerics.ibm.*). Whole steps (run/step.hpp take_step and the force
// measures), per cell and against the diffuse carrier's (issue "Sharp corners" asks at most 1.3 times).
// Rank 0 prints Markdown tables.
#include <HYPRE_utilities.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "boundary_conditions.hpp"
#include "case_file.hpp"
#include "convection.hpp"
#include "diagnostics.hpp"
#include "diffusion.hpp"
#include "flow_solver.hpp"
#include "halo_exchange.hpp"
#include "model.hpp"
#include "poisson_solver.hpp"
#include "projection.hpp"
#include "step.hpp"
#include "time_step_control.hpp"
#include "triad.hpp"

using namespace chute;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Options {
    std::vector<int> grids;
    int warmup = 50;
    int min_steps = 20;
    double min_seconds = 2.0;
    int poisson_repeats = 3;
    bool kernels = false;
    bool body = false;
};

// The lid-driven cavity at Re 1000: the flow alone (the benchmark times the flow solver).
FlowConfig cavity_case(int n) {
    FlowConfig c;
    c.x = AxisConfig{0.0, 1.0, n, "uniform", 2.0, 1.05, {}};
    c.y = c.x;
    for (auto& b : c.boundary) b.type = BoundaryType::wall;
    c.boundary[static_cast<int>(Side::top)].velocity = {1.0, 0.0};
    c.viscosity = 1e-3;
    c.convection = ConvectionScheme::central;
    c.cfl = 0.5;
    c.poisson_tolerance = 1e-8;
    return c;
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
        }
    return "unknown";
}

int cpu_count() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    int n = 0;
    while (std::getline(in, line))
        if (line.rfind("processor", 0) == 0) ++n;
    return n;
}

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    double a = 0, b = 0, c = 0;
    in >> a >> b >> c;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f %.2f %.2f", a, b, c);
    return buf;
}

std::string today() {
    const std::time_t t = std::time(nullptr);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M", std::localtime(&t));
    return buf;
}

struct StepRow {
    int n = 0;
    long steps = 0;
    double seconds = 0, sec_momentum = 0, sec_poisson = 0, sec_correction = 0, sec_diagnostics = 0;
    double min_step = 0, iterations = 0;
};

struct PoissonRow {
    int n = 0;
    double seconds = 0;
    int iterations = 0;
    double residual = 0;
};

struct KernelRow {
    std::string name;
    double seconds = 0;         // best of the repeats, one call
    double bytes_per_cell = 0;  // memory traffic model (STREAM counting: each array read or written once, 8 B)
    int per_step = 0;           // times the part runs in one step (0: not part of FlowSolver::advance())
};

// Evicts the caches (writes a buffer larger than the last-level cache), so that a kernel timed next reads
// its fields from memory, as it does within a step (the Poisson solve streams far more than the cache).
void flush_caches() {
    static std::vector<double> junk(std::size_t{1} << 23);  // 64 MiB
    for (double& x : junk) x += 1.0;
    volatile double keep = junk[junk.size() / 2];
    (void)keep;
}

// Runs f `repeats` times (synchronised; from cold caches if `cold`) and returns the best wall time of one
// call (max over ranks).
double best_time(MPI_Comm comm, int repeats, bool cold, const std::function<void()>& f) {
    double best = INFINITY;
    for (int r = 0; r < repeats; ++r) {
        if (cold) flush_caches();
        MPI_Barrier(comm);
        const auto t0 = Clock::now();
        f();
        double t = since(t0);
        MPI_Allreduce(MPI_IN_PLACE, &t, 1, MPI_DOUBLE, MPI_MAX, comm);
        best = std::min(best, t);
    }
    return best;
}

std::vector<KernelRow> time_kernels(FlowSolver& s, int repeats) {
    const Grid& g = s.grid();
    const FlowConfig& c = s.config();
    MPI_Comm comm = g.comm();
    BoundaryConditions bc(g, c.boundary);
    HaloExchange halo(g);
    Velocity vel = s.velocity(), rhs(g), rhs_old = s.previous_rhs(), star(g);
    Field2D p = s.pressure(), source(g);
    const double dt = s.next_dt();
    const int nx = g.nx(), ny = g.ny();
    volatile double sink = 0.0;
    std::vector<KernelRow> rows;
    auto add = [&](const char* name, double bytes, int per_step, const std::function<void()>& f) {
        rows.push_back({name, best_time(comm, repeats, true, f), bytes, per_step});
    };
    PoissonSolver poisson(g, {false, false, false, false}, c.poisson_tolerance, c.poisson_max_iterations);
    divergence(g, vel, 1.0 / dt, source);
    Field2D phi(g);

    add("time_step_limits (next_dt)", 16, 1,
        [&] { sink = time_step_limits(g, vel, c.viscosity, c.cfl, c.diffusion_number).stable(); });
    add("convection (central)", 32, 1, [&] { convection(g, c.convection, vel, bc.u_first(), bc.v_first(), rhs); });
    add("add_diffusion", 48, 1, [&] { add_diffusion(g, c.viscosity, vel, bc.u_first(), bc.v_first(), rhs); });
    add("AB2 update u*", 64, 1, [&] {
        for (int j = 0; j < ny; ++j)
            for (int i = bc.u_first(); i < nx; ++i)
                star.u(i, j) = vel.u(i, j) + 1.5 * dt * rhs.u(i, j) - 0.5 * dt * rhs_old.u(i, j);
        for (int j = bc.v_first(); j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                star.v(i, j) = vel.v(i, j) + 1.5 * dt * rhs.v(i, j) - 0.5 * dt * rhs_old.v(i, j);
    });
    add("set_outflow + halo(u*)", 0, 1, [&] {
        bc.set_outflow(vel, star, dt);
        halo.exchange(star);
    });
    add("divergence", 24, 1, [&] { divergence(g, star, 1.0 / dt, source); });
    add("residual-floor sum (multigrid only)", 16, 0, [&] {
        const auto& X = g.lx();
        const auto& Y = g.ly();
        double scale = 0.0;
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const double rate = std::abs(star.u(i, j)) / X.w(i) + std::abs(star.v(i, j)) / Y.w(j);
                const double b = X.w(i) * Y.w(j) * rate / dt;
                scale += b * b;
            }
        MPI_Allreduce(MPI_IN_PLACE, &scale, 1, MPI_DOUBLE, MPI_SUM, comm);
        sink = scale;
    });
    add("halo(p) + apply_pressure", 0, 2, [&] {
        halo.exchange(p);
        bc.apply_pressure(p);
    });
    add("subtract_pressure_gradient", 40, 2, [&] { subtract_pressure_gradient(g, bc, p, dt, star); });
    add("halo(u) + bc.apply", 0, 1, [&] {
        halo.exchange(star);
        bc.apply(star);
    });
    add("kinetic_energy (run loop)", 16, 0, [&] { sink = kinetic_energy(g, vel); });
    add("max_divergence (run loop)", 16, 0, [&] { sink = max_divergence(g, vel); });
    add("p^{n-1} <- p^n, p += phi", 40, 1, [&] {
        for (int j = 0; j < ny; ++j)  // two passes, as in the step (pressure_increment_guess, then the correction)
            for (int i = 0; i < nx; ++i) rhs_old.u(i, j) = p(i, j);
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) p(i, j) += source(i, j);
    });
    // The direct solve (one rank): forward transform out of place (8 + 8), the tridiagonal sweeps over blocks of
    // modes that stay in cache (16), the inverse in place (16). On more ranks the pencil transposes add theirs.
    add(poisson.direct() ? "Poisson solve (direct)" : "Poisson solve (multigrid)", poisson.direct() ? 48 : 0, 1,
        [&] { poisson.solve(source, phi); });
    (void)sink;
    return rows;
}

// The cavity of cavity_case(n) with the square of the body case (above), on `interface` (diffuse, or sharp with
// `faces`), fixed or moving.
std::string body_case_text(int n, const std::string& interface, const std::string& faces, bool moving) {
    std::string motion = moving ? "    motion: {type: oscillation, amplitude: [0.05, 0.0], angular_amplitude: 20.0, "
                                  "frequency: 1.0}\n"
                                : "";
    std::string ibm = interface == "diffuse" ? "" : ", ibm: {interface: sharp, sharp_faces: " + faces + "}";
    char grid[160];
    std::snprintf(grid, sizeof grid, "  x: {start: 0.0, end: 1.0, cells: %d}\n  y: {start: 0.0, end: 1.0, cells: %d}\n",
                  n, n);
    return "name: bench_body\ndomain:\n" + std::string(grid) +
           "fluid: {density: 1.0, viscosity: 0.001}\n"
           "boundaries:\n  left: {type: wall}\n  right: {type: wall}\n  bottom: {type: wall}\n"
           "  top: {type: wall, velocity: [1.0, 0.0]}\n"
           "bodies:\n  square:\n    shape: rectangle\n    centre: [0.5, 0.5]\n    size: [0.25, 0.25]\n"
           "    angle: 22.5\n" +
           motion + "numerics: {convection: central, cfl: 0.5" + ibm + "}\ntime: {end: 1000.0}\n";
}

struct BodyRow {
    int n = 0;
    std::string carrier;
    bool moving = false;
    long steps = 0;
    double seconds = 0, bodies = 0, poisson = 0;
};

BodyRow time_body_case(int n, const std::string& interface, const std::string& faces, bool moving, const Options& opt) {
    const CaseConfig c = parse_case_text(body_case_text(n, interface, faces, moving));
    Model model(c, MPI_COMM_WORLD);
    auto step = [&](StageTimer* stages) {
        take_step(model, model.stable_dt(), stages);
        measure_forces(model, stages);
    };
    for (int k = 0; k < opt.warmup; ++k) step(nullptr);
    MPI_Barrier(MPI_COMM_WORLD);
    auto t0 = Clock::now();
    step(nullptr);
    double probe = since(t0);
    MPI_Bcast(&probe, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    const long count = std::max<long>(opt.min_steps, static_cast<long>(std::ceil(opt.min_seconds / probe)));
    StageTimer stages(kStepStages);
    BodyRow row{n, interface == "diffuse" ? "diffuse" : "sharp, " + faces + " faces", moving, count};
    MPI_Barrier(MPI_COMM_WORLD);
    t0 = Clock::now();
    for (long k = 0; k < count; ++k) step(&stages);
    MPI_Barrier(MPI_COMM_WORLD);
    row.seconds = since(t0);
    row.bodies = stages.seconds("bodies");
    row.poisson = stages.seconds("poisson");
    if (!std::isfinite(kinetic_energy(model.flow().grid(), model.flow().velocity()))) {
        int rank = 0;
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        if (rank == 0) std::fprintf(stderr, "bench_step: the body case (%s) diverged\n", row.carrier.c_str());
        MPI_Abort(MPI_COMM_WORLD, 3);
    }
    return row;
}

void print_body_rows(const std::vector<BodyRow>& rows, int size) {
    std::printf("\n### Body case (the cavity with a square turned 22.5 degrees, side 0.25), %d rank%s\n\n", size,
                size > 1 ? "s" : "");
    std::printf(
        "| grid | square | carrier | steps | us / cell-step | against diffuse | bodies share | Poisson share |\n"
        "|---|---|---|---|---|---|---|---|\n");
    for (const BodyRow& r : rows) {
        const double cells = static_cast<double>(r.n) * r.n;
        double diffuse = 0.0;
        for (const BodyRow& d : rows)
            if (d.n == r.n && d.moving == r.moving && d.carrier == "diffuse") diffuse = d.seconds / d.steps;
        const double per_step = r.seconds / r.steps;
        std::printf("| %d^2 | %s | %s | %ld | %.3f | %.2fx | %.0f %% | %.0f %% |\n", r.n, r.moving ? "moving" : "fixed",
                    r.carrier.c_str(), r.steps, 1e6 * per_step / cells, diffuse > 0 ? per_step / diffuse : 0.0,
                    100 * r.bodies / r.seconds, 100 * r.poisson / r.seconds);
    }
}

void usage() {
    std::fprintf(stderr,
                 "usage: bench_step [--warmup N] [--min-steps N] [--min-seconds S] [--poisson-repeats N] "
                 "[--kernels] [--body] [GRID ...]\n");
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    HYPRE_Init();
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const bool root = rank == 0;

    Options opt;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        auto value = [&]() -> const char* {
            if (a + 1 >= argc) {
                if (root) usage();
                MPI_Abort(MPI_COMM_WORLD, 2);
            }
            return argv[++a];
        };
        if (arg == "--warmup")
            opt.warmup = std::atoi(value());
        else if (arg == "--min-steps")
            opt.min_steps = std::atoi(value());
        else if (arg == "--min-seconds")
            opt.min_seconds = std::atof(value());
        else if (arg == "--poisson-repeats")
            opt.poisson_repeats = std::atoi(value());
        else if (arg == "--kernels")
            opt.kernels = true;
        else if (arg == "--body")
            opt.body = true;
        else if (arg == "-h" || arg == "--help") {
            if (root) usage();
            HYPRE_Finalize();
            MPI_Finalize();
            return 0;
        } else if (const int n = std::atoi(arg.c_str()); n >= 8)
            opt.grids.push_back(n);
        else {
            if (root) usage();
            MPI_Abort(MPI_COMM_WORLD, 2);
        }
    }
    if (opt.grids.empty()) opt.grids = {256, 512, 1024};

    const bench::Triad triad_start = bench::measure_triad(MPI_COMM_WORLD);
    if (root) {
        std::printf("Machine: %s, %d cores; %s; load average at start %s\n\n", cpu_model().c_str(), cpu_count(),
                    today().c_str(), load_average().c_str());
        std::printf("STREAM triad (bench/triad.hpp), %d rank%s at once: %.1f GB/s (%.1f per rank)\n\n", size,
                    size > 1 ? "s" : "", triad_start.total_gbs, triad_start.per_rank_gbs);
        std::printf(
            "Case: lid-driven cavity, Re 1000, central convection, CFL 0.5, Poisson tol 1e-8; %d warm-up "
            "steps, then >= %d steps and >= %.1f s timed.\n\n",
            opt.warmup, opt.min_steps, opt.min_seconds);
        std::fflush(stdout);
    }

    std::vector<StepRow> steps;
    std::vector<PoissonRow> poisson;
    std::vector<std::pair<int, std::vector<KernelRow>>> kernels;
    for (const int n : opt.grids) {
        FlowSolver s(cavity_case(n), MPI_COMM_WORLD);
        const Grid& g = s.grid();
        for (int k = 0; k < opt.warmup; ++k) s.advance();

        // Number of timed steps: from the last warm-up steps' speed (decided on rank 0, so all agree).
        MPI_Barrier(MPI_COMM_WORLD);
        auto t0 = Clock::now();
        s.advance();
        double probe = since(t0);
        MPI_Bcast(&probe, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
        long count = std::max<long>(opt.min_steps, static_cast<long>(std::ceil(opt.min_seconds / probe)));

        StepRow row;
        row.n = n;
        row.steps = count;
        row.min_step = INFINITY;
        double ke = 0, div = 0;
        StageTimer stages;
        s.set_timer(&stages);
        MPI_Barrier(MPI_COMM_WORLD);
        for (long k = 0; k < count; ++k) {
            t0 = Clock::now();
            const StepStats st = s.advance();
            const double t_step = since(t0);
            const auto t1 = Clock::now();
            ke += kinetic_energy(g, s.velocity());
            div = std::max(div, max_divergence(g, s.velocity()));
            row.sec_diagnostics += since(t1);
            row.seconds += t_step;
            row.min_step = std::min(row.min_step, t_step);
            row.iterations += st.poisson_iterations;
        }
        s.set_timer(nullptr);
        row.sec_momentum = stages.seconds("momentum");
        row.sec_poisson = stages.seconds("poisson");
        row.sec_correction = stages.seconds("correction");
        if (!std::isfinite(ke) || !std::isfinite(div)) {
            if (root) std::fprintf(stderr, "bench_step: the %d^2 run diverged\n", n);
            MPI_Abort(MPI_COMM_WORLD, 3);
        }
        steps.push_back(row);

        if (opt.kernels) kernels.emplace_back(n, time_kernels(s, 5));

        // Bare Poisson solve from a zero guess, all-Neumann (the projection's problem).
        PoissonSolver ps(g, {false, false, false, false}, 1e-8, 200);
        Field2D source(g), p(g);
        std::mt19937_64 rng(12345u + 7919u * static_cast<unsigned>(rank));
        std::uniform_real_distribution<double> dist(-1.0, 1.0);
        double sum = 0.0;
        for (int j = 0; j < g.ny(); ++j)
            for (int i = 0; i < g.nx(); ++i) sum += (source(i, j) = dist(rng));
        MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
        const double mean = sum / static_cast<double>(g.global_cells());
        for (int j = 0; j < g.ny(); ++j)
            for (int i = 0; i < g.nx(); ++i) source(i, j) -= mean;
        PoissonRow prow;
        prow.n = n;
        PoissonStats pst;
        prow.seconds = best_time(MPI_COMM_WORLD, opt.poisson_repeats, false, [&] {
            p.fill(0.0);
            pst = ps.solve(source, p);
        });
        prow.iterations = pst.iterations;
        prow.residual = pst.relative_residual;
        poisson.push_back(prow);
    }

    std::vector<BodyRow> body_rows;
    if (opt.body)
        for (const int n : opt.grids)
            for (const bool moving : {false, true})
                for (const auto& [interface, faces] :
                     {std::pair<std::string, std::string>{"diffuse", ""}, {"sharp", "forcing"}, {"sharp", "ghost"}})
                    body_rows.push_back(time_body_case(n, interface, faces, moving, opt));

    if (root) {
        std::printf("### Time step, %d rank%s\n\n", size, size > 1 ? "s" : "");
        std::printf(
            "| ranks | grid | steps | us / cell-step | Poisson share | momentum share | correction share | "
            "Poisson it. (mean) | cell-steps / s | min step, ms | diagnostics, us / cell |\n");
        std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
        for (const auto& r : steps) {
            const double cells = static_cast<double>(r.n) * r.n;
            const double per_step = r.seconds / r.steps;
            std::printf("| %d | %d^2 | %ld | %.3f | %.0f %% | %.0f %% | %.0f %% | %.1f | %.3g | %.1f | %.3f |\n", size,
                        r.n, r.steps, 1e6 * per_step / cells, 100 * r.sec_poisson / r.seconds,
                        100 * r.sec_momentum / r.seconds, 100 * r.sec_correction / r.seconds, r.iterations / r.steps,
                        cells / per_step, 1e3 * r.min_step, 1e6 * r.sec_diagnostics / r.steps / cells);
        }
        std::printf(
            "\n### Poisson solve alone (zero guess, tolerance 1e-8, all-Neumann, random zero-mean "
            "right-hand side, best of %d), %d rank%s\n\n",
            opt.poisson_repeats, size, size > 1 ? "s" : "");
        std::printf("| ranks | grid | iterations | solve, s | us / unknown | us / unknown / iteration |\n");
        std::printf("|---|---|---|---|---|---|\n");
        for (const auto& r : poisson) {
            const double cells = static_cast<double>(r.n) * r.n;
            std::printf("| %d | %d^2 | %d | %.4f | %.3f | %.4f |\n", size, r.n, r.iterations, r.seconds,
                        1e6 * r.seconds / cells, 1e6 * r.seconds / cells / std::max(1, r.iterations));
        }
        for (const auto& [n, rows] : kernels) {
            const double cells = static_cast<double>(n) * n;
            std::printf("\n### Parts of the step timed one by one from cold caches, %d^2, %d rank%s (best of 5)\n\n", n,
                        size, size > 1 ? "s" : "");
            std::printf(
                "| part | per step | us / cell | bytes / cell (model) | GB/s (all ranks) | of the triad |\n"
                "|---|---|---|---|---|---|\n");
            double step_seconds = 0.0, step_bytes = 0.0;
            for (const auto& k : rows) {
                const double gbs = k.bytes_per_cell * cells / k.seconds / 1e9;
                if (k.bytes_per_cell > 0)
                    std::printf("| %s | %d | %.4f | %.0f | %.1f | %.0f %% |\n", k.name.c_str(), k.per_step,
                                1e6 * k.seconds / cells, k.bytes_per_cell, gbs, 100 * gbs / triad_start.total_gbs);
                else
                    std::printf("| %s | %d | %.4f | - | - | - |\n", k.name.c_str(), k.per_step,
                                1e6 * k.seconds / cells);
                step_seconds += k.per_step * k.seconds;
                step_bytes += k.per_step * k.bytes_per_cell;
            }
            const double limit = step_bytes * cells / (triad_start.total_gbs * 1e9);
            std::printf(
                "\nOne step's parts: %.0f bytes per cell; at the triad's %.1f GB/s that is %.4f us / cell, the "
                "bandwidth limit; the parts take %.4f us / cell (%.1fx the limit)",
                step_bytes, triad_start.total_gbs, 1e6 * limit / cells, 1e6 * step_seconds / cells,
                step_seconds / limit);
            for (const auto& r : steps)
                if (r.n == n) {
                    const double per_cell = r.seconds / r.steps;
                    std::printf("; the whole step, timed above, %.4f us / cell (%.1fx the limit)",
                                1e6 * per_cell / cells, per_cell / limit);
                }
            std::printf(".\n");
        }
        if (opt.body) print_body_rows(body_rows, size);
        std::printf("\nLoad average at end: %s\n", load_average().c_str());
    }
    const bench::Triad triad_end = bench::measure_triad(MPI_COMM_WORLD);
    if (root) {
        std::printf("STREAM triad at the end: %.1f GB/s (%.1f per rank)\n", triad_end.total_gbs,
                    triad_end.per_rank_gbs);
        std::fflush(stdout);
    }

    HYPRE_Finalize();
    MPI_Finalize();
    return 0;
}
