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
    const bool lower_closed = !(out[first_] > out[first_ - 1]), upper_closed = !(out[last_ + 1] > out[last_]);
    const int zone_top = static_cast<int>(offsets_.size()) - 1;
    if ((lower_closed && first_ == 1 && hole_lower_ == 0) ||
        (upper_closed && last_ + 2 == static_cast<int>(lines.size()) && hole_upper_ == zone_top))
        throw RunFailure(key_ + ": the block reached the domain's " + (lower_closed ? "lower" : "upper") +
                         " end (the layers between had all been removed); contact of a body_fitted body is not "
                         "built yet: end the run before (time.end) or use the immersed carrier");
    if (lower_closed || upper_closed)
        throw RunFailure(key_ +
                         ": the block moved through a whole modifier layer in one step (the step is too "
                         "long for the far-field cells, or a layer change was missed)");
    return out;
}

std::optional<std::vector<double>> AxisLayers::change(const std::vector<double>& lines, double velocity) {
    const int cells = static_cast<int>(lines.size()) - 1;
    const int zone_top = static_cast<int>(offsets_.size()) - 1;  // the zone's top line, from first_
    std::vector<double> out = lines;
    if (velocity < 0.0) {
        // The lower modifier merges with the fixed cell below it or, at the domain's end, with the zone's lowest cell
        // (the zone compresses towards the wall, down to the block's own side: then the modifier is the gap).
        const bool fixed_below = first_ >= 2, zone_below = hole_lower_ > 0;
        if (!fixed_below && !zone_below) return std::nullopt;
        const double beyond = fixed_below ? lines[first_ - 1] - lines[first_ - 2] : lines[first_ + 1] - lines[first_];
        if (lines[first_] - lines[first_ - 1] >= beyond / 3.0) return std::nullopt;
        // The upper modifier gets a line as far below its fixed line as the merged cell was wide (halfway if it is not
        // thick enough), so the count stays.
        double added = lines[last_ + 1] - beyond;
        if (added - lines[last_] < beyond / 3.0) added = 0.5 * (lines[last_] + lines[last_ + 1]);
        if (fixed_below) {
            out.erase(out.begin() + (first_ - 1));
            --first_;
        } else {
            out.erase(out.begin() + first_);
            offsets_.erase(offsets_.begin());
            --hole_lower_;
            --hole_upper_;
            ++trimmed_[0];
        }
        --last_;
        out.insert(out.begin() + (last_ + 1), added);
    } else if (velocity > 0.0) {
        const bool fixed_above = last_ + 2 <= cells, zone_above = hole_upper_ < zone_top;
        if (!fixed_above && !zone_above) return std::nullopt;
        const double beyond = fixed_above ? lines[last_ + 2] - lines[last_ + 1] : lines[last_] - lines[last_ - 1];
        if (lines[last_ + 1] - lines[last_] >= beyond / 3.0) return std::nullopt;
        double added = lines[first_ - 1] + beyond;
        if (lines[first_] - added < beyond / 3.0) added = 0.5 * (lines[first_ - 1] + lines[first_]);
        if (fixed_above) {
            out.erase(out.begin() + (last_ + 1));
        } else {
            out.erase(out.begin() + last_);
            offsets_.pop_back();
            --last_;
            ++trimmed_[1];
        }
        out.insert(out.begin() + first_, added);
        ++first_;
        ++last_;
    } else {
        return std::nullopt;
    }
    ++changes_;
    return out;
}

double AxisLayers::hierarchy_centre(const std::vector<double>& lines, double centre) const {
    // Far from walls a whole far-field cell: the hierarchy is set up a quarter as often as with a quarter cell, for
    // 6.0 PCG iterations per step against 5.8 (the study's free fall). Near a wall (the zone compressed) a quarter:
    // the gap is the cell that stretches, and a whole cell there took 7.3 against 5.7 (the bed bounce).
    const double quantum = (trimmed_[0] + trimmed_[1] > 0 ? 0.25 : 1.0) * far_width();
    const double rounded = std::round(centre / quantum);
    // Both modifiers open, at least a tenth of the smaller of their widths now (the cycle is set up on a nearby grid).
    const double now = std::min(lines[first_] - lines[first_ - 1], lines[last_ + 1] - lines[last_]);
    auto keeps_open = [&](double c) {
        return c + offsets_.front() - lines[first_ - 1] >= 0.1 * now &&
               lines[last_ + 1] - (c + offsets_.back()) >= 0.1 * now;
    };
    for (double shift : {0.0, 1.0, -1.0})
        if (keeps_open((rounded + shift) * quantum)) return (rounded + shift) * quantum;
    return centre;
}

void AxisLayers::trim(int below, int above) {
    for (int k = 0; k < below; ++k) {
        offsets_.erase(offsets_.begin());
        --hole_lower_;
        --hole_upper_;
    }
    for (int k = 0; k < above; ++k) offsets_.pop_back();
    last_ = first_ + static_cast<int>(offsets_.size()) - 1;
    trimmed_ = {trimmed_[0] + below, trimmed_[1] + above};
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
