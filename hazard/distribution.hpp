#pragma once
// A quantity of a hazard analysis that varies from one trajectory to the next (block size and density, release
// point and speed, a material's restitution and friction): fixed, uniform, normal or lognormal, as rockfall
// codes give them (RocFall, Rocscience). Normal and lognormal may be truncated to [min, max] (by rejection, so
// the shape inside is kept). In the case file:
//   size: {distribution: normal, mean: 0.3, sd: 0.05, min: 0.1}
//   density: {distribution: uniform, min: 2500, max: 2800}
//   height: {value: 1.0}                                   (fixed; the default distribution)
// Lognormal takes the mean and standard deviation of the quantity itself (not of its logarithm).
#include <deque>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace chute {

struct CaseKey;
class CaseReader;

enum class DistributionKind { fixed, uniform, normal, lognormal };

class Distribution {
public:
    static Distribution fixed(double value);
    static Distribution uniform(double min, double max);
    static Distribution normal(double mean, double sd, std::optional<double> min = {}, std::optional<double> max = {});
    static Distribution lognormal(double mean, double sd, std::optional<double> min = {},
                                  std::optional<double> max = {});

    DistributionKind kind() const { return kind_; }
    double mean() const;  // of the untruncated distribution (fixed: the value; uniform: the midpoint)
    // Smallest and largest value a draw can take (infinite where unbounded).
    double lowest() const;
    double highest() const;
    double sample(std::mt19937_64& rng) const;

private:
    DistributionKind kind_ = DistributionKind::fixed;
    double a_ = 0.0, b_ = 0.0;  // fixed: value; uniform: min, max; normal: mean, sd; lognormal: mean, sd
    std::optional<double> min_, max_;
};

// The limits a quantity must keep (a size above 0, a restitution within [0, 1]); the reading checks that no
// draw can leave them, and names the key to add (a truncation) when one could.
struct QuantityLimits {
    std::optional<double> above = {}, at_least = {}, at_most = {};
};

// The schema's keys of a distributed quantity at `path` (a section with distribution, value, min, max, mean,
// sd). Their paths are kept in `storage`, which must outlive the keys.
std::vector<CaseKey> distribution_keys(std::deque<std::string>& storage, const std::string& path,
                                       const std::string& units, const std::string& meaning,
                                       const std::string& default_value = {});
// Reads and checks it against `limits` (a CaseError naming the key otherwise). A quantity declared without a
// default must be given (`required`).
Distribution read_distribution(const CaseReader& reader, const std::string& path, const QuantityLimits& limits,
                               bool required = false);

// The random numbers of trajectory `index` of a run seeded with `seed`: the same on any number of ranks.
std::mt19937_64 trajectory_rng(unsigned long long seed, unsigned long long index);

}  // namespace chute
