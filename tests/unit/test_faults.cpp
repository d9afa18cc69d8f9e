// Faults around the results (issue 14, item 4): a full disk, a file size limit, a results folder that cannot
// be written, and a run killed (SIGKILL) while writing a checkpoint. Each must stop the run with a clear
// message and exit code 4 (or 137 for the kill), keep every file written before whole, and leave a
// checkpoint that restarts. WriteFailure.* run in this process (any rank count); Faults.* run the chute
// binary (single rank only, see chute_process.hpp) and skip where the privilege they need is missing.
#include <gtest/gtest.h>
#include <mpi.h>
#include <poll.h>
#include <sys/inotify.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <thread>
#include <vector>

#include "append_file.hpp"
#include "checkpoint.hpp"
#include "chute_process.hpp"
#include "hdf5_file.hpp"
#include "output_error.hpp"

using namespace chute;
using namespace chute_test;

namespace {

int world_rank() {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return rank;
}

// Lowers this process's file size limit (ulimit -f) for a scope, with SIGXFSZ ignored as chute does, so a
// write past it fails with EFBIG instead of killing the process. Unprivileged: the soft limit only.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &old_);
        old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
        const rlimit lower{bytes, old_.rlim_max};
        setrlimit(RLIMIT_FSIZE, &lower);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &old_);
        std::signal(SIGXFSZ, old_handler_);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
    rlimit old_{};
    void (*old_handler_)(int) = SIG_DFL;
};

bool has_tmp_file(const fs::path& dir) {
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".tmp") return true;
    return false;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The line of `text` that holds `part` (all of `text` if none does): the message of a log.
std::string line_with(const std::string& text, const std::string& part) {
    const std::size_t at = text.find(part);
    if (at == std::string::npos) return text;
    const std::size_t newline = text.rfind('\n', at), end = text.find('\n', at);
    const std::size_t begin = newline == std::string::npos ? 0 : newline + 1;
    return text.substr(begin, end == std::string::npos ? end : end - begin);
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

}  // namespace

// ---- In this process: the writers under a file size limit ---------------------------------------------

