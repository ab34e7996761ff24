/**
 * Adaptation of a settlement whose uniform mesh is incompatible: a barrel
 * vault (span 6 m, rise 3 m, length 6 m, 2 x 2 blocks per half) with no
 * tension no sliding joints whose supports move along x by 0.01 y / 6 m.
 * The uniform mesh's analysis (an independent run without adaptation) is
 * `incompatible'. With the genetic algorithm and with crack refinement the
 * run ends as that one does: status `incompatible', exit code 0, the
 * adaptation stopped after the one evaluation of the uniform mesh, and
 * summary.json without a fitness (before, the uniform fitness -inf stopped
 * both runs as `failed': "the result ... is not a finite number").
 */
#include "vault_tests.h"

using namespace vault_tests;

namespace
{
  const std::string barrel =
    barrel_prm(2, "0.01*y/6; 0; 0", "  set Model = no tension no sliding\n");

  /** Whether run @p s ended incompatible after one evaluation, with no
   * fitness in its summary. */
  bool
  stopped(const masonry::Json &s)
  {
    const auto &a = s.at("adaptation");
    return s.at("status").get<std::string>() == "incompatible" &&
           a.at("evaluations").get<double>() == 1 &&
           !a.contains("best_fitness") && !a.contains("uniform_fitness") &&
           a.contains("stopped");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check(run("uniform", barrel).at("status").get<std::string>() ==
          "incompatible",
        "uniform mesh: incompatible");
  check(stopped(run("genetic",
                    barrel + "subsection Adaptation\n"
                             "  set Optimiser = genetic\nend\n")),
        "genetic: incompatible, stopped after the uniform mesh");
  check(stopped(run("crack",
                    barrel + "subsection Adaptation\n"
                             "  set Optimiser = crack refinement\nend\n")),
        "crack refinement: incompatible, stopped after the uniform mesh");
}
