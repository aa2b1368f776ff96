// A run's results appear as a set or not at all. Every file goes into a fresh
// staging folder beside Output/Directory; when the scene has finished, the
// staging folder takes the place of Output/Directory in one rename, and the
// previous results go. A run that fails removes its staging folder and leaves
// the previous results untouched.
//
// Output/Directory belongs to penny: it is replaced whole, so it must be new,
// empty, or an earlier result folder (marked by the file .penny-results).
// All members are collective over MPI_COMM_WORLD: rank 0 writes, the other
// ranks learn whether it succeeded, and an error reaches every rank.
#pragma once

#include "output/table.h"

#include <filesystem>
#include <string>

namespace penny
{
  class ResultFolder
  {
  public:
    // Checks Output/Directory and creates the staging folder; throws
    // InputError (naming Output/Directory) where that is impossible, or where
    // replacing the folder would remove the working folder or `input_file`.
    ResultFolder(const std::filesystem::path &directory, const std::filesystem::path &input_file);
    ResultFolder(const ResultFolder &) = delete;
    ~ResultFolder();

    // The results' final folder, as the user named it.
    const std::filesystem::path &directory() const { return final_directory; }
    // Where the files go until commit().
    const std::filesystem::path &staging() const { return staging_directory; }

    void write(const std::string &file, const std::string &contents) const;
    void write_csv(const std::string &file, const Table &table) const;

    // Moves the results into place.
    void commit();

  private:
    std::filesystem::path final_directory, staging_directory;
    bool                  committed = false;
  };
} // namespace penny
