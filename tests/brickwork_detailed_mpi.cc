/**
 * The detailed model (`Model = detailed') in parallel and across a restart:
 * a stack-bonded prism of three units (215 x 102.5 x 65 mm, damage
 * plasticity, f_b = 20 MPa) with two 10 mm mortar layers (damage
 * plasticity, f_m = 5 MPa, E_m = 1 GPa), the `composite' law with stiff
 * contact penalties as the bond, splitting interfaces through the units,
 * IMPL-EX and element deletion, the units' tensile measure averaged over
 * `Nonlocal length' = 30 mm (its points' neighbours lie in cells of both
 * ranks), loaded until the mortar layers flow. The run on
 * all ranks and the run on rank 0 alone give the same curve (stress, largest
 * joint damage and the units' and mortar's largest damages), and a run stopped
 * by `Maximum steps' and resumed from its checkpoint (on all ranks) equals the
 * uninterrupted one.
 */
#include <algorithm>

#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  const std::string wallette = "  set Model = detailed\n"
                               "  set Courses = 3\n"
                               "  set Length in bricks = 1\n"
                               "  set Elements along the length = 4\n"
                               "  set Elements along the width = 2\n"
                               "  set Elements along the height = 2\n"
                               "  set Platen lateral restraint = fixed\n"
                               "  set Target strain = 0.006\n"
                               "  set Number of steps = 30\n"
                               "  set Damage integration = implex\n"
                               "  set Splitting interfaces = true\n"
                               "  set Deletion strain = 0.01\n"
                               "  set Checkpoint interval = 0\n";

  const std::string plugins = "subsection Bond\n  set Pattern = stack\nend\n"
                              "subsection Brick material\n"
                              "  set Model = damage plasticity\n"
                              "  subsection Damage plasticity\n"
                              "    set Young's modulus = 10e9\n"
                              "    set Poisson's ratio = 0.15\n"
                              "    set Compressive strength = 20e6\n"
                              "    set Strain at peak = 0.004\n"
                              "    set Compressive fracture energy = 20000\n"
                              "    set Tensile strength = 2e6\n"
                              "    set Tensile fracture energy = 80\n"
                              "    set Maximum damage = 0.95\n"
                              "    set Nonlocal length = 0.03\n"
                              "  end\n"
                              "end\n"
                              "subsection Mortar material\n"
                              "  set Model = damage plasticity\n"
                              "  subsection Damage plasticity\n"
                              "    set Young's modulus = 1e9\n"
                              "    set Poisson's ratio = 0.2\n"
                              "    set Compressive strength = 5e6\n"
                              "    set Strain at peak = 0.01\n"
                              "    set Compressive fracture energy = 1e6\n"
                              "    set Tensile strength = 0.5e6\n"
                              "    set Tensile fracture energy = 20\n"
                              "    set Maximum damage = 0.95\n"
                              "  end\n"
                              "end\n"
                              "subsection Interface law\n"
                              "  set Law = composite\n"
                              "  set Normal stiffness = 1e13\n"
                              "  set Shear stiffness = 1e13\n"
                              "  subsection Composite\n"
                              "    set Tensile strength = 0.2e6\n"
                              "    set Cohesion = 0.28e6\n"
                              "    set Mode I fracture energy = 15\n"
                              "    set Mode II fracture energy = 100\n"
                              "    set Cap strength = 100e6\n"
                              "  end\n"
                              "end\n";
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const masonry::Json all = run("ranks_all", prm(wallette, plugins));
  run("resumed", prm(wallette + "  set Maximum steps = 12\n", plugins));
  const masonry::Json resumed =
    run("resumed", prm(wallette + "  set Resume = true\n", plugins));
  if (rank == 0)
    {
      const masonry::Json one =
        run("ranks_one", prm(wallette, plugins), MPI_COMM_SELF);
      std::cout << "ranks: " << all.at("n_mpi_ranks").get<double>() << " and "
                << one.at("n_mpi_ranks").get<double>() << "\n";
      const auto a = curve("ranks_all"), b = curve("ranks_one"),
                 c = curve("resumed");
      check(all.at("status").get<std::string>() == "completed" &&
              one.at("status").get<std::string>() == "completed" &&
              resumed.at("status").get<std::string>() == "completed",
            "the three runs complete");
      // the mortar layers yield and damage, and, confined by the units,
      // carry more than their uniaxial strength f_m = 5 MPa
      check(one.at("max_brick_mortar_damage_compression").get<double>() > 0.5,
            "the mortar layers damage in compression (largest damage > 0.5)");
      check(one.at("peak_stress").get<double>() > 5e6,
            "the prism carries more than the mortar's uniaxial strength");
      check(curve_difference(a, b) < 1e-6,
            "same curve (stress, damages of joints, units and mortar) on 1 "
            "and N ranks (1e-6)");
      check(curve_difference(a, c) < 1e-12,
            "the resumed run equals the uninterrupted one (1e-12)");
      check(one.at("n_mortar_cells").get<double>() ==
                all.at("n_mortar_cells").get<double>() &&
              one.at("n_splitting_interface_faces").get<double>() ==
                all.at("n_splitting_interface_faces").get<double>(),
            "the same mortar cells and splitting faces");
    }
  MPI_Barrier(MPI_COMM_WORLD);
}
