#pragma once
// Small text helpers shared by the tools: a whole file as a string, printf-style formatting into a string, and
// Debian's libfccp CSV reader (io::CSVReader, header-only) included once with its warning silenced.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#define CSV_IO_NO_THREAD  // the files read are small: no reading thread
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-truncation"  // its file-name copy for messages, cut at 255 on purpose
#include <libfccp/csv.h>
#pragma GCC diagnostic pop

namespace chute {

// The file's text ("" if it cannot be read: callers check existence first where it matters).
inline std::string read_text_file(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// snprintf into a string (lines of tables and summaries; up to 511 characters).
inline std::string printf_text(const char* format, auto... args) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, format, args...);
    return buffer;
}

}  // namespace chute
