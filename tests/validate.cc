// `masonry --validate FILE.prm`: reads and checks the file, creates the
// analysis, runs nothing and writes no output directory.
#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::filesystem::remove_all("results");

  testing::write_file("good.prm",
                      "set Analysis         = test\n"
                      "set Output directory = results\n"
                      "subsection Test\n"
                      "  set Length = 4\n"
                      "end\n");
  const testing::Result good = testing::run({"--validate", "good.prm"});
  std::cout << "=== good file\nexit code: " << good.exit_code
            << "\nstdout: " << good.out << "stderr: '" << good.err
            << "'\noutput directory created: "
            << (std::filesystem::exists("results") ? "yes" : "no") << "\n";

  testing::write_file("bad.prm",
                      "set Analysis         = test\n"
                      "set Output directory = results\n"
                      "subsection Test\n"
                      "  set Length = 0\n"
                      "end\n");
  std::cout << "=== bad file\n";
  testing::check_error(testing::run({"--validate", "bad.prm"}));
  std::cout << "output directory created: "
            << (std::filesystem::exists("results") ? "yes" : "no") << "\n";

  std::cout << "=== no file\n";
  testing::check_error(testing::run({"--validate"}));
}