// A line that does not fit is cut back: the file keeps its whole lines and nothing of the failed one, so a
// restart continues it cleanly (timeseries.hpp).
TEST(WriteFailure, AppendPastTheFileSizeLimitKeepsWholeLines) {
    if (world_rank() != 0) return;
    const fs::path dir = fs::temp_directory_path() / ("chute_test_append_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path file = dir / "series.csv";
    write_text(file, "t,x\n");
    AppendFile csv(file);
    csv.append("0.1,1\n");
    {
        FileSizeLimit limit(fs::file_size(file) + 20);  // room for part of the next line only
        try {
            csv.append("0.2,2.000000000000000000000000000000000000001\n");
            ADD_FAILURE() << "a line past the file size limit was written";
        } catch (const OutputError& e) {
            EXPECT_TRUE(contains(e.what(), file.string())) << e.what();
            EXPECT_TRUE(contains(e.what(), "File too large")) << e.what();
        }
    }
    EXPECT_EQ(read_text(file), "t,x\n0.1,1\n");
    csv.append("0.2,2\n");  // and the file goes on once there is room again
    EXPECT_EQ(read_text(file), "t,x\n0.1,1\n0.2,2\n");
    fs::remove_all(dir);
}

// An HDF5 file that cannot be written whole: an OutputError naming the file and the system's reason, the
// older file of that name untouched, no temporary left. (Before HDF5 files were built in memory, HDF5 1.10
// left a file whose flush failed half-closed and the process crashed at exit: this test would then end the
// test process with SIGSEGV.)
TEST(WriteFailure, Hdf5FilePastTheFileSizeLimitKeepsTheOlderFile) {
    if (world_rank() != 0) return;
    const fs::path dir = fs::temp_directory_path() / ("chute_test_h5limit_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path target = dir / "data.h5";
    const auto write = [&](double value) {
        write_atomically(target, [&](const fs::path& tmp) {
            Hdf5File f = Hdf5File::create(tmp);
            f.write("values", std::vector<double>(4096, value));  // 32 KiB
            f.close();
        });
    };
    write(1.0);
    {
        FileSizeLimit limit(8192);
        try {
            write(2.0);
            ADD_FAILURE() << "an HDF5 file past the file size limit was written";
        } catch (const OutputError& e) {
            EXPECT_TRUE(contains(e.what(), target.string())) << e.what();
            EXPECT_TRUE(contains(e.what(), "File too large")) << e.what();
        }
    }
    EXPECT_FALSE(has_tmp_file(dir));
    EXPECT_EQ(Hdf5File::open_read(target).read("values"), std::vector<double>(4096, 1.0));
    fs::remove_all(dir);
}

// ---- The chute binary ---------------------------------------------------------------------------------

namespace {

// The lid-driven cavity on 16 x 16 cells with a fixed step (a restart is then bit for bit), writing fields
// and a checkpoint every 4 steps and keeping every checkpoint, so that a small disk fills up mid-run.
const char* kCavity = R"(
name: fault_cavity
domain:
  x: {start: 0.0, end: 1.0, cells: 16}
  y: {start: 0.0, end: 1.0, cells: 16}
fluid: {viscosity: 0.01}
boundaries:
  left: {type: wall}
  right: {type: wall}
  bottom: {type: wall}
  top: {type: wall, velocity: [1.0, 0.0]}
numerics: {dt: 0.005}
time: {end: 1.0}
output: {plots: false, fields_interval: 0.02, checkpoint_interval: 0.02, checkpoints_kept: 1000}
)";

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// Every output in `out` is whole: no temporary left, every HDF5 file opens and reads, every checkpoint
// is a whole checkpoint, every CSV file ends with a newline and each line has the header's column count.
void expect_outputs_whole(const fs::path& out) {
    for (const auto& e : fs::directory_iterator(out)) {
        const fs::path p = e.path();
        const std::string name = p.filename().string();
        EXPECT_NE(p.extension(), ".tmp") << "a partial file is left: " << p;
        if (p.extension() == ".h5") {
            if (name.starts_with("checkpoint_")) {
                EXPECT_NO_THROW(check_checkpoint_readable(p)) << p;
            } else {  // fields_<step>.h5 (grid lines x, y), timeseries.h5 and body series (column t)
                EXPECT_NO_THROW((void)Hdf5File::open_read(p).read(name.starts_with("fields_") ? "x" : "t")) << p;
            }
        }
        if (p.extension() == ".csv") {
            const std::string text = read_text(p);
            ASSERT_FALSE(text.empty()) << p;
            EXPECT_EQ(text.back(), '\n') << "a cut line at the end of " << p;
            std::istringstream lines(text);
            std::string line;
            std::getline(lines, line);
            const auto commas = std::count(line.begin(), line.end(), ',');
            for (int row = 1; std::getline(lines, line); ++row)
                EXPECT_EQ(std::count(line.begin(), line.end(), ','), commas) << p << " row " << row << ": " << line;
        }
    }
}

// The time in the last row of a CSV series.
double last_time(const fs::path& csv) {
    const std::string text = read_text(csv);
    const std::size_t end = text.find_last_not_of('\n');
    const std::size_t start = text.rfind('\n', end);
    return std::stod(text.substr(start + 1));
}

}  // namespace

// A full disk (a small tmpfs, in a private mount namespace): the run stops at once with exit code 4 and a
// message naming the file, the cause and the results folder; everything written before is whole; the
// results, moved to a disk with room, continue from their newest checkpoint to the end time. Three disk sizes,
// so that the disk fills up in different writers (measured: 100k a checkpoint, 300k fields.xdmf, 450k
// timeseries.h5; the test asserts only what holds for any of them).
TEST(Faults, FullDiskStopsTheRunAndTheNewestCheckpointRestarts) {
    if (!single_rank()) GTEST_SKIP() << "starts its own process";
    const fs::path dir = scratch("faults_full_disk");
    const std::string unshare = private_mount_command(dir);
    if (unshare.empty()) GTEST_SKIP() << "cannot mount a tmpfs here (neither unshare -m nor unshare -rm works)";
    write_text(dir / "case.yaml", kCavity);
    for (const char* size : {"100k", "300k", "450k"}) {
        SCOPED_TRACE(std::string("tmpfs of ") + size);
        const fs::path disk = dir / "disk", copy = dir / (std::string("results_") + size);
        fs::create_directories(disk);
        // In the namespace: mount, run, time the run, and copy what it wrote out before the tmpfs vanishes.
        write_text(dir / "in_namespace.sh",
                   "mount -t tmpfs -o size=" + std::string(size) + " tmpfs " + quoted(disk) + " || exit 90\n" +
                       "start=$(date +%s%N)\n" + CHUTE_BINARY + " run " + quoted(dir / "case.yaml") + " --out " +
                       quoted(disk / "out") + " > " + quoted(dir / "run.log") + " 2>&1\n" + "echo $? > " +
                       quoted(dir / "run.code") + "\n" + "echo $(( ($(date +%s%N) - start) / 1000000 )) > " +
                       quoted(dir / "run.ms") + "\n" + "cp -a " + quoted(disk / "out") + " " + quoted(copy) + "\n");
        const auto shell = run_shell(unshare + " sh " + quoted(dir / "in_namespace.sh"), dir);
        ASSERT_EQ(shell.exit_code, 0) << shell.output;
        const std::string log = read_text(dir / "run.log");
        std::printf("[ tmpfs %s ] exit %s in %s ms: %s\n", size, first_line(read_text(dir / "run.code")).c_str(),
                    first_line(read_text(dir / "run.ms")).c_str(), line_with(log, "chute: cannot").c_str());
        EXPECT_EQ(std::stoi(read_text(dir / "run.code")), 4) << log;
        EXPECT_TRUE(contains(log, "cannot write '" + (disk / "out").string() + "/")) << log;
        EXPECT_TRUE(contains(log, "No space left on device")) << log;
        EXPECT_TRUE(contains(log, "results folder '" + (disk / "out").string() + "'")) << log;
        EXPECT_LT(last_time(copy / "timeseries.csv"), 1.0) << "the run went on after the disk was full";
        expect_outputs_whole(copy);

        const auto newest = newest_readable_checkpoint(copy);
        ASSERT_TRUE(newest) << "no checkpoint survived";
        const auto resumed = run_chute(
            "run " + quoted(dir / "case.yaml") + " --out " + quoted(copy) + " --restart " + quoted(copy), dir);
        EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
        EXPECT_TRUE(contains(resumed.output, "continuing from " + newest->string())) << resumed.output;
        EXPECT_DOUBLE_EQ(last_time(copy / "timeseries.csv"), 1.0) << resumed.output;
        expect_outputs_whole(copy);
        fs::remove_all(copy);
    }
}

// A file size limit (ulimit -f, set on the running process once it has started, since MPI's start-up
// writes shared-memory files larger than the limit): the growing time series meets it first; the run stops
// with exit code 4 naming it and "File too large", the series is cut back to its last whole line, and the
// run continues from its newest checkpoint without the limit. Needs no privilege.
TEST(Faults, FileSizeLimitStopsTheRunAndKeepsWholeLines) {
    if (!single_rank()) GTEST_SKIP() << "starts its own process";
    const fs::path dir = scratch("faults_fsize");
    write_text(dir / "case.yaml", kCavity);
    const fs::path out = dir / "out";
    // Fields rarely, so the XDMF index stays small; checkpoints (21 kB) fit; timeseries.csv (95 bytes a
    // row) reaches 40 kB near step 420 of 600.
    const std::string args = "run " + quoted(dir / "case.yaml") + " --out " + quoted(out) +
                             " --set time.end=3 --set output.fields_interval=0.5 --set output.checkpoint_interval=0.1"
                             " --set output.checkpoints_kept=2";
    {
        ChuteProcess run(args, dir / "run.log");
        while (!fs::exists(out / "case.yaml") && run.running())
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        const rlimit limit{40000, RLIM_INFINITY};
        ASSERT_EQ(prlimit(run.pid(), RLIMIT_FSIZE, &limit, nullptr), 0)
            << "cannot set the limit: " << std::strerror(errno);
        const int code = run.wait();
        const std::string log = read_text(dir / "run.log");
        std::printf("[ file size limit 40000 bytes ] exit %d: %s\n", code, line_with(log, "chute: cannot").c_str());
        EXPECT_EQ(code, 4) << log;
        EXPECT_TRUE(contains(log, "cannot write '" + out.string() + "/")) << log;
        EXPECT_TRUE(contains(log, "File too large")) << log;
    }
    EXPECT_LE(fs::file_size(out / "timeseries.csv"), 40000u);
    EXPECT_LT(last_time(out / "timeseries.csv"), 3.0);
    expect_outputs_whole(out);
    const auto resumed = run_chute(args + " --restart " + quoted(out), dir);
    EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_DOUBLE_EQ(last_time(out / "timeseries.csv"), 3.0) << resumed.output;
    expect_outputs_whole(out);
}

// --out under a regular file: no folder can be made there (even for root). The run stops before it starts,
// exit code 4, naming the folder; nothing is written.
TEST(Faults, ResultsFolderUnderAFileStopsBeforeTheRun) {
    if (!single_rank()) GTEST_SKIP() << "starts its own process";
    const fs::path dir = scratch("faults_not_a_folder");
    write_text(dir / "case.yaml", kCavity);
    write_text(dir / "plain", "a file, not a folder\n");
    const fs::path out = dir / "plain" / "out";
    const auto r = run_chute("run " + quoted(dir / "case.yaml") + " --out " + quoted(out), dir);
    EXPECT_EQ(r.exit_code, 4) << r.output;
    EXPECT_TRUE(contains(r.output, "results folder '" + out.string() + "'")) << r.output;
    EXPECT_TRUE(contains(r.output, "Not a directory")) << r.output;
    EXPECT_FALSE(contains(r.output, "step")) << "the run started: " << r.output;
    EXPECT_EQ(read_text(dir / "plain"), "a file, not a folder\n");
}

// A read-only results folder: without write permission (as a normal user), or on a read-only tmpfs (as root,
// who ignores permissions). The run stops before it starts, exit code 4, naming the folder and the cause.
TEST(Faults, ReadOnlyResultsFolderStopsBeforeTheRun) {
    if (!single_rank()) GTEST_SKIP() << "starts its own process";
    const fs::path dir = scratch("faults_read_only");
    write_text(dir / "case.yaml", kCavity);
    const fs::path out = dir / "read_only";
    fs::create_directories(out);
    const std::string run = std::string(CHUTE_BINARY) + " run " + quoted(dir / "case.yaml") + " --out " + quoted(out);
    CommandResult r;
    std::string cause;
    if (::geteuid() != 0) {
        fs::permissions(out, fs::perms::owner_read | fs::perms::owner_exec);
        r = run_shell(run, dir);
        fs::permissions(out, fs::perms::owner_all);
        cause = "Permission denied";
    } else {
        const std::string unshare = private_mount_command(dir);
        if (unshare.empty()) GTEST_SKIP() << "root ignores permissions, and no read-only tmpfs can be mounted here";
        write_text(dir / "in_namespace.sh",
                   "mount -t tmpfs -o ro,size=64k tmpfs " + quoted(out) + " || exit 90\n" + run);
        r = run_shell(unshare + " sh " + quoted(dir / "in_namespace.sh"), dir);
        cause = "Read-only file system";
    }
    EXPECT_EQ(r.exit_code, 4) << r.output;
    EXPECT_TRUE(contains(r.output, "results folder '" + out.string() + "'")) << r.output;
    EXPECT_TRUE(contains(r.output, cause)) << r.output;
    EXPECT_FALSE(contains(r.output, "step")) << "the run started: " << r.output;
    EXPECT_TRUE(fs::is_empty(out));
}

namespace {

// The moments of a checkpoint write (write_atomically) at which the run is killed, as inotify sees them.
struct KillMoment {
    const char* what;
    std::uint32_t event;  // on checkpoint_<step>.h5.tmp, or (IN_MOVED_TO) on checkpoint_<step>.h5
    int microseconds;     // waited after the event before the kill
};

// Starts a run, kills it with SIGKILL at the third checkpoint write's `moment`; the exit code.
int run_and_kill(const std::string& args, const fs::path& out, const fs::path& log, const KillMoment& moment) {
    const int watch = inotify_init1(IN_CLOEXEC | IN_NONBLOCK);
    if (watch < 0 || inotify_add_watch(watch, out.c_str(), IN_CREATE | IN_MODIFY | IN_CLOSE_WRITE | IN_MOVED_TO) < 0)
        throw std::runtime_error("inotify: " + std::string(std::strerror(errno)));
    ChuteProcess run(args, log);
    int seen = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (seen < 3 && run.running() && std::chrono::steady_clock::now() < deadline) {
        pollfd p{watch, POLLIN, 0};
        if (::poll(&p, 1, 100) <= 0) continue;
        alignas(inotify_event) char buffer[4096];
        const ssize_t n = ::read(watch, buffer, sizeof buffer);
        for (ssize_t at = 0; at < n && seen < 3;) {
            const auto* e = reinterpret_cast<const inotify_event*>(buffer + at);
            const std::string name = e->len > 0 ? e->name : "";
            const bool checkpoint = name.starts_with("checkpoint_");
            const bool tmp = name.ends_with(".h5.tmp");
            if (checkpoint && (e->mask & moment.event) && tmp == (moment.event != IN_MOVED_TO)) ++seen;
            at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
        }
    }
    ::close(watch);
    if (seen == 3) {
        std::this_thread::sleep_for(std::chrono::microseconds(moment.microseconds));
        ::kill(run.pid(), SIGKILL);
    }
    return run.wait();
}

}  // namespace

// SIGKILL while a checkpoint is being written, at several moments of the write (as the temporary file is
// made, written, closed, right after the rename, and at delays after it is made): every checkpoint_*.h5
// present is whole, --restart <folder> continues from the newest each time (a partial temporary left by the
// kill is removed), and the chain of killed and continued runs ends where a straight run ends, bit for bit.
TEST(Faults, KilledWhileWritingACheckpointRestartsFromThePreviousOne) {
    if (!single_rank()) GTEST_SKIP() << "starts its own process";
    const fs::path dir = scratch("faults_sigkill");
    // 64 x 64 cells (a checkpoint of 200 kB, written in a few hundred microseconds), a checkpoint every 2 steps.
    write_text(dir / "case.yaml", kCavity);
    const std::string base =
        "run " + quoted(dir / "case.yaml") +
        " --set domain.x.cells=64 --set domain.y.cells=64 --set numerics.dt=0.002"
        " --set time.end=0.2 --set output.fields_interval=0.1 --set output.checkpoint_interval=0.004"
        " --set output.checkpoints_kept=3 --out ";
    const fs::path out = dir / "killed", straight = dir / "straight";
    fs::create_directories(out);
    const std::vector<KillMoment> moments = {{"temporary made", IN_CREATE, 0},
                                             {"temporary written", IN_MODIFY, 0},
                                             {"temporary closed", IN_CLOSE_WRITE, 0},
                                             {"just renamed", IN_MOVED_TO, 0},
                                             {"200 us after the temporary was made", IN_CREATE, 200},
                                             {"1 ms after the temporary was made", IN_CREATE, 1000}};
    std::string restart;
    int partial_left = 0;
    for (const KillMoment& moment : moments) {
        SCOPED_TRACE(moment.what);
        const int code = run_and_kill(base + quoted(out) + restart, out, dir / "killed.log", moment);
        const std::string log = read_text(dir / "killed.log");
        ASSERT_EQ(code, 128 + SIGKILL) << "the run was not killed (it ended first?): " << log;
        if (has_tmp_file(out)) ++partial_left;
        for (const auto& e : fs::directory_iterator(out))
            if (e.path().filename().string().starts_with("checkpoint_") && e.path().extension() == ".h5") {
                EXPECT_NO_THROW(check_checkpoint_readable(e.path())) << e.path();
            }
        ASSERT_TRUE(newest_readable_checkpoint(out)) << "no checkpoint to continue from";
        restart = " --restart " + quoted(out);
    }
    const auto resumed = run_chute(base + quoted(out) + restart, dir);
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_DOUBLE_EQ(last_time(out / "timeseries.csv"), 0.2) << resumed.output;
    expect_outputs_whole(out);
    std::printf("[ SIGKILL ] %zu kills, %d left a partial temporary (removed by the next run)\n", moments.size(),
                partial_left);

    ASSERT_EQ(run_chute(base + quoted(straight), dir).exit_code, 0);
    const auto killed_end = latest_checkpoint(out), straight_end = latest_checkpoint(straight);
    ASSERT_TRUE(killed_end && straight_end);
    EXPECT_EQ(killed_end->filename(), straight_end->filename());
    for (const char* field : {"fields/u", "fields/v", "fields/p"})
        EXPECT_EQ(Hdf5File::open_read(*killed_end).read(field), Hdf5File::open_read(*straight_end).read(field))
            << field;
}

// --restart <results folder> takes the newest checkpoint that reads whole, passing over a damaged one with a
// note; a folder without any readable checkpoint is a case error (exit code 2) naming it.
TEST(Faults, RestartFromAFolderPassesOverADamagedCheckpoint) {
    if (!single_rank()) GTEST_SKIP() << "starts its own process";
    const fs::path dir = scratch("faults_restart_folder");
    write_text(dir / "case.yaml", kCavity);
    const fs::path out = dir / "out";
    const std::string c = "run " + quoted(dir / "case.yaml") + " --out " + quoted(out) + " --set time.end=0.1";
    ASSERT_EQ(run_chute(c, dir).exit_code, 0);
    const auto good = latest_checkpoint(out);
    ASSERT_TRUE(good);
    // A newer checkpoint cut in half, as a copy to a full disk by hand would leave it.
    const std::string whole = read_text(*good);
    write_text(checkpoint_path(out, 999999), whole.substr(0, whole.size() / 2));
    const auto r = run_chute(c + " --set time.end=0.12 --restart " + quoted(out), dir);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "passing over " + checkpoint_path(out, 999999).string())) << r.output;
    EXPECT_TRUE(contains(r.output, "continuing from " + good->string())) << r.output;
    EXPECT_DOUBLE_EQ(last_time(out / "timeseries.csv"), 0.12);

    const fs::path empty = dir / "empty";
    fs::create_directories(empty);
    const auto none = run_chute(c + " --restart " + quoted(empty), dir);
    EXPECT_EQ(none.exit_code, 2) << none.output;
    EXPECT_TRUE(contains(none.output, "no readable checkpoint in the folder '" + empty.string() + "'")) << none.output;
}
