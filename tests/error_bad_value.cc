// A value that does not match the pattern of its entry: an analysis that is not
// registered.
#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::write_file("error_bad_value.prm",
                      "set Output directory = results\n"
                      "set Analysis         = no such analysis\n");
  testing::check_error(testing::run({"error_bad_value.prm"}));
}
