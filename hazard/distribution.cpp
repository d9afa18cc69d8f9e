#include "distribution.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "case_reader.hpp"

namespace chute {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// Lognormal: the parameters of ln X from the mean m and standard deviation s of X.
double log_sd(double m, double s) { return std::sqrt(std::log1p(s * s / (m * m))); }
double log_mean(double m, double s) { return std::log(m) - 0.5 * std::pow(log_sd(m, s), 2); }

}  // namespace

Distribution Distribution::fixed(double value) {
    Distribution d;
    d.kind_ = DistributionKind::fixed;
    d.a_ = value;
    return d;
}

Distribution Distribution::uniform(double min, double max) {
    if (!(min < max)) throw std::invalid_argument("uniform distribution: min must be below max");
    Distribution d;
    d.kind_ = DistributionKind::uniform;
    d.a_ = min, d.b_ = max;
    return d;
}

Distribution Distribution::normal(double mean, double sd, std::optional<double> min, std::optional<double> max) {
    if (!(sd > 0.0)) throw std::invalid_argument("normal distribution: sd must be positive");
    if (min && max && !(*min < *max)) throw std::invalid_argument("normal distribution: min must be below max");
    Distribution d;
    d.kind_ = DistributionKind::normal;
    d.a_ = mean, d.b_ = sd, d.min_ = min, d.max_ = max;
    return d;
}

Distribution Distribution::lognormal(double mean, double sd, std::optional<double> min, std::optional<double> max) {
    if (!(mean > 0.0)) throw std::invalid_argument("lognormal distribution: mean must be positive");
    Distribution d = normal(mean, sd, min, max);
    d.kind_ = DistributionKind::lognormal;
    return d;
}

double Distribution::mean() const { return kind_ == DistributionKind::uniform ? 0.5 * (a_ + b_) : a_; }

double Distribution::lowest() const {
    switch (kind_) {
        case DistributionKind::fixed:
        case DistributionKind::uniform:
            return a_;
        case DistributionKind::normal:
            return min_.value_or(-infinity);
        case DistributionKind::lognormal:
            return min_.value_or(0.0);
    }
    return a_;
}

double Distribution::highest() const {
    switch (kind_) {
        case DistributionKind::fixed:
            return a_;
        case DistributionKind::uniform:
            return b_;
        default:
            return max_.value_or(infinity);
    }
}

double Distribution::sample(std::mt19937_64& rng) const {
    switch (kind_) {
        case DistributionKind::fixed:
            return a_;
        case DistributionKind::uniform:
            return std::uniform_real_distribution<double>(a_, b_)(rng);
        default:
            break;
    }
    // Truncation by rejection keeps the shape inside [min, max]; the reading refuses a window that holds
    // less than a millionth of the distribution, so this ends.
    const bool log = kind_ == DistributionKind::lognormal;
    std::normal_distribution<double> gauss(log ? log_mean(a_, b_) : a_, log ? log_sd(a_, b_) : b_);
    for (;;) {
        const double g = gauss(rng);
        const double v = log ? std::exp(g) : g;
        if ((!min_ || v >= *min_) && (!max_ || v <= *max_)) return v;
    }
}

std::vector<CaseKey> distribution_keys(std::deque<std::string>& storage, const std::string& path,
                                       const std::string& units, const std::string& meaning,
                                       const std::string& default_value) {
    using K = KeyType;
    const auto keep = [&](const std::string& s) -> std::string_view { return storage.emplace_back(s); };
    const std::string_view u = keep(units);
    const std::vector<std::string_view> truncated{"uniform", "normal", "lognormal"};
    const std::vector<std::string_view> shaped{"normal", "lognormal"};
    return {
        {.path = keep(path),
         .type = K::section,
         .meaning = keep(meaning + (default_value.empty() ? " Required." : " Default: " + default_value + "."))},
        {.path = keep(path + ".distribution"),
         .type = K::choice,
         .default_value = "fixed",
         .choices = {"fixed", "uniform", "normal", "lognormal"},
         .meaning = "How it varies from one trajectory to the next (lognormal: mean and sd of the quantity)."},
        {.path = keep(path + ".value"),
         .type = K::number,
         .required = default_value.empty(),
         .default_value = keep(default_value),
         .when_key = "distribution",
         .when_values = {"fixed"},
         .units = u,
         .meaning = "The value of every trajectory."},
        {.path = keep(path + ".min"),
         .type = K::number,
         .required = false,
         .when_key = "distribution",
         .when_values = truncated,
         .units = u,
         .meaning = "Lowest value (uniform: required; normal and lognormal: a truncation, optional)."},
        {.path = keep(path + ".max"),
         .type = K::number,
         .when_key = "distribution",
         .when_values = truncated,
         .units = u,
         .meaning = "Highest value (uniform: required; normal and lognormal: a truncation, optional)."},
        {.path = keep(path + ".mean"),
         .type = K::number,
         .required = true,
         .when_key = "distribution",
         .when_values = shaped,
         .units = u,
         .meaning = "Mean of the quantity."},
        {.path = keep(path + ".sd"),
         .type = K::number,
         .required = true,
         .min = above(0.0),
         .when_key = "distribution",
         .when_values = shaped,
         .units = u,
         .meaning = "Standard deviation of the quantity."},
    };
}

