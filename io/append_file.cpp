#include "append_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <utility>

#include "output_error.hpp"

namespace chute {

AppendFile::AppendFile(std::filesystem::path path) : path_(std::move(path)) {
    fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    struct stat st {};
    if (fd_ < 0 || ::fstat(fd_, &st) != 0) {
        const int error = errno;
        if (fd_ >= 0) ::close(fd_);
        fd_ = -1;
        throw OutputError(path_, "cannot open it for appending: " + errno_text(error));
    }
    size_ = static_cast<long long>(st.st_size);
}

AppendFile::AppendFile(AppendFile&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), size_(other.size_), path_(std::move(other.path_)) {}

AppendFile& AppendFile::operator=(AppendFile&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) ::close(fd_);
        fd_ = std::exchange(other.fd_, -1);
        size_ = other.size_;
        path_ = std::move(other.path_);
    }
    return *this;
}

AppendFile::~AppendFile() {
    if (fd_ >= 0) ::close(fd_);
}

void AppendFile::append(const std::string& text) {
    if (fd_ < 0) throw OutputError(path_, "the file is not open");
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : ENOSPC;  // a write of 0 bytes: nothing more fits
            // Cut back to the last whole line; shrinking a file needs no space.
            (void)::ftruncate(fd_, static_cast<off_t>(size_));
            throw OutputError(path_, errno_text(error) + " (the file is kept up to its last whole line)");
        }
        done += static_cast<std::size_t>(n);
    }
    size_ += static_cast<long long>(text.size());
}

}  // namespace chute
