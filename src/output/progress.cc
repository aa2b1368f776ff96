#include "output/progress.h"

#include <iomanip>

namespace penny
{
  Progress::Progress(std::ostream &log, std::string unit, const double interval)
      : log(log), unit(std::move(unit)), interval(interval), last_line(start)
  {
  }

  void Progress::step(const std::string &state)
  {
    ++steps;
    const auto now = Clock::now();
    if (steps > 1 && std::chrono::duration<double>(now - last_line).count() < interval)
      return;
    last_line = now;
    log << "  [" << std::fixed << std::setprecision(1) << std::setw(6)
        << std::chrono::duration<double>(now - start).count() << " s] " << steps << ' ' << unit << ", "
        << state << std::defaultfloat << std::endl;
  }
} // namespace penny
