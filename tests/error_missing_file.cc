// A parameter file that does not exist.
#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::check_error(
    testing::run(std::vector<std::string>{"no-such-file.prm"}));
}
