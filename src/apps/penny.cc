// penny: runs one scene from a deal.II parameter file.
#include "input/input_error.h"
#include "parallel/interruption.h"
#include "scenes/scene.h"

#include <deal.II/base/mpi.h>

#include <chrono>
#include <cstdlib>
#include <exception>
#include <fcntl.h>
#include <iomanip>
#include <iostream>
#include <string>
#include <thread>
#include <unistd.h>

namespace
{
  void print_usage(std::ostream &out)
  {
    out << "Usage: penny SCENE.prm                  run the scene described by the parameter file\n"
           "       penny --print-parameters [SCENE] the entries SCENE reads, with defaults and "
           "documentation\n"
           "                                        (SCENE defaults to penny-gap)\n"
           "       penny --help                     show this text\n"
           "\n"
           "A parameter file names its scene in the entry 'Scene'. Results go to the folder\n"
           "'Output/Directory', replaced whole by each run. Examples are in prms/. Scenes:\n";
    std::size_t width = 0;
    for (const auto &scene : penny::scene_types())
      width = std::max(width, scene.name.size());
    for (const auto &scene : penny::scene_types())
      out << "  " << std::left << std::setw(width + 2) << scene.name << scene.description << '\n';
  }

  // A message for the user, on one line.
  std::string error_message(const std::exception_ptr &error, const std::string &parameter_file)
  {
    try
      {
        std::rethrow_exception(error);
      }
    catch (const penny::InputError &input_error)
      {
        return penny::one_line(parameter_file + ": " + input_error.what());
      }
    catch (const dealii::ExceptionBase &exception)
      {
        return penny::one_line(exception);
      }
    catch (const std::bad_alloc &)
      {
        return "out of memory: the run needs more memory than it can get (a smaller model needs less: "
               "fewer refinements, a lower degree, fewer grid points)";
      }
    catch (const std::exception &exception)
      {
        return penny::one_line(exception.what());
      }
    catch (...)
      {
        return "unknown failure";
      }
  }

  // Ends a run that failed, with exit status 1. An error on some ranks only
  // would leave the others waiting in a collective operation: each failing
  // rank waits a few seconds, in a non-blocking barrier on its own
  // communicator, for all ranks to fail too; then rank 0 reports. If they do
  // not, the rank reports itself and ends the whole run.
  int fail(MPI_Comm errors, const std::string &message)
  {
    MPI_Request request;
    MPI_Ibarrier(errors, &request);
    const auto deadline   = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    int        all_failed = 0;
    while (!all_failed && std::chrono::steady_clock::now() < deadline)
      {
        MPI_Test(&request, &all_failed, MPI_STATUS_IGNORE);
        if (!all_failed)
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    if (all_failed)
      {
        if (rank == 0)
          std::cerr << "penny: error: " << message << std::endl;
        return 1;
      }
    std::cerr << "penny: error on MPI rank " << rank << " alone: " << message << std::endl;
    MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
} // namespace

int main(int argc, char **argv)
{
  // Descriptors 0-2 left closed by the caller would be taken by the first
  // files MPI or penny open, and the screen output would land in them.
  const bool stdout_closed = fcntl(STDOUT_FILENO, F_GETFD) == -1;
  for (const int descriptor : {STDIN_FILENO, STDOUT_FILENO, STDERR_FILENO})
    if (fcntl(descriptor, F_GETFD) == -1)
      open("/dev/null", descriptor == STDIN_FILENO ? O_RDONLY : O_WRONLY);

  // Open MPI's start-up, cut to what one machine needs (a user's own setting
  // wins): the point-to-point layer ob1, which skips loading the Omni-Path
  // (psm2) plugin whose initialisation sleeps, and, for a run without mpirun,
  // no daemon (orted) forked for the single process.
  setenv("OMPI_MCA_pml", "ob1", 0);
  if (!std::getenv("OMPI_COMM_WORLD_SIZE"))
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);

  penny::handle_interruptions();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPI_Comm                                 errors;
  MPI_Comm_dup(MPI_COMM_WORLD, &errors);
  const std::string argument = argc >= 2 ? argv[1] : "";
  const bool        blank    = argument.find_first_not_of(" \t") == std::string::npos;
  // Under mpirun every rank computes; rank 0 speaks.
  const bool    speaks = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::ostream  silent(nullptr);
  std::ostream &log = speaks ? std::cout : silent;
  // Each line reaches a file or a pipe as it is printed, as on a terminal:
  // progress lines, and what a killed run had printed.
  std::cout << std::unitbuf;
  try
    {
      if (stdout_closed)
        throw std::runtime_error("standard output is closed; penny prints its results there");
      if ((argument == "--help" || argument == "-h") && argc == 2)
        print_usage(log);
      else if (argument == "--print-parameters" && argc <= 3)
        {
          penny::print_parameters(penny::find_scene(argc == 3 ? argv[2] : penny::default_scene), log);
        }
      else if (argc != 2 || blank || argument[0] == '-')
        {
          if (speaks)
            std::cerr << "penny: error: "
                      << (argc == 2 && blank ? "the parameter file's name is empty"
                                             : "expected one parameter file")
                      << " (try 'penny --help')" << std::endl;
          return 2;
        }
      else
        {
          const penny::Verdict verdict = penny::run_scene_file(argument, log);
          if (!verdict.passed)
            {
              if (speaks)
                std::cerr << "penny: FAIL: " << penny::one_line(verdict.message) << std::endl;
              return 1;
            }
          if (!verdict.message.empty())
            log << "PASS: " << verdict.message << std::endl;
        }
      // What penny printed must have arrived: a full disk or a closed pipe is an error.
      if (speaks && !(std::cout << std::flush))
        throw std::runtime_error("could not write to standard output");
    }
  catch (...)
    {
      return fail(errors, error_message(std::current_exception(), argument));
    }
  return 0;
}
