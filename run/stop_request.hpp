#pragma once
// Stopping a run on SIGINT (Ctrl-C) and SIGTERM (a batch system's time limit).
//   The first signal sets a flag; the run loop polls it once per step on all ranks together, finishes the
//   step, and writes its final fields and checkpoint as at the end of a run, so `chute run --restart` can
//   continue from there.
//   A second signal, or a step that has not ended `grace_seconds` after the first, exits at once with
//   128 + the signal number: a step stuck in a loop must not hold a cluster allocation in silence. Nothing
//   already written is lost, since every output is written to a temporary file and renamed.
#include <mpi.h>

#include <filesystem>

namespace chute {

// Installs the handlers (the command-line tool does this; library users may choose not to). `out_dir` is
// named in the message printed on an immediate exit.
void install_stop_handlers(const std::filesystem::path& out_dir, unsigned grace_seconds = 5);
// Collective: the signal number if any rank was asked to stop, else 0. Once it has answered a signal, the
// step has ended: the grace period's alarm is cancelled and the final outputs are written unhurried.
int stop_requested(MPI_Comm comm);

}  // namespace chute
