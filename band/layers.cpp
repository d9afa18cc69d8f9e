#include "layers.hpp"

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
    // A modifier on each side and at least one fixed cell beyond it to remove.
    if (first_ < 2 || last_ > cells - 2)
        throw std::invalid_argument(key_ + ": modifier layers need at least two cells of the far-field width (the "
                                           "outermost cell's) between the block's zone and each end of the domain; "
                                           "use spacing clustered with `max` and a domain that extends beyond the "
                                           "block's path");
    for (int k = first_; k <= last_; ++k) offsets_.push_back(lines[k] - centre);
}

std::vector<double> AxisLayers::stretched(const std::vector<double>& lines, double centre) const {
    std::vector<double> out = lines;
    for (std::size_t k = 0; k < offsets_.size(); ++k) out[first_ + k] = centre + offsets_[k];
    if (!(out[first_] > out[first_ - 1]) || !(out[last_ + 1] > out[last_]))
        throw RunFailure(key_ + ": the block moved through a whole modifier layer in one step (the step is too "
                                "long for the far-field cells, or a layer change was missed)");
    return out;
}

std::optional<std::vector<double>> AxisLayers::change(const std::vector<double>& lines, double velocity) {
    const int cells = static_cast<int>(lines.size()) - 1;
    const double lower = lines[first_] - lines[first_ - 1], upper = lines[last_ + 1] - lines[last_];
    std::vector<double> out = lines;
    if (velocity < 0.0 && lower < below_ / 3.0) {
        // The lower modifier merges with the fixed cell below it; the upper one gets a line H below its fixed line.
        if (first_ - 1 < 1)
            throw RunFailure(key_ + ": the block's moving zone reached the domain's lower end (no fixed cell left "
                                    "below it to remove); extend the domain along its path");
        double added = lines[last_ + 1] - above_;
        if (added - lines[last_] < above_ / 3.0) added = 0.5 * (lines[last_] + lines[last_ + 1]);
        out.erase(out.begin() + (first_ - 1));
        --first_;
        --last_;
        out.insert(out.begin() + (last_ + 1), added);
    } else if (velocity > 0.0 && upper < above_ / 3.0) {
        if (last_ + 1 > cells - 1)
            throw RunFailure(key_ + ": the block's moving zone reached the domain's upper end (no fixed cell left "
                                    "above it to remove); extend the domain along its path");
        double added = lines[first_ - 1] + below_;
        if (lines[first_] - added < below_ / 3.0) added = 0.5 * (lines[first_ - 1] + lines[first_]);
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
    for (int f = 1; f + n < static_cast<int>(lines.size()); ++f) {
        bool match = true;
        for (int k = 0; k < n && match; ++k)
            match = std::abs(lines[f + k] - (centre + offsets_[k])) <= 1e-9 * (below_ + above_);
        if (match) {
            first_ = f;
            last_ = f + n - 1;
            return;
        }
    }
    throw std::invalid_argument(key_ + ": the restored grid has no rigid zone around the block at its offsets (a "
                                       "checkpoint of another case?)");
}

}  // namespace chute
