#pragma once
// Running the chute binary (CHUTE_BINARY) from a test: as a shell command to wait for, or spawned in the
// background to watch and signal. Single-rank only: a child of an mpirun-launched rank fails in MPI_Init
// (tests/CMakeLists.txt), so tests using this skip themselves on more than one rank.
#include <mpi.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

extern char** environ;

namespace chute_test {

namespace fs = std::filesystem;

inline bool single_rank() {
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return size == 1;
}

// A fresh, empty folder for one test (single rank).
inline fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("chute_test_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

inline std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void write_text(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// The exit code of a wait status the way a shell reports it: the code, or 128 + the signal number.
inline int exit_code(int status) {
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    return -1;
}

struct CommandResult {
    int exit_code;
    std::string output;
};

// Runs a shell command line, its output (stdout and stderr) into dir/command.log.
inline CommandResult run_shell(const std::string& command, const fs::path& dir) {
    const fs::path log = dir / "command.log";
    const int status = std::system((command + " > '" + log.string() + "' 2>&1").c_str());
    return {exit_code(status), read_text(log)};
}

// `chute <args>`; `args` is shell text (quote paths).
inline CommandResult run_chute(const std::string& args, const fs::path& dir) {
    return run_shell(std::string(CHUTE_BINARY) + " " + args, dir);
}

// `chute <args>` in the background, its output into `log`; the process is chute itself (sh execs it).
class ChuteProcess {
public:
    ChuteProcess(const std::string& args, const fs::path& log) {
        const std::string command = "exec " + std::string(CHUTE_BINARY) + " " + args + " > '" + log.string() + "' 2>&1";
        const char* argv[] = {"sh", "-c", command.c_str(), nullptr};
        if (posix_spawn(&pid_, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ) != 0)
            throw std::runtime_error("cannot start " + command);
    }
    ~ChuteProcess() {
        if (pid_ > 0) {  // a test that failed half-way: do not leave the run behind
            ::kill(pid_, SIGKILL);
            wait();
        }
    }
    ChuteProcess(const ChuteProcess&) = delete;
    ChuteProcess& operator=(const ChuteProcess&) = delete;

    pid_t pid() const { return pid_; }
    // True while the process has not ended (its status is then collected by wait()).
    bool running() const {
        siginfo_t info{};
        return pid_ > 0 && ::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
               info.si_pid == 0;
    }
    // Waits for the end; the exit code, or 128 + the signal that ended it.
    int wait() {
        int status = 0;
        while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
        }
        pid_ = -1;
        return exit_code(status);
    }

private:
    pid_t pid_ = -1;
};

// The command ("unshare -m" as root, "unshare -rm" in a user namespace otherwise) that gives a shell its own
// mount namespace in which it may mount a tmpfs; the mounts vanish with it. Empty if neither works here
// (a container without CAP_SYS_ADMIN and without user namespaces).
inline std::string private_mount_command(const fs::path& dir) {
    const fs::path point = dir / "mount_probe";
    fs::create_directories(point);
    for (const char* unshare : {"unshare -m", "unshare -rm"}) {
        const std::string probe = std::string(unshare) + " sh -c \"mount -t tmpfs -o size=64k tmpfs '" +
                                  point.string() + "'\" > /dev/null 2>&1";
        if (std::system(probe.c_str()) == 0) return unshare;
    }
    return "";
}

}  // namespace chute_test
