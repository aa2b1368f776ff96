// Result files are written under a temporary name and renamed into place, so
// a run that fails never leaves a truncated file or clobbers an earlier one.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace penny
{
  // Creates the folder if needed; throws InputError naming Output/Directory if
  // it cannot be created or written.
  void prepare_output_directory(const std::filesystem::path &directory);

  // On MPI rank 0 only: the other ranks hold the same results.
  void write_atomically(const std::filesystem::path &file, const std::function<void(std::ostream &)> &write);
} // namespace penny
