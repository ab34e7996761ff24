/**
 * `Adaptation/Reuse evaluations`: the same genetic-algorithm run (fixed
 * seed) with reuse (fitness look-up of repeated gene vectors; in a minimum
 * thickness evaluation also the blocks rescaled for every factor instead of
 * rebuilt) and without it, every evaluation from scratch, in one test:
 *
 * - settlement of an arch (mean radius 5 m, 3 blocks per half, Mohr–Coulomb
 *   joints): the same best fitness and best genes, bit for bit (a look-up
 *   returns the value the evaluation returned), and the same number of
 *   evaluations; the run with reuse looks some up, the other none;
 * - minimum thickness of the same arch (4 blocks per half, no tension no
 *   sliding): the same best thickness factor, bit for bit (the rescaled
 *   blocks are the rebuilt ones to the last bit, and every bisection starts
 *   without a basis from another mesh), and the final analysis of the best
 *   mesh gives its fitness again;
 * - the minimum thickness of the uniform arch (8 blocks per half) with
 *   `LP solver/Warm starts = false' (every LP of the bisection solved from
 *   scratch): the factor of the run with warm starts within the bisection
 *   tolerance (1e-6) plus the scatter that the LP tolerances leave near the
 *   minimum (documented as about 1e-5 relative, doc/rigid-blocks.md), with
 *   more simplex iterations. (A genetic algorithm is not compared this way:
 *   evaluations that differ by the LP tolerances change its selection, and
 *   the runs with and without warm starts end at different meshes.)
 */
#include <deal.II/base/mpi.h>

#include "vault_tests.h"

using namespace vault_tests;

namespace
{
  std::string
  adaptation(const bool reuse)
  {
    return std::string("subsection Adaptation\n  set Optimiser = genetic\n"
                       "  set Population size = 8\n  set Generations = 6\n"
                       "  set Stall generations = 3\n  set Seed = 3\n"
                       "  set Reuse evaluations = ") +
           (reuse ? "true" : "false") + "\nend\n";
  }

  std::string
  thickness_prm(const bool         reuse,
                const bool         warm_starts     = true,
                const unsigned int n_u             = 4,
                const bool         with_adaptation = true)
  {
    return std::string(
             "set Analysis = minimum thickness\n"
             "subsection Geometry model\n  set Model name = arch\n"
             "  set Thickness = 0.5\n  set Density = 2000\n"
             "  subsection Arch\n    set Span = 10\n    set Rise = 5\n"
             "    set Depth = 1\n  end\nend\n"
             "subsection Minimum thickness\n  set Blocks along u = ") +
           std::to_string(n_u) +
           "\n  set Blocks along v = 1\n  set Stations per edge = 2\n"
           "  set Tolerance = 1e-6\n  set Write picture = false\nend\n"
           "subsection LP solver\n  set Warm starts = " +
           (warm_starts ? "true" : "false") + "\nend\n" +
           (with_adaptation ? adaptation(reuse) : std::string());
  }

  const std::string mohr_coulomb =
    "subsection Interface model\n  set Model = mohr coulomb\n"
    "  subsection Mohr coulomb\n    set Friction coefficient = 0.6\n"
    "    set Cohesion = 0\n    set Tensile strength = 0\n  end\nend\n";

  bool
  same_genes(const masonry::Json &a, const masonry::Json &b)
  {
    const auto &ga   = a.at("adaptation").at("best_genes");
    const auto &gb   = b.at("adaptation").at("best_genes");
    bool        same = ga.size() == gb.size();
    for (unsigned int i = 0; same && i < ga.size(); ++i)
      same = ga.at(i).get<double>() == gb.at(i).get<double>();
    return same;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const std::string settlement =
    arch_prm(5, 1, 3, "0; 0; -0.01") + mohr_coulomb;
  const masonry::Json a = run("settlement_reuse", settlement + adaptation(1));
  const masonry::Json b = run("settlement_scratch", settlement + adaptation(0));
  const auto         &aa = a.at("adaptation");
  const auto         &ba = b.at("adaptation");
  check(aa.at("best_fitness").get<double>() ==
          ba.at("best_fitness").get<double>(),
        "settlement: the same best fitness with and without reuse");
  check(same_genes(a, b), "settlement: the same best genes");
  check(aa.at("evaluations").get<double>() ==
          ba.at("evaluations").get<double>(),
        "settlement: the same number of evaluations");
  check(aa.at("repeated_evaluations").get<double>() > 0 &&
          ba.at("repeated_evaluations").get<double>() == 0,
        "settlement: repeated gene vectors looked up with reuse only");

  const masonry::Json c  = run("thickness_reuse", thickness_prm(true));
  const masonry::Json d  = run("thickness_scratch", thickness_prm(false));
  const double        fc = c.at("adaptation").at("best_fitness").get<double>();
  const double        fd = d.at("adaptation").at("best_fitness").get<double>();
  check(fc == fd,
        "minimum thickness: the same best factor with and without reuse");
  check(c.at("minimum_thickness_factor").get<double>() == fc,
        "minimum thickness: the best mesh analysed again gives its fitness");

  const masonry::Json w =
    run("thickness_warm", thickness_prm(true, true, 8, 0));
  const masonry::Json e =
    run("thickness_cold", thickness_prm(true, false, 8, 0));
  const double fw = w.at("minimum_thickness_factor").get<double>();
  const double fe = e.at("minimum_thickness_factor").get<double>();
  check(std::abs(fe - fw) <= 1e-5 * fw,
        "minimum thickness: the same factor with and without warm starts "
        "(1e-5)");
  check(e.at("lp_iterations").get<double>() >
          w.at("lp_iterations").get<double>(),
        "minimum thickness: the run without warm starts needs more simplex "
        "iterations");
}
