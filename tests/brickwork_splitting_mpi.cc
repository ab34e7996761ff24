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
  const std::string   text = prm("  set Brick length = 2.0\n"
                                 "  set Brick width = 0.002\n"
                                 "  set Brick height = 0.1\n"
                                 "  set Joint thickness = 0\n"
                                 "  set Courses = 1\n"
                                 "  set Length in bricks = 1\n"
                                 "  set Elements along the length = 40\n"
                                 "  set Elements along the width = 1\n"
                                 "  set Elements along the height = 8\n"
                                 "  set Platen lateral restraint = fixed\n"
                                 "  set Target strain = 0.0006\n"
                                 "  set Number of steps = 60\n"
                                 "  set Splitting interfaces = true\n"
                                 "  set Splitting tensile strength = 1e6\n"
                                 "  set Splitting fracture energy = 50\n"
                                 "  set Splitting compressive strength = 10e6\n"
                                 "  set Splitting stiffness = 1e15\n",
                               "subsection Bond\n  set Pattern = stack\nend\n"
                                 "subsection Brick material\n"
                                 "  set Model = elastic\n"
                                 "  subsection Elastic\n"
                                 "    set Young's modulus = 10e9\n"
                                 "    set Poisson's ratio = -0.25\n"
                                 "  end\n"
                                 "end\n");
  const masonry::Json all  = run("ranks_all", text, MPI_COMM_WORLD);
  if (rank == 0)
    {
      const masonry::Json one = run("ranks_one", text, MPI_COMM_SELF);
      std::cout << "ranks: " << all.at("n_mpi_ranks").as_number() << " and "
                << one.at("n_mpi_ranks").as_number() << "\n";
      const auto   a = curve("ranks_all"), b = curve("ranks_one");
      const double peak = one.at("peak_stress").as_number();
      double       diff = 0;
      bool         same = a.size() == b.size();
      for (unsigned int i = 0; same && i < a.size(); ++i)
        diff = std::max({diff,
                         std::abs(a[i][4] - b[i][4]) / peak,
                         std::abs(a[i][6] - b[i][6])});
      check(same && diff < 1e-8,
            "same curve and interface damage on 1 and N ranks (1e-8)");
      check(one.at("max_damage").as_number() > 0.01,
            "the splitting interface opens (damage > 0.01)");
      check(all.at("n_splitting_interface_faces").as_number() == 8 &&
              one.at("n_splitting_interface_faces").as_number() == 8,
            "the same 8 splitting face pairs");
    }
  MPI_Barrier(MPI_COMM_WORLD);
}
