#include "output/result_folder.h"

#include "input/input_error.h"
#include "parallel/collective.h"
#include "parallel/interruption.h"

#include <deal.II/base/mpi.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace penny
{
  namespace fs = std::filesystem;

  namespace
  {
    const char *const marker = ".penny-results";

    bool on_rank_zero()
    {
      return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    }

    std::string errno_text()
    {
      return std::strerror(errno);
    }

    // The file or folder at `path` reaches the disk.
    void sync_to_disk(const fs::path &path, const std::string &what)
    {
      const int descriptor = open(path.c_str(), O_RDONLY | O_CLOEXEC);
      if (descriptor < 0 || fsync(descriptor) != 0)
        {
          const std::string reason = errno_text();
          if (descriptor >= 0)
            close(descriptor);
          throw std::runtime_error("output: could not sync " + what + ": " + reason);
        }
      close(descriptor);
    }

    // On rank 0: `contents` into the new file `path` (never through a link),
    // all of it or an exception naming `what`, and on the disk before it returns.
    void write_file(const fs::path &path, const std::string &contents, const std::string &what)
    {
      const int descriptor = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
      if (descriptor < 0)
        throw std::runtime_error("output: could not create " + what + ": " + errno_text());
      const auto fail = [&]() {
        const std::string reason = errno_text();
        close(descriptor);
        throw std::runtime_error("output: could not write " + what + ": " + reason);
      };
      for (std::size_t written = 0; written < contents.size();)
        {
          const ssize_t n = ::write(descriptor, contents.data() + written, contents.size() - written);
          if (n < 0 && errno == EINTR)
            continue;
          if (n <= 0)
            {
              if (n == 0)
                errno = ENOSPC; // a write that makes no progress
              fail();
            }
          written += n;
        }
      if (fsync(descriptor) != 0)
        fail();
      if (close(descriptor) != 0)
        throw std::runtime_error("output: could not write " + what + ": " + errno_text());
    }

    // Staging folders are named .NAME.staging-XXXXXX, beside the folder NAME.
    std::string staging_prefix(const fs::path &target)
    {
      return "." + target.filename().string() + ".staging-";
    }
  } // namespace

  ResultFolder::ResultFolder(const fs::path &directory, const std::vector<fs::path> &input_files)
      : final_directory(directory)
  {
    run_on_rank_zero(MPI_COMM_WORLD, [&]() {
      try
        {
          prepare(input_files);
        }
      catch (...)
        {
          release();
          throw;
        }
    });
  }

  ResultFolder::~ResultFolder()
  {
    if (on_rank_zero())
      release();
  }

  fs::path ResultFolder::folder() const
  {
    const fs::path target =
        fs::absolute(final_directory.empty() ? fs::path(".") : final_directory).lexically_normal();
    return target.has_filename() ? target : target.parent_path(); // "out/" normalises to "out/"
  }

  void ResultFolder::prepare(const std::vector<fs::path> &input_files)
  {
    const std::string entry  = in_quotes(final_directory.string());
    const fs::path    target = folder();
    const fs::path    parent = target.parent_path();
    if (!target.has_filename() || target == parent)
      throw InputError(entry + " is not a folder penny can replace");
    std::error_code error;
    fs::create_directories(parent, error);
    if (error || access(parent.c_str(), W_OK) != 0)
      throw InputError(entry + " cannot be created or is not writable");

    // A folder inside another run's results would go when that run replaces its folder whole.
    for (fs::path above = fs::canonical(parent, error); !error && !above.empty(); above = above.parent_path())
      {
        if (fs::exists(above / marker))
          throw InputError(entry + " lies inside " + in_quotes(above.string()) +
                           ", the results of another run, which that run replaces whole; name a folder "
                           "outside it");
        if (above == above.parent_path())
          break;
      }

    // A folder holding the working folder or an input file is refused before
    // the lock, whose file would otherwise appear beside it (for '.', in the
    // working folder's parent).
    if (fs::is_directory(fs::symlink_status(target, error)))
      {
        const auto inside = [&](const fs::path &path) {
          const fs::path relative = fs::weakly_canonical(path).lexically_relative(fs::canonical(target));
          return !relative.empty() && *relative.begin() != "..";
        };
        if (inside(fs::current_path()))
          throw InputError(entry + " holds the working folder; a run replaces its output folder whole");
        for (const fs::path &input : input_files)
          if (!input.empty() && inside(input))
            throw InputError(entry + " holds the input file " + in_quotes(input.string()) +
                             "; a run replaces its output folder whole");
      }

    // The lock next: everything below looks at a folder no other run touches.
    const fs::path lock_file = parent / ("." + target.filename().string() + ".lock");
    lock                     = open(lock_file.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (lock < 0 && errno == ELOOP)
      throw InputError(entry + " cannot be locked: its lock file " + in_quotes(lock_file.string()) +
                       " is a symbolic link");
    if (lock < 0)
      throw InputError(entry + " cannot be created or is not writable (lock file " +
                       in_quotes(lock_file.string()) + ": " + errno_text() + ")");
    struct stat status;
    if (fstat(lock, &status) != 0 || !S_ISREG(status.st_mode))
      throw InputError(entry + " cannot be locked: its lock file " + in_quotes(lock_file.string()) +
                       " is not a regular file");
    if (flock(lock, LOCK_EX | LOCK_NB) != 0)
      throw InputError(entry + " is in use by another penny run (it holds " + in_quotes(lock_file.string()) +
                       "); wait for that run or name another folder");

    const fs::file_status target_status = fs::symlink_status(target, error);
    if (fs::exists(target_status))
      {
        if (fs::is_symlink(target_status))
          throw InputError(entry + " is a symbolic link; name the folder itself (a run replaces its output "
                                   "folder whole)");
        if (!fs::is_directory(target_status))
          throw InputError(entry + " is not a folder");
        if (!fs::is_empty(target) && !fs::exists(target / marker))
          throw InputError(entry + " holds files penny did not write; name a new or empty folder (a run "
                                   "replaces its output folder whole)");
      }

    // Staging folders of runs that were killed: empty, penny's results, or
    // what is left of them when the removal was cut short (its marker may
    // have gone first). No live run uses them while we hold the lock.
    const std::string     prefix = staging_prefix(target);
    std::vector<fs::path> stale;
    for (const auto &item : fs::directory_iterator(parent, error))
      {
        const std::string name = item.path().filename().string();
        if (name.size() == prefix.size() + 6 && name.compare(0, prefix.size(), prefix) == 0 &&
            !item.is_symlink() && item.is_directory())
          stale.push_back(item.path());
      }
    for (const fs::path &path : stale)
      fs::remove_all(path, error);

    std::string pattern = (parent / (prefix + "XXXXXX")).string();
    if (!mkdtemp(pattern.data()))
      throw InputError(entry + " cannot be created or is not writable (" + errno_text() + ")");
    staging_directory = pattern;
    remove_on_interruption(staging_directory);
    write_file(staging_directory / marker,
               "results of penny, replaced whole by the next run into this folder\n",
               (final_directory / marker).string());
  }

  void ResultFolder::release()
  {
    std::error_code ignored;
    if (!committed && !staging_directory.empty())
      fs::remove_all(staging_directory, ignored);
    forget_on_interruption(staging_directory);
    staging_directory.clear();
    if (lock >= 0)
      close(lock); // releases the flock
    lock = -1;
  }

  void ResultFolder::write(const std::string &file, const std::string &contents) const
  {
    run_on_rank_zero(MPI_COMM_WORLD, [&]() {
      write_file(staging_directory / file, contents, (final_directory / file).string());
    });
  }

  void ResultFolder::write_csv(const std::string &file, const Table &table) const
  {
    write(file, table.csv());
  }

  // The staging folder reaches the disk with its files; then, with the target
  // in place, the two folders swap names in one step (renameat2
  // RENAME_EXCHANGE), the swap reaches the disk, and the previous results go.
  void ResultFolder::commit()
  {
    run_on_rank_zero(MPI_COMM_WORLD, [&]() {
      const fs::path    target = folder();
      const std::string name   = final_directory.string();
      const mode_t      mask   = umask(0);
      umask(mask);
      if (chmod(staging_directory.c_str(), 0777 & ~mask) != 0)
        throw std::runtime_error("output: could not open " + name + " to its readers: " + errno_text());
      sync_to_disk(staging_directory, name);
      const bool replaces = fs::exists(fs::symlink_status(target));
      {
        // An interruption removes the staging folder before or after the swap, not during it.
        const auto held = hold_interruptions();
        if (renameat2(AT_FDCWD, staging_directory.c_str(), AT_FDCWD, target.c_str(),
                      replaces ? RENAME_EXCHANGE : RENAME_NOREPLACE) != 0)
          throw std::runtime_error("output: could not move the results into " + name + ": " + errno_text());
      }
      committed = true;
      if (replaces) // the staging folder now holds the previous results
        {
          std::error_code ignored;
          fs::remove_all(staging_directory, ignored);
        }
      sync_to_disk(target.parent_path(), "the folder holding " + name);
      release();
    });
    committed = true;
  }

  void publish(const Table &table, const std::string &file, const ResultFolder &results, std::ostream &log,
               const std::string &title)
  {
    if (!title.empty())
      log << title << '\n';
    table.print(log);
    results.write_csv(file, table);
  }
} // namespace penny
