#pragma once
// A result file could not be written: the disk is full, a file size limit (ulimit -f) was reached, or the
// results folder is missing, read-only or not a folder. The run stops (chute exits with code 4); every file
// written before is complete, since each is written to a temporary name and renamed (hdf5_file.hpp).
#include <filesystem>
#include <stdexcept>
#include <string>

namespace chute {

class OutputError : public std::runtime_error {
public:
    // "cannot write '<file>': <cause>"
    OutputError(const std::filesystem::path& file, const std::string& cause)
        : std::runtime_error("cannot write '" + file.string() + "': " + cause) {}
    // A message already made: an OutputError relayed from another rank (gather.hpp), or one with more said.
    explicit OutputError(const std::string& message) : std::runtime_error(message) {}
};

// The text of a C errno value ("No space left on device"), with its symbolic number for searches.
std::string errno_text(int error);

}  // namespace chute
