// An output directory that cannot be created: a path below a regular file.
#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::write_file("error_output_directory.prm",
                      "set Analysis         = test\n"
                      "set Output directory = afile/sub\n");
  testing::write_file("afile", "a regular file, not a directory\n");
  testing::check_error(testing::run({"error_output_directory.prm"}));
}
