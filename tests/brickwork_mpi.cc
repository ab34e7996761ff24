/**
 * The same softening wallette (stretcher bond, pulled apart, bilinear
 * joints, Gauss points, bricks distorted by 20 % of the mesh spacing) on
 * all ranks and on rank 0 alone: the curves agree to 1e-10 (relative to
 * the peak stress), and so do the joint counts.
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
        "set Platen direction = 0, 0, 1\nset Target strain = 6e-4\n"
        "set Number of steps = 12\nset Interface integration = gauss\n"
        "set Mesh distortion = 0.2\n",
        "subsection Bond\nset Pattern = stretcher\nend\n");
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
        diff = std::max(diff, std::abs(a[i][4] - b[i][4]) / peak);
      check(same && diff < 1e-10, "same curve on 1 and N ranks to 1e-10");
      check(one.at("max_damage").get<double>() > 0.5,
            "the joints soften (damage > 0.5)");
      check(all.at("n_bed_interface_faces").get<double>() ==
              one.at("n_bed_interface_faces").get<double>(),
            "same interfaces");
    }
  MPI_Barrier(MPI_COMM_WORLD);
}
