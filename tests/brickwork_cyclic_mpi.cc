/**
 * A small stretcher-bonded wallette with damage-plasticity bricks, bilinear
 * joints, strength scatter and element deletion under two load-unload
 * cycles into the softening branch (IMPL-EX), on all ranks and on rank 0
 * alone: the curves agree to the Newton tolerance, 1e-8 of the peak stress
 * (the partitions sum in a different order; the differences seen are
 * 2e-10), and the same cells are deleted.
 */
#include "brickwork_tests.h"

using namespace brickwork_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const std::string text =
    prm("set Courses = 3\nset Length in bricks = 2\n"
        "set Elements along the length = 4\n"
        "set Elements along the width = 1\n"
        "set Elements along the height = 1\n"
        "set Protocol = cyclic\nset Cycle amplitudes = 0.003, 0.006\n"
        "set Target strain = 0.006\nset Number of steps = 30\n"
        "set Strength scatter = 0.15\nset Random seed = 7\n"
        "set Deletion strain = 0.0015\nset Linear solver = direct\n"
        "set Damage integration = implex\n",
        "subsection Bond\nset Pattern = stretcher\nend\n"
        "subsection Brick material\nset Model = damage plasticity\nend\n");
  const masonry::Json all = run("ranks_all", text, MPI_COMM_WORLD);
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
        {
          diff = std::max(diff, std::abs(a[i][4] - b[i][4]) / peak);
          same = a[i][10] == b[i][10];
        }
      check(
        same && diff < 1e-8,
        "same curve (to the Newton tolerance 1e-8) and deleted cells on 1 and N ranks");
      check(one.at("max_brick_damage_compression").get<double>() > 0.1,
            "the bricks are damaged in compression");
      check(one.at("status").get<std::string>() == "completed" &&
              one.at("deleted_cells").get<double>() > 0,
            "completed, with cells deleted");
    }
  MPI_Barrier(MPI_COMM_WORLD);
}
