#include "stop_request.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>

namespace chute {

namespace {

volatile std::sig_atomic_t received_signal = 0;
unsigned grace = 5;
// The immediate exit's messages, composed at installation: a signal handler may only write(2) them.
char second_signal_note[1024], grace_over_note[1024];

[[noreturn]] void exit_at_once(const char* note) {
    (void)!write(STDERR_FILENO, note, std::strlen(note));
    _exit(128 + received_signal);
}

extern "C" void on_stop_signal(int signal) {
    if (received_signal != 0) exit_at_once(second_signal_note);
    received_signal = signal;
    alarm(grace);
}

extern "C" void on_grace_over(int) { exit_at_once(grace_over_note); }

void install(int signal, void (*handler)(int)) {
    struct sigaction action {};
    action.sa_handler = handler;
    sigemptyset(&action.sa_mask);
    sigaction(signal, &action, nullptr);
}

}  // namespace

void install_stop_handlers(const std::filesystem::path& out_dir, unsigned grace_seconds) {
    grace = grace_seconds;
    const char* whole =
        "exiting at once; the outputs already written in %s are whole (each is written to a temporary "
        "file, then renamed): continue from its newest checkpoint with --restart\n";
    char tail[900];
    std::snprintf(tail, sizeof tail, whole, out_dir.c_str());
    std::snprintf(second_signal_note, sizeof second_signal_note, "chute: a second stop signal: %s", tail);
    std::snprintf(grace_over_note, sizeof grace_over_note,
                  "chute: the step did not end within %u s of the stop signal: %s", grace_seconds, tail);
    install(SIGINT, on_stop_signal);
    install(SIGTERM, on_stop_signal);
    install(SIGALRM, on_grace_over);
}

int stop_requested(MPI_Comm comm) {
    int local = received_signal, global = 0;
    MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, comm);
    if (local != 0) alarm(0);
    return global;
}

}  // namespace chute
