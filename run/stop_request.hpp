#pragma once
// Graceful stop on SIGINT (Ctrl-C) and SIGTERM (a batch system's time limit): the signal only sets a flag;
// the run loop polls it once per step on all ranks together, finishes the step, and writes its final
// fields and checkpoint as at the end of a run, so `chute run --restart` can continue from there.
#include <mpi.h>

namespace chute {

// Installs the handlers (the command-line tool does this; library users may choose not to).
void install_stop_handlers();
// Collective: the signal number if any rank was asked to stop, else 0.
int stop_requested(MPI_Comm comm);

}  // namespace chute
