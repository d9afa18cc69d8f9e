#include "layers.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "run_failure.hpp"

namespace chute {

namespace {

bool same_width(double w, double h) { return std::abs(w - h) <= 1e-9 * h; }

}  // namespace

AxisLayers::AxisLayers(const std::vector<double>& lines, double centre, int hole_lower, int hole_upper,
                       const std::string& key)
    : key_(key) {
    const int cells = static_cast<int>(lines.size()) - 1;
    auto width = [&](int k) { return lines[k + 1] - lines[k]; };
    below_ = width(0);
    above_ = width(cells - 1);
    first_ = 0;
    while (first_ < hole_lower && same_width(width(first_), below_)) ++first_;
    last_ = cells;
    while (last_ > hole_upper && same_width(width(last_ - 1), above_)) --last_;
    // A modifier on each side (the cell beyond the zone); the fixed cells beyond are checked when one is needed.
    if (first_ < 1 || last_ > cells - 1)
        throw std::invalid_argument(key_ +
                                    ": modifier layers need a cell between the block's zone (its window and "
                                    "the growth up to the far-field width) and each end of the domain");
    for (int k = first_; k <= last_; ++k) offsets_.push_back(lines[k] - centre);
    hole_lower_ = hole_lower - first_;
    hole_upper_ = hole_upper - first_;
}

std::vector<double> AxisLayers::stretched(const std::vector<double>& lines, double centre) const {
    std::vector<double> out = lines;
    for (std::size_t k = 0; k < offsets_.size(); ++k) out[first_ + k] = centre + offsets_[k];
    if (!(out[first_] > out[first_ - 1]) || !(out[last_ + 1] > out[last_]))
        throw RunFailure(key_ +
                         ": the block moved through a whole modifier layer in one step (the step is too "
                         "long for the far-field cells, or a layer change was missed)");
    return out;
}

std::optional<std::vector<double>> AxisLayers::change(const std::vector<double>& lines, double velocity) {
    const int cells = static_cast<int>(lines.size()) - 1;
    const double lower = lines[first_] - lines[first_ - 1], upper = lines[last_ + 1] - lines[last_];
    // The fixed cell beyond each modifier (none at the domain's end).
    const double beyond_lower = first_ >= 2 ? lines[first_ - 1] - lines[first_ - 2] : 0.0;
    const double beyond_upper = last_ + 2 <= cells ? lines[last_ + 2] - lines[last_ + 1] : 0.0;
    std::vector<double> out = lines;
    if (velocity < 0.0 && lower < (beyond_lower > 0.0 ? beyond_lower : lower + upper) / 3.0) {
        // The lower modifier merges with the fixed cell below it; the upper one gets a line as far below its fixed
        // line as the merged cell was wide (or halfway if it is not thick enough), so the count stays.
        if (beyond_lower == 0.0)
            throw RunFailure(key_ +
                             ": the block's moving zone reached the domain's lower end (no fixed cell left "
                             "below it to remove); extend the domain along its path");
        double added = lines[last_ + 1] - beyond_lower;
        if (added - lines[last_] < beyond_lower / 3.0) added = 0.5 * (lines[last_] + lines[last_ + 1]);
        out.erase(out.begin() + (first_ - 1));
        --first_;
        --last_;
        out.insert(out.begin() + (last_ + 1), added);
    } else if (velocity > 0.0 && upper < (beyond_upper > 0.0 ? beyond_upper : lower + upper) / 3.0) {
        if (beyond_upper == 0.0)
            throw RunFailure(key_ +
                             ": the block's moving zone reached the domain's upper end (no fixed cell left "
                             "above it to remove); extend the domain along its path");
        double added = lines[first_ - 1] + beyond_upper;
        if (lines[first_] - added < beyond_upper / 3.0) added = 0.5 * (lines[first_ - 1] + lines[first_]);
        out.erase(out.begin() + (last_ + 1));
        out.insert(out.begin() + first_, added);
        ++first_;
        ++last_;
    } else {
        return std::nullopt;
    }
    ++changes_;
    return out;
}

void AxisLayers::locate(const std::vector<double>& lines, double centre) {
    const int n = static_cast<int>(offsets_.size());
    double smallest = below_;
    for (int k = 0; k + 1 < n; ++k) smallest = std::min(smallest, offsets_[k + 1] - offsets_[k]);
    for (int f = 1; f + n < static_cast<int>(lines.size()); ++f) {
        // The zone is rigid: its lines keep their spacings exactly, and sit near the offsets from the centre.
        const double shift = lines[f] - (centre + offsets_[0]);
        bool match = std::abs(shift) <= 0.25 * smallest;
        for (int k = 1; k < n && match; ++k)
            match = std::abs(lines[f + k] - (centre + offsets_[k]) - shift) <= 1e-9 * (below_ + above_);
        if (match) {
            first_ = f;
            last_ = f + n - 1;
            return;
        }
    }
    throw std::invalid_argument(key_ +
                                ": the restored grid has no rigid zone around the block at its offsets (a "
                                "checkpoint of another case?)");
}

}  // namespace chute
