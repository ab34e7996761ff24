// An error that one MPI rank sees alone (here rank 1 throws in run() while
// rank 0 waits in a barrier that rank 1 will never join) stops every rank
// within seconds, with a one-line error naming the rank and the cause, a
// non-zero exit and a summary.json that says the run is not complete. Never
// a hang. The test runs itself under `mpirun -np 2` (the child does the run)
// and times it; a hang would be cut by `timeout` after 120 s.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sys/wait.h>

#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  if (argc > 1 && std::string(argv[1]) == "child")
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      // not testing::run(): its captured std::cerr would die with the rank
      return masonry::run_application({"rank.prm"}, MPI_COMM_WORLD);
    }

  std::filesystem::remove_all("results");
  testing::write_file("rank.prm",
                      "set Analysis         = test\n"
                      "set Output directory = results\n"
                      "subsection Test\n"
                      "  set Fail on rank = 1\n"
                      "end\n");
  const auto        start = std::chrono::steady_clock::now();
  const std::string self =
    std::filesystem::read_symlink("/proc/self/exe").string();
  const int status =
    std::system(("timeout 120 mpirun --allow-run-as-root --oversubscribe "
                 "-np 2 '" +
                 self + "' child >child.out 2>child.err")
                  .c_str());
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
  const int         code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  const std::string err  = testing::read_file("child.err");

  std::cout << "exit code non-zero: " << (code != 0 ? "yes" : "no") << "\n"
            << "not cut by the timeout: " << (code != 124 ? "yes" : "no")
            << "\n"
            << "every rank ended within 30 s: " << (seconds < 30 ? "yes" : "no")
            << "\n";
  const std::string expected =
    "masonry: error: rank 1 of 2: a non-finite value in this rank's cells "
    "(on purpose)";
  std::cout << "the error names the rank and the cause: "
            << (err.find(expected) != std::string::npos ? "yes" : "no") << "\n";
  const masonry::Json summary =
    masonry::parse_json(testing::read_file("results/summary.json"));
  std::cout << "summary.json: status "
            << summary.at("status").get<std::string>() << ", complete "
            << (summary.at("complete").get<bool>() ? "yes" : "no") << "\n";
  if (code == 0 || seconds >= 30)
    {
      std::cout << "--- child stderr\n"
                << err << "--- child stdout\n"
                << testing::read_file("child.out");
    }
  return 0;
}
