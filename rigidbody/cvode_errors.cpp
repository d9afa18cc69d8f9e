#include "cvode_errors.hpp"

#include <cvode/cvode.h>

#include <stdexcept>

namespace chute {

namespace {

thread_local std::string last_error;

extern "C" void keep_error(int code, const char*, const char* function, char* message, void*) {
    if (code < 0) last_error = std::string(function) + ": " + message;
}

}  // namespace

void keep_cvode_errors(void* cvode_mem) {
    last_error.clear();
    cvode_check(CVodeSetErrHandlerFn(cvode_mem, keep_error, nullptr), "CVodeSetErrHandlerFn", "CVODE");
}

void cvode_check(int flag, const char* what, const char* who) {
    if (flag < 0)
        throw std::runtime_error(std::string(who) + ": CVODE " + what + " failed (flag " + std::to_string(flag) +
                                 (last_error.empty() ? "" : ", " + last_error) + ")");
}

}  // namespace chute
