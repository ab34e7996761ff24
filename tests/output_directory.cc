// The output-directory contract: parameters.prm, log.txt (the same text as the
// screen) and summary.json (analysis, status, wall_seconds, files, results);
// a second run into the same directory that writes fewer files names the
// earlier run's leftover files on screen and leaves them untouched.
#include "test_analysis.h"
#include "tests.h"

namespace
{
  void
  report(const testing::Result &r)
  {
    std::cout << "exit code: " << r.exit_code << "\nstderr: '" << r.err
              << "'\n--- screen\n"
              << testing::normalise(r.out) << "--- end of screen\n";
    std::cout << "log.txt equals the screen: "
              << (testing::read_file("results/log.txt") == r.out ? "yes" : "no")
              << "\n";
    const masonry::Json summary =
      masonry::parse_json(testing::read_file("results/summary.json"));
    std::cout << "summary.json: analysis = "
              << summary.at("analysis").get<std::string>()
              << ", status = " << summary.at("status").get<std::string>()
              << ", wall_seconds >= 0: "
              << (summary.at("wall_seconds").get<double>() >= 0 ? "yes" : "no")
              << ", length = " << summary.at("length").get<double>()
              << "\n  files:";
    for (std::size_t i = 0; i < summary.at("files").size(); ++i)
      {
        const std::string f = summary.at("files").at(i).get<std::string>();
        std::cout << " " << f
                  << (std::filesystem::exists("results/" + f) ? "" :
                                                                "(missing!)");
      }
    std::cout << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::filesystem::remove_all("results");

  testing::write_file("contract.prm",
                      "set Analysis         = test\n"
                      "set Output directory = results\n"
                      "subsection Test\n"
                      "  set Length          = 2.5\n"
                      "  set Number of files = 3\n"
                      "end\n");
  std::cout << "=== first run: three data files\n";
  report(testing::run({"contract.prm"}));
  std::cout << "--- parameters.prm\n"
            << testing::read_file("results/parameters.prm")
            << "--- end of parameters.prm\n";

  testing::write_file("contract.prm",
                      "set Analysis         = test\n"
                      "set Output directory = results\n"
                      "subsection Test\n"
                      "  set Length          = 3\n"
                      "  set Number of files = 1\n"
                      "end\n");
  std::cout << "\n=== second run into the same directory: one data file\n";
  report(testing::run({"contract.prm"}));
  std::cout << "data-2.txt of the first run untouched: "
            << (testing::read_file("results/data-2.txt") == "file 2 of 3\n" ?
                  "yes" :
                  "no")
            << "\n";
}
