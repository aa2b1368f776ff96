// A run's results appear as a set or not at all. Every file goes into a fresh
// staging folder beside the result folder; when the scene has finished, the
// staging folder takes the place of the result folder in one rename, and the
// previous results go. A run that fails removes its staging folder and leaves
// the previous results untouched, and so does one that is interrupted
// (parallel/interruption.h); one killed by SIGKILL leaves at most a stale
// staging folder, which the next run into the same folder removes.
//
// The result folder belongs to penny: it is replaced whole, so it must be new,
// empty, or an earlier result folder (marked by the file .penny-results). One
// run at a time holds it: an flock on the lock file .NAME.lock beside it, held
// until the results are in place and released by the kernel when a run dies.
// Every write is checked (a short write, a full disk and a failed fsync are
// errors), and each file and the folder reach the disk before the rename.
// All members are collective over MPI_COMM_WORLD: rank 0 writes, the other
// ranks learn whether it succeeded, and an error reaches every rank.
#pragma once

#include "output/table.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace penny
{
  class ResultFolder
  {
  public:
    // Locks `directory`, checks it and creates the staging folder; throws
    // InputError (its message starting with the folder's name in quotes)
    // where that is impossible, where
    // another run holds the folder, or where replacing the folder would remove
    // the working folder or one of `input_files`.
    ResultFolder(const std::filesystem::path              &directory,
                 const std::vector<std::filesystem::path> &input_files);
    ResultFolder(const ResultFolder &) = delete;
    ~ResultFolder();

    // The results' final folder, as the user named it.
    const std::filesystem::path &directory() const { return final_directory; }

    // `contents` as `file` of the results; collective, the contents of rank 0 count.
    void write(const std::string &file, const std::string &contents) const;
    void write_csv(const std::string &file, const Table &table) const;

    // Moves the results into place.
    void commit();

  private:
    // Rank 0: the absolute path of the folder.
    std::filesystem::path folder() const;
    // Rank 0: the lock, the checks and the staging folder.
    void prepare(const std::vector<std::filesystem::path> &input_files);
    // Rank 0: removes the staging folder unless committed, and unlocks.
    void release();

    std::filesystem::path final_directory;
    std::filesystem::path staging_directory; // rank 0
    int                   lock      = -1;    // rank 0: the descriptor of the locked lock file
    bool                  committed = false;
  };
  // A table as the scenes show a result: printed to `log` under the line
  // `title` (if any) and written into `results` as the CSV file `file`.
  void publish(const Table &table, const std::string &file, const ResultFolder &results, std::ostream &log,
               const std::string &title = "");
} // namespace penny
