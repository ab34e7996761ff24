/**
 * Splitting interfaces on several ranks: the unit of brickwork_splitting
 * (thin plate between fixed platens, nu = -0.25, split at mid-length),
 * loaded past the opening of the splitting interface, on all ranks and on
 * rank 0 alone: the curves (stress and largest interface damage) agree to
 * the Newton tolerance.
 */
#include <algorithm>

#include "brickwork_tests.h"

using namespace brickwork_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const std::string   text = splitting_unit(-0.25, 0.0006, 60);
  const masonry::Json all  = run("ranks_all", text, MPI_COMM_WORLD);
  if (rank == 0)
    {
      const masonry::Json one = run("ranks_one", text, MPI_COMM_SELF);
      std::cout << "ranks: " << all.at("n_mpi_ranks").get<double>() << " and "
                << one.at("n_mpi_ranks").get<double>() << "\n";
      const auto   a = curve("ranks_all"), b = curve("ranks_one");
      const double peak = one.at("peak_stress").get<double>();
      double       diff = 0;
      bool         same = a.size() == b.size();
      for (unsigned int i = 0; same && i < a.size(); ++i)
        diff = std::max({diff,
                         std::abs(a[i][4] - b[i][4]) / peak,
                         std::abs(a[i][6] - b[i][6])});
      check(same && diff < 1e-8,
            "same curve and interface damage on 1 and N ranks (1e-8)");
      check(one.at("max_damage").get<double>() > 0.01,
            "the splitting interface opens (damage > 0.01)");
      check(all.at("n_splitting_interface_faces").get<double>() == 8 &&
              one.at("n_splitting_interface_faces").get<double>() == 8,
            "the same 8 splitting face pairs");
    }
  MPI_Barrier(MPI_COMM_WORLD);
}
