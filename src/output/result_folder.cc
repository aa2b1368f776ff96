#include "output/result_folder.h"

#include "input/input_error.h"

#include <deal.II/base/mpi.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
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

    // Runs `action` on rank 0; the message of an exception it throws reaches
    // every rank, where it is thrown again (as InputError if it was one).
    template <typename Action> void on_rank_zero_for_all(Action &&action)
    {
      std::string message;
      bool        input_error = false;
      if (on_rank_zero())
        try
          {
            action();
          }
        catch (const InputError &error)
          {
            message     = error.what();
            input_error = true;
          }
        catch (const std::exception &error)
          {
            message = error.what();
          }
      message     = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, message, 0);
      input_error = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, input_error, 0);
      if (message.empty())
        return;
      if (input_error)
        throw InputError(message);
      throw std::runtime_error(message);
    }

    // On rank 0: `contents` into `path`, or an exception.
    void write_file(const fs::path &path, const std::string &contents)
    {
      std::ofstream out(path, std::ios::binary);
      out << contents;
      out.close();
      if (!out)
        throw std::runtime_error("output: could not write " + path.string());
    }

    std::string errno_text()
    {
      return std::strerror(errno);
    }
  } // namespace

  ResultFolder::ResultFolder(const fs::path &directory, const fs::path &input_file)
      : final_directory(directory)
  {
    const fs::path target = directory.empty() ? fs::path(".") : directory;
    on_rank_zero_for_all([&]() {
      const std::string entry = "Output/Directory = '" + directory.string() + "'";
      std::error_code   error;
      if (fs::exists(target, error))
        {
          if (!fs::is_directory(target))
            throw InputError(entry + " is not a folder");
          const auto inside = [&](const fs::path &path) {
            const fs::path relative = fs::weakly_canonical(path).lexically_relative(fs::canonical(target));
            return !relative.empty() && *relative.begin() != "..";
          };
          if (inside(fs::current_path()))
            throw InputError(entry + " holds the working folder; a run replaces its output folder whole");
          if (!input_file.empty() && inside(input_file))
            throw InputError(entry + " holds the parameter file '" + input_file.string() +
                             "'; a run replaces its output folder whole");
          if (!fs::is_empty(target) && !fs::exists(target / marker))
            throw InputError(entry + " holds files penny did not write; name a new or empty folder (a run "
                                     "replaces its output folder whole)");
        }
      const fs::path parent = fs::absolute(target).lexically_normal().parent_path();
      fs::create_directories(parent, error);
      std::string pattern =
          (parent / ("." + fs::absolute(target).lexically_normal().filename().string() + ".staging-XXXXXX"))
              .string();
      if (error || access(parent.c_str(), W_OK) != 0 || !mkdtemp(pattern.data()))
        throw InputError(entry + " cannot be created or is not writable");
      staging_directory = pattern;
      write_file(staging_directory / marker,
                 "results of penny, replaced whole by the next run into this folder\n");
    });
    staging_directory = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, staging_directory.string(), 0);
  }

  ResultFolder::~ResultFolder()
  {
    if (!committed && on_rank_zero())
      {
        std::error_code ignored;
        fs::remove_all(staging_directory, ignored);
      }
  }

  void ResultFolder::write(const std::string &file, const std::string &contents) const
  {
    on_rank_zero_for_all([&]() { write_file(staging_directory / file, contents); });
  }

  void ResultFolder::write_csv(const std::string &file, const Table &table) const
  {
    write(file, table.csv());
  }

  // With the target in place, the two folders swap names in one step
  // (renameat2 RENAME_EXCHANGE), and the previous results are removed.
  void ResultFolder::commit()
  {
    on_rank_zero_for_all([&]() {
      const fs::path  target = final_directory.empty() ? fs::path(".") : final_directory;
      std::error_code error;
      if (fs::exists(target, error))
        {
          if (renameat2(AT_FDCWD, staging_directory.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) != 0)
            throw std::runtime_error("output: could not move the results into " + target.string() + ": " +
                                     errno_text());
          fs::remove_all(staging_directory, error);
        }
      else if (renameat2(AT_FDCWD, staging_directory.c_str(), AT_FDCWD, target.c_str(), RENAME_NOREPLACE) !=
               0)
        throw std::runtime_error("output: could not move the results into " + target.string() + ": " +
                                 errno_text());
    });
    committed = true;
  }
} // namespace penny
