#include "results_folder.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <system_error>

#include "output_error.hpp"

namespace chute {

namespace {

// A temporary that write_atomically() makes: an output's name (of the kinds Chute writes) + ".tmp".
bool is_left_temporary(const std::string& name) {
    if (!name.ends_with(".tmp")) return false;
    const std::string target = name.substr(0, name.size() - 4);
    for (const char* ext : {".h5", ".csv", ".xdmf", ".txt", ".yaml", ".png"})
        if (target.ends_with(ext)) return true;
    return false;
}

}  // namespace

std::vector<std::string> prepare_results_folder(const std::filesystem::path& folder) {
    const std::string where = "the results folder '" + folder.string() + "'";
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw OutputError("cannot make " + where + ": " + ec.message());
    if (!std::filesystem::is_directory(folder, ec)) throw OutputError(where + " is not a folder");

    // One byte is enough to meet a read-only folder, a missing permission or a disk already full.
    const std::filesystem::path probe = folder / ".chute_write_probe.tmp";
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw OutputError("cannot write in " + where + ": " + errno_text(errno));
    const char byte = '\n';
    const int error = ::write(fd, &byte, 1) == 1 ? 0 : errno;
    ::close(fd);
    std::filesystem::remove(probe, ec);
    if (error != 0) throw OutputError("cannot write in " + where + ": " + errno_text(error));

    std::vector<std::string> removed;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        if (is_left_temporary(name) && entry.is_regular_file(ec) && std::filesystem::remove(entry.path(), ec))
            removed.push_back(name);
    }
    std::sort(removed.begin(), removed.end());
    return removed;
}

}  // namespace chute
