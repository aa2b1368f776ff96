// The main of the unit tests (every tests/test_*.cc one suite of the same
// program): deal.II wants MPI initialised first.
#define BOOST_TEST_MODULE penny
#define BOOST_TEST_NO_MAIN
#include <deal.II/base/mpi.h>

#include <boost/test/unit_test.hpp>

bool init_unit_test();

int main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return boost::unit_test::unit_test_main(&init_unit_test, argc, argv);
}
