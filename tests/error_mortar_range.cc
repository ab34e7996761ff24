// A value outside the physical range of an entry of a plugin declared in a
// second place: the mortar law's entries under `Mortar material' (the
// detailed model's mortar) are range-checked like those under `Brick
// material', because the law declares its ranges itself.
#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  testing::write_file("error_mortar_range.prm",
                      "set Output directory = results\n"
                      "set Analysis         = wallette\n"
                      "subsection Mortar material\n"
                      "  set Model = mortar\n"
                      "  subsection Mortar\n"
                      "    set Compressive strength = 1e300\n"
                      "  end\n"
                      "end\n");
  testing::check_error(testing::run({"error_mortar_range.prm"}));
}