Distribution read_distribution(const CaseReader& r, const std::string& path, const QuantityLimits& limits,
                               bool required) {
    if (required && !r.present(path)) r.fail(path, "missing required key (give its value or its distribution)");
    const std::string kind = r.choice(path + ".distribution");
    const auto optional = [&](const std::string& key) -> std::optional<double> {
        return r.present(key) ? std::optional<double>(r.number(key)) : std::nullopt;
    };
    Distribution d;
    if (kind == "fixed") {
        d = Distribution::fixed(r.number(path + ".value"));
    } else if (kind == "uniform") {
        for (const char* key : {".min", ".max"})
            if (!r.present(path + key)) r.fail(path + key, "missing required key (a uniform distribution's bound)");
        const double lo = r.number(path + ".min"), hi = r.number(path + ".max");
        if (!(lo < hi)) r.fail(path + ".max", "must be above " + path + ".min (" + exact_text(lo) + ")");
        d = Distribution::uniform(lo, hi);
    } else {
        const double mean = r.number(path + ".mean"), sd = r.number(path + ".sd");
        const std::optional<double> lo = optional(path + ".min"), hi = optional(path + ".max");
        if (lo && hi && !(*lo < *hi)) r.fail(path + ".max", "must be above " + path + ".min (" + exact_text(*lo) + ")");
        if (kind == "lognormal" && !(mean > 0.0))
            r.fail(path + ".mean", "a lognormal distribution's mean must be positive");
        // The window must hold a fair share of the distribution (rejection sampling), and the mean must lie
        // within a few standard deviations of it.
        if ((lo && *lo > mean + 4.0 * sd) || (hi && *hi < mean - 4.0 * sd))
            r.fail(path + (lo && *lo > mean + 4.0 * sd ? ".min" : ".max"),
                   "the truncation leaves almost nothing of the distribution (more than 4 sd from the mean)");
        d = kind == "normal" ? Distribution::normal(mean, sd, lo, hi) : Distribution::lognormal(mean, sd, lo, hi);
    }
    // No draw may leave the quantity's limits.
    const double lo = d.lowest(), hi = d.highest();
    const bool shaped = kind == "normal" || kind == "lognormal";
    const auto key_for = [&](const char* bound) { return path + (kind == "fixed" ? ".value" : bound); };
    const auto hint = [&](const char* bound) {
        return shaped
                   ? std::string(" (a ") + kind + " distribution reaches there: truncate it with " + path + bound + ")"
                   : std::string();
    };
    if (limits.above && !(lo > *limits.above))
        r.fail(key_for(".min"), "must be above " + exact_text(*limits.above) + hint(".min"));
    if (limits.at_least && !(lo >= *limits.at_least))
        r.fail(key_for(".min"), "must be at least " + exact_text(*limits.at_least) + hint(".min"));
    if (limits.at_most && !(hi <= *limits.at_most))
        r.fail(key_for(".max"), "must be at most " + exact_text(*limits.at_most) + hint(".max"));
    return d;
}

std::mt19937_64 trajectory_rng(unsigned long long seed, unsigned long long index) {
    // SplitMix64 of (seed, index): neighbouring indices give unrelated streams (Steele, Lea & Flood 2014).
    unsigned long long z = seed * 0x9E3779B97F4A7C15ULL + index + 0x632BE59BD9B4E019ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    std::seed_seq seq{static_cast<unsigned>(z), static_cast<unsigned>(z >> 32), static_cast<unsigned>(index)};
    return std::mt19937_64(seq);
}

}  // namespace chute
