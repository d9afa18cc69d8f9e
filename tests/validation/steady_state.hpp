#pragma once
// Helpers shared by the validation tests: run a case to a steady state, read reference tables.
#include <mpi.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "flow_solver.hpp"

namespace chute::validation {

// Advances until the velocity changes by less than `rate` (max |du/dt| over all faces, 1/s in units of
// the velocity scale) over a window of `window` seconds, or until t_max. Returns the last measured rate.
inline double run_to_steady_state(FlowSolver& s, double rate, double window, double t_max) {
    Velocity before = s.velocity();
    double t_before = s.time(), measured = INFINITY;
    while (s.time() < t_max) {
        s.advance();
        if (s.time() - t_before < window) continue;
        double m = 0.0;
        for (int j = 0; j < s.grid().ny(); ++j)
            for (int i = 0; i < s.grid().nx(); ++i) {
                m = std::max(m, std::abs(s.velocity().u(i, j) - before.u(i, j)));
                m = std::max(m, std::abs(s.velocity().v(i, j) - before.v(i, j)));
            }
        MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_MAX, s.grid().comm());
        measured = m / (s.time() - t_before);
        if (measured < rate) break;
        before = s.velocity();
        t_before = s.time();
    }
    return measured;
}

// Whitespace-separated numeric table; lines starting with '#' are comments.
inline std::vector<std::vector<double>> read_table(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open reference table " + path);
    std::vector<std::vector<double>> rows;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ls(line);
        std::vector<double> row;
        double v;
        while (ls >> v) row.push_back(v);
        if (!row.empty()) rows.push_back(row);
    }
    return rows;
}

// Linear interpolation of (xs, ys), xs increasing.
inline double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
    if (x <= xs.front()) return ys.front();
    if (x >= xs.back()) return ys.back();
    std::size_t k = 1;
    while (xs[k] < x) ++k;
    const double f = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
    return ys[k - 1] + f * (ys[k] - ys[k - 1]);
}

}  // namespace chute::validation
