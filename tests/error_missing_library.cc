// An `Additional shared libraries` file that does not exist: the error names
// the file, the line and the entry.
#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::write_file(
    "error_missing_library.prm",
    "set Analysis                    = test\n"
    "set Output directory            = results\n"
    "set Additional shared libraries = ./libno_such_plugin.so\n");
  testing::check_error(testing::run({"error_missing_library.prm"}));
}
