// An analysis that throws during run(): one error line, a non-zero exit code,
// and summary.json with status "error" and the message.
#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::filesystem::remove_all("results");
  testing::write_file("fails.prm",
                      "set Analysis         = test\n"
                      "set Output directory = results\n"
                      "subsection Test\n"
                      "  set Fail during run = true\n"
                      "end\n");
  const testing::Result r = testing::run({"fails.prm"});
  std::cout << "--- screen\n"
            << testing::normalise(r.out) << "--- end of screen\n";
  testing::check_error(r);
  const masonry::Json summary =
    masonry::parse_json(testing::read_file("results/summary.json"));
  std::cout << "summary.json: status = "
            << summary.at("status").get<std::string>()
            << "\n  error = " << summary.at("error").get<std::string>()
            << "\n  files:";
  for (std::size_t i = 0; i < summary.at("files").size(); ++i)
    std::cout << " " << summary.at("files").at(i).get<std::string>();
  std::cout << "\n";
}
