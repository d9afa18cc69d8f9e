#pragma once
// A text file that grows by whole lines (the time series' CSV files): one write per line, so a run that is
// killed leaves at most its last line cut short, and a write that fails (full disk, file size limit) is cut
// back to the last whole line before it throws, so the file stays a clean prefix that a restart continues.
// Rewriting the whole file atomically at every row would cost O(rows^2); the HDF5 copies are atomic.
#include <filesystem>
#include <string>

namespace chute {

class AppendFile {
public:
    AppendFile() = default;
    // Opens an existing file for appending; throws OutputError naming it if it cannot be opened.
    explicit AppendFile(std::filesystem::path path);
    AppendFile(AppendFile&& other) noexcept;
    AppendFile& operator=(AppendFile&& other) noexcept;
    AppendFile(const AppendFile&) = delete;
    AppendFile& operator=(const AppendFile&) = delete;
    ~AppendFile();

    // Appends `text` whole, or throws OutputError naming the file and the system's reason, the file cut back
    // to its length before the call.
    void append(const std::string& text);

private:
    int fd_ = -1;
    long long size_ = 0;  // bytes written and kept so far
    std::filesystem::path path_;
};

}  // namespace chute
