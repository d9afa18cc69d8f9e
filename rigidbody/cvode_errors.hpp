#pragma once
// CVODE's messages for the lumped models (lumped_model.cpp, hazard/trajectory.cpp): an error is kept for the
// exception cvode_check() throws; warnings are dropped. The one met in practice, "root functions identically 0"
// at the start of a step, comes from a block resting on or grazing the ground, which the callers settle;
// CVodeReInit re-arms it after every impact, so printed it floods the terminal (thousands of lines for a block
// started inside the bed's reach). Not re-entrant: one message slot per thread.
#include <string>

namespace chute {

// Routes `cvode_mem`'s messages to the slot cvode_check() reads.
void keep_cvode_errors(void* cvode_mem);
// Throws std::runtime_error "<who>: CVODE <what> failed (flag, CVODE's message)" if flag < 0.
void cvode_check(int flag, const char* what, const char* who);

}  // namespace chute
