// What a run leaves when it is stopped by SIGINT, SIGTERM or SIGHUP (Ctrl-C,
// kill, mpirun passing either on to its ranks, a closed terminal): none of
// its own folders. handle_interruptions(), called first in main, before MPI
// or any other thread starts, blocks these signals in every thread and starts
// one that waits for them; on one, it removes the folders registered below
// and ends the process by the same signal, as its default action would.
// Signals the caller ignores stay ignored. SIGKILL cannot be caught: a run
// killed by it leaves its staging folder for the next run into the same
// folder to remove.
#pragma once

#include <filesystem>
#include <mutex>

namespace penny
{
  void handle_interruptions();

  // `folder` is removed if the run is interrupted, until it is forgotten.
  void remove_on_interruption(const std::filesystem::path &folder);
  void forget_on_interruption(const std::filesystem::path &folder);

  // Held, no interruption removes a folder: for a step that must not meet
  // the removal half-way (moving a folder into place).
  std::unique_lock<std::mutex> hold_interruptions();

  // In a forked child: the signals unblocked, ignored or default as at the start.
  void restore_interruption_signals();
} // namespace penny
