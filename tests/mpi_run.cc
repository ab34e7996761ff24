// The same run on two MPI ranks: the screen output is printed once (by rank
// 0), the files are written once, and summary.json records the ranks.
#include "test_analysis.h"
#include "tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  if (rank == 0)
    {
      std::filesystem::remove_all("results");
      testing::write_file("parallel.prm",
                          "set Analysis         = test\n"
                          "set Output directory = results\n"
                          "subsection Test\n"
                          "  set Length = 2\n"
                          "end\n");
    }
  MPI_Barrier(MPI_COMM_WORLD);

  const testing::Result r = testing::run({"parallel.prm"});
  const auto            sizes =
    dealii::Utilities::MPI::gather(MPI_COMM_WORLD, r.out.size(), 0);
  const auto codes =
    dealii::Utilities::MPI::gather(MPI_COMM_WORLD, r.exit_code, 0);
  if (rank == 0)
    {
      for (unsigned int i = 0; i < sizes.size(); ++i)
        std::cout << "rank " << i << ": exit code " << codes[i]
                  << ", wrote to the screen: " << (sizes[i] > 0 ? "yes" : "no")
                  << "\n";
      std::cout << "--- screen\n"
                << testing::normalise(r.out) << "--- end of screen\n";
      std::cout << "log.txt equals the screen: "
                << (testing::read_file("results/log.txt") == r.out ? "yes" :
                                                                     "no")
                << "\n";
      const masonry::Json summary =
        masonry::parse_json(testing::read_file("results/summary.json"));
      std::cout << "summary.json: status "
                << summary.at("status").get<std::string>() << ", n_mpi_ranks "
                << summary.at("n_mpi_ranks").get<double>() << "\n";
    }

  // an error on all ranks is reported once
  if (rank == 0)
    testing::write_file("bad.prm",
                        "set Analysis = test\n"
                        "set Output directory = results\n"
                        "subsection Test\n"
                        "  set Length = -1\n"
                        "end\n");
  MPI_Barrier(MPI_COMM_WORLD);
  const testing::Result bad = testing::run({"bad.prm"});
  const auto            err_sizes =
    dealii::Utilities::MPI::gather(MPI_COMM_WORLD, bad.err.size(), 0);
  if (rank == 0)
    {
      for (unsigned int i = 0; i < err_sizes.size(); ++i)
        std::cout << "bad file, rank " << i
                  << " wrote to stderr: " << (err_sizes[i] > 0 ? "yes" : "no")
                  << "\n";
      testing::check_error(bad);
    }
}
