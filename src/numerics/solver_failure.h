// An iterative solver that did not reach its tolerance (or broke down): the
// message, and which settings a user changes about it, which the run's error
// line adds.
#pragma once

#include <stdexcept>
#include <string>

namespace penny
{
  struct SolverFailure : std::runtime_error
  {
    SolverFailure(const std::string &message, std::string settings)
        : std::runtime_error(message), settings(std::move(settings))
    {
    }

    std::string settings; // e.g. "subsection 'Contact solver' sets its Tolerance and Maximum iterations"
  };
} // namespace penny
