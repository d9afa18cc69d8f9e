#include "output_error.hpp"

#include <cstring>

namespace chute {

std::string errno_text(int error) {
    const char* name = strerrorname_np(error);  // glibc: "ENOSPC"
    return std::string(std::strerror(error)) + (name != nullptr ? " (" + std::string(name) + ")" : "");
}

}  // namespace chute
