// Included files (issue 18, robust reading): a file that is included with
// its own UTF-8 byte-order mark (Windows editors) is read like the main
// file, and an error in an included file names that file and its line, not
// the line of the text deal.II was given (the includes are inlined).
// Checked: a main file and an included file, both with a byte-order mark,
// are valid; a bad value after the mark of an included file names
// inc-bad.prm:2; `springing  right' (two spaces) in an included file is
// normalised like in the main file; an unknown entry after the include
// names its own line of the main file.
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        bom = "\xEF\xBB\xBF";
  testing::write_file("inc-bom.prm",
                      bom + "subsection Wallette\n"
                            "  set Courses = 3\n"
                            "end\n");
  testing::write_file("main.prm",
                      bom + "set Analysis = wallette\n"
                            "subsection Wallette\n"
                            "  set Courses = 5\n"
                            "end\n"
                            "include inc-bom.prm\n");
  testing::Result r = testing::run({"--validate", "main.prm"});
  std::cout << "main with byte-order mark includes a file with one: exit "
            << r.exit_code << ", " << r.out;

  testing::write_file("inc-bad.prm",
                      bom + "subsection Wallette\n"
                            "  set Courses = 0\n"
                            "end\n");
  testing::write_file("bad.prm",
                      "set Analysis = wallette\n"
                      "include inc-bad.prm\n");
  testing::check_error(testing::run({"--validate", "bad.prm"}));

  // (read by deal.II itself, the included lines kept the double spaces:
  // "entry 'Settlement/Supported edges' (default value): no free edge is
  // labelled 'springing right'")
  testing::write_file("inc-spaces.prm",
                      bom + "subsection Settlement\n"
                            "  set Supported edges = springing left, "
                            "springing  right\n"
                            "  set Settling edges = springing  right\n"
                            "end\n");
  testing::write_file("spaces.prm",
                      "set Analysis = settlement\n"
                      "include inc-spaces.prm\n");
  r = testing::run({"--validate", "spaces.prm"});
  std::cout << "double spaces in an included file: exit " << r.exit_code << ", "
            << r.out;

  testing::write_file("after.prm",
                      "set Analysis = wallette\n"
                      "include inc-bom.prm\n"
                      "subsection Wallette\n"
                      "  set Corses = 2\n"
                      "end\n");
  testing::check_error(testing::run({"--validate", "after.prm"}));
}
