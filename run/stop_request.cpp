#include "stop_request.hpp"

#include <csignal>

namespace chute {

namespace {
volatile std::sig_atomic_t received_signal = 0;
extern "C" void on_stop_signal(int signal) { received_signal = signal; }
}  // namespace

void install_stop_handlers() {
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
}

int stop_requested(MPI_Comm comm) {
    int local = received_signal, global = 0;
    MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, comm);
    return global;
}

}  // namespace chute
