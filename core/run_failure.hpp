#pragma once
// A run that cannot go on (the command-line tool's exit code 3): the method reached a bound it may not pass
// (the k-epsilon sub-steps of one step, the contact passes of one step, the impacts of a lumped trajectory)
// or left its stable regime (run/health_check.hpp). The message names the cause and the case keys behind it;
// the run loop keeps the outputs written so far and says where they are.
#include <stdexcept>

namespace chute {

class RunFailure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace chute
