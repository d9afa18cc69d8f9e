#pragma once
// The kinds of carrier a run can choose (body/carrier.hpp), by name. "immersed" (ibm/) is registered here;
// a new kind of carrier registers its factory once and needs nothing else of run/, rigidbody/, contact/ or
// turbulence/ (tests/unit/test_carrier_seam.cpp registers one).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "carrier.hpp"
#include "case_config.hpp"

namespace chute {

using CarrierFactory =
    std::function<std::unique_ptr<Carrier>(const Grid& grid, const CaseConfig& config, std::vector<Body>& bodies)>;

void register_carrier(const std::string& name, CarrierFactory factory);
// Throws std::invalid_argument listing the registered names when `name` is not one of them.
std::unique_ptr<Carrier> make_carrier(const std::string& name, const Grid& grid, const CaseConfig& config,
                                      std::vector<Body>& bodies);

}  // namespace chute
