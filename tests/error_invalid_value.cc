// A value that passes its pattern but is rejected by the plugin with
// masonry::ExcParameter: the message has `file:line: entry 'Section/Entry'`.
#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::write_file("error_invalid_value.prm",
                      "set Analysis         = test\n"
                      "set Output directory = results\n"
                      "\n"
                      "subsection Test\n"
                      "  # negative on purpose\n"
                      "  set Length = -2.5\n"
                      "end\n");
  testing::check_error(testing::run({"error_invalid_value.prm"}));
}
