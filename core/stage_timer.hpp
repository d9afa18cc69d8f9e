#pragma once
// Wall time spent in each named stage of the time step, summed over the steps of a run (seconds). The run
// summary and the benchmarks print it as shares; stages appear in the order they were first timed.
//
//   StageTimer timer;
//   { auto scope = timer.scope("poisson"); solve(); }      // adds the scope's wall time to "poisson"
// A null StageTimer* gives scopes that time nothing, so a solver can be used with or without one.
#include <chrono>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace chute {

class StageTimer {
public:
    class Scope {
    public:
        Scope(StageTimer* timer, std::string_view stage)
            : timer_(timer), stage_(stage), start_(timer ? clock::now() : clock::time_point{}) {}
        ~Scope() {
            if (timer_) timer_->add(stage_, std::chrono::duration<double>(clock::now() - start_).count());
        }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        using clock = std::chrono::steady_clock;
        StageTimer* timer_;
        std::string_view stage_;
        clock::time_point start_;
    };

    StageTimer() = default;
    // Stages listed in this order whatever order they first run in (those that never run stay at zero).
    explicit StageTimer(std::span<const std::string_view> order) {
        for (std::string_view stage : order) stages_.emplace_back(std::string(stage), 0.0);
    }

    Scope scope(std::string_view stage) { return Scope(this, stage); }
    void add(std::string_view stage, double seconds) {
        for (auto& [name, total] : stages_)
            if (name == stage) {
                total += seconds;
                return;
            }
        stages_.emplace_back(std::string(stage), seconds);
    }
    double seconds(std::string_view stage) const {
        for (const auto& [name, total] : stages_)
            if (name == stage) return total;
        return 0.0;
    }
    double total() const {
        double s = 0.0;
        for (const auto& st : stages_) s += st.second;
        return s;
    }
    const std::vector<std::pair<std::string, double>>& stages() const { return stages_; }
    void reset() {
        for (auto& st : stages_) st.second = 0.0;
    }

private:
    std::vector<std::pair<std::string, double>> stages_;
};

}  // namespace chute
