#include "parallel/interruption.h"

#include <algorithm>
#include <csignal>
#include <pthread.h>
#include <thread>
#include <vector>

namespace penny
{
  namespace
  {
    std::mutex                         registry_mutex;
    std::vector<std::filesystem::path> registry; // under registry_mutex
    constexpr int                      interruptions[] = {SIGINT, SIGTERM, SIGHUP};

    sigset_t interruption_signals()
    {
      sigset_t signals;
      sigemptyset(&signals);
      for (const int each : interruptions)
        sigaddset(&signals, each);
      return signals;
    }

    // The interruptions the caller told the run to ignore (nohup ignores
    // SIGHUP, a script's background job SIGINT), as they were at the start:
    // Open MPI's start sets SIGHUP back to its default.
    sigset_t ignored_at_start;

    // Waits for an interruption that is not ignored, removes the registered
    // folders (holding the registry, so that nothing is moved or registered
    // meanwhile) and lets the signal's default action end the process.
    void await_interruption(const sigset_t signals)
    {
      int received = 0;
      while (sigwait(&signals, &received) != 0 || sigismember(&ignored_at_start, received))
        ;
      const std::lock_guard<std::mutex> lock(registry_mutex);
      std::error_code                   ignored;
      for (const auto &folder : registry)
        std::filesystem::remove_all(folder, ignored);
      std::signal(received, SIG_DFL);
      sigset_t own;
      sigemptyset(&own);
      sigaddset(&own, received);
      pthread_sigmask(SIG_UNBLOCK, &own, nullptr);
      raise(received);
    }
  } // namespace

  void handle_interruptions()
  {
    sigemptyset(&ignored_at_start);
    for (const int each : interruptions)
      {
        struct sigaction action;
        if (sigaction(each, nullptr, &action) == 0 && action.sa_handler == SIG_IGN)
          sigaddset(&ignored_at_start, each);
      }
    const sigset_t signals = interruption_signals();
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    std::thread(await_interruption, signals).detach();
  }

  void remove_on_interruption(const std::filesystem::path &folder)
  {
    const std::lock_guard<std::mutex> lock(registry_mutex);
    registry.push_back(folder);
  }

  void forget_on_interruption(const std::filesystem::path &folder)
  {
    const std::lock_guard<std::mutex> lock(registry_mutex);
    registry.erase(std::remove(registry.begin(), registry.end(), folder), registry.end());
  }

  std::unique_lock<std::mutex> hold_interruptions()
  {
    return std::unique_lock<std::mutex>(registry_mutex);
  }

  void restore_interruption_signals()
  {
    for (const int each : interruptions)
      std::signal(each, sigismember(&ignored_at_start, each) ? SIG_IGN : SIG_DFL);
    const sigset_t signals = interruption_signals();
    pthread_sigmask(SIG_UNBLOCK, &signals, nullptr);
  }
} // namespace penny
