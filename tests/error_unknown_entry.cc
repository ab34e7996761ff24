// An entry the file sets that no plugin declares: the error names the file, the
// line and the entry.
#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::write_file("error_unknown_entry.prm",
                      "set Analysis         = test\n"
                      "set Output directory = results\n"
                      "subsection Test\n"
                      "  set Lenght = 2\n"
                      "end\n");
  testing::check_error(testing::run({"error_unknown_entry.prm"}));
}
