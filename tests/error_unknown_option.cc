// An unknown command-line option.
#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::check_error(
    testing::run(std::vector<std::string>{"--frobnicate", "x.prm"}));
}
