// penny: runs one scene from a deal.II parameter file.
#include "input/input_error.h"
#include "scenes/scene_registry.h"

#include <deal.II/base/mpi.h>

#include <iomanip>
#include <iostream>
#include <string>

namespace
{
  void print_usage(std::ostream &out)
  {
    out << "Usage: penny SCENE.prm                  run the scene described by the parameter file\n"
           "       penny --print-parameters [SCENE] the entries SCENE reads, with defaults and "
           "documentation\n"
           "                                        (SCENE defaults to the first below)\n"
           "       penny --help                     show this text\n"
           "\n"
           "A parameter file names its scene in the entry 'Scene'. Results go to the folder\n"
           "'Output/Directory', replaced whole by each run. Examples are in prms/. Scenes:\n";
    std::size_t width = 0;
    for (const auto &scene : penny::scene_registry())
      width = std::max(width, scene.name.size());
    for (const auto &scene : penny::scene_registry())
      out << "  " << std::left << std::setw(width + 2) << scene.name << scene.description << '\n';
  }
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        argument = argc >= 2 ? argv[1] : "";
  // Under mpirun every rank computes; rank 0 speaks.
  const bool    speaks = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::ostream  silent(nullptr);
  std::ostream &log = speaks ? std::cout : silent;
  try
    {
      if ((argument == "--help" || argument == "-h") && argc == 2)
        {
          print_usage(log);
          return 0;
        }
      if (argument == "--print-parameters" && argc <= 3)
        {
          dealii::ParameterHandler prm;
          penny::declare_scene(prm, argc == 3 ? penny::find_scene(argv[2]) : penny::scene_registry().front());
          prm.print_parameters(log, dealii::ParameterHandler::PRM);
          return 0;
        }
      if (argc != 2 || argument.empty() || argument[0] == '-')
        {
          if (speaks)
            std::cerr << "penny: error: expected one parameter file (try 'penny --help')" << std::endl;
          return 2;
        }
      const penny::Verdict verdict = penny::run_scene_file(argument, log);
      if (!verdict.passed)
        {
          if (speaks)
            std::cerr << "penny: FAIL: " << verdict.message << std::endl;
          return 1;
        }
      if (!verdict.message.empty())
        log << "PASS: " << verdict.message << std::endl;
    }
  catch (const penny::InputError &error)
    {
      if (speaks)
        std::cerr << "penny: error: " << argument << ": " << error.what() << std::endl;
      return 1;
    }
  catch (const std::exception &error)
    {
      if (speaks)
        std::cerr << "penny: error: " << error.what() << std::endl;
      return 1;
    }
  return 0;
}
