#pragma once
// Shortest decimal text that reads back as the same double (std::to_chars round trip), so time values in
// CSV and XDMF files compare exactly after a restart.
#include <charconv>
#include <string>

namespace chute {

inline std::string exact_text(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

}  // namespace chute
