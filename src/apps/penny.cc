// penny: runs one penny-gap scene from a deal.II parameter file.
#include "../parameters.h"
#include "../scenes.h"

#include <deal.II/base/mpi.h>

#include <iostream>
#include <string>

namespace
{
  void print_usage(std::ostream &out)
  {
    out << "Usage: penny SCENE.prm          run the scene described by the parameter file\n"
           "       penny --print-parameters write a complete default parameter file to stdout\n"
           "       penny --help             show this text\n"
           "\n"
           "A scene solves the axisymmetric elasticity problem of one penny-shaped gap\n"
           "(a crack of radius c whose faces carry the traction p(r)), computes K_I from\n"
           "domain J-integrals on several rings and prints them beside Sneddon's closed\n"
           "form. Results go to the folder 'Output/Directory': rings.csv, summary.txt,\n"
           "parameters.prm (the parameters used) and, unless switched off, solution.vtu\n"
           "with solution.pvd for ParaView. Examples are in prms/.\n";
  }
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string argument = argc == 2 ? argv[1] : "";
  if (argument == "--help" || argument == "-h")
    {
      print_usage(std::cout);
      return 0;
    }
  if (argument == "--print-parameters")
    {
      dealii::ParameterHandler prm;
      penny::Parameters::declare(prm);
      prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
      return 0;
    }
  if (argc != 2 || argument.empty() || argument[0] == '-')
    {
      std::cerr << "penny: error: expected one parameter file (try 'penny --help')" << std::endl;
      return 2;
    }

  // Under mpirun every rank computes; rank 0 speaks.
  const bool    speaks = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::ostream  silent(nullptr);
  std::ostream &log = speaks ? std::cout : silent;
  try
    {
      dealii::ParameterHandler prm;
      const auto               parameters = penny::Parameters::read(argument, prm);
      penny::run_scene(parameters, prm, log);
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
