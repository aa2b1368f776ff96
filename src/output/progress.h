// Progress of a long scene on the terminal: after each step (an FE solve, a
// case, a cycle) a line, at most one per `interval` seconds, with the elapsed
// time, the steps done and what the scene is at. Rank 0 prints: under MPI
// the steps counted are its own, and the line says so.
#pragma once

#include <chrono>
#include <ostream>
#include <string>

namespace penny
{
  class Progress
  {
  public:
    Progress(std::ostream &log, std::string unit, double interval = 5);

    // One more step is done; `state` says where the scene stands.
    void step(const std::string &state);

    unsigned int n_steps() const { return steps; }

  private:
    using Clock = std::chrono::steady_clock;

    std::ostream           &log;
    const std::string       unit;
    const double            interval;
    const Clock::time_point start = Clock::now();
    Clock::time_point       last_line;
    unsigned int            steps = 0;
  };
} // namespace penny
