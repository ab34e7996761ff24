/**
 * The no-tension route of `automatic` with `Crossover = never` (the
 * default): from 2000 rows of the explicit dual LP up, Clp's barrier solves
 * the dual with its unbounded contact forces bounded by the total load, and
 * its interior point is kept when it checks out on the LP itself.
 *
 * - A semicircular arch (mean radius 5 m, thickness 1 m, 200 blocks per
 *   half: 2400 rows of the dual LP) with no tension no sliding joints under
 *   a settlement of one springing: the run keeps the interior point, its
 *   optimum equals the vertex of `Crossover = always` (an independent solve:
 *   the primal simplex on the dual, then the clean-up) to 1e-8 relative, and
 *   it finds the same cracks and hinges.
 * - The limit load of the same arch under a horizontal acceleration: its
 *   dual LP has a column of 400 entries (the load multiplier's), and such
 *   LPs stay on the simplex (the boxed barrier's point missed the check
 *   there): the vertex's multiplier to 1e-12.
 * - The Bothwell vertical settlement example (prm/examples, 12 x 16 blocks
 *   per half: 2304 rows) with no tension no sliding joints: no block moves
 *   at the vertex (its optimum is 0: the settling support separates), and
 *   the interior point's optimum is within 1e-8 of the loads' work at the
 *   settlement, W delta (the scale of the check; a settlement that moves a
 *   block does work of that order), with the same cracks.
 * - The horizontal settlement example with the same joints cannot follow
 *   without sliding: `incompatible` with either setting (the LP's own
 *   verdict: `Check support motion = false`, since the direct check sees
 *   it). The boxed dual then has its optimum at the bound, its point fails
 *   the check on the LP far off, and phase 1 decides.
 */
#include <deal.II/base/mpi.h>

#include "vault_tests.h"

using namespace vault_tests;

namespace
{
  const std::string no_tension = "  set Model = no tension no sliding\n";

  std::string
  crossover(const std::string &c)
  {
    return "subsection LP solver\n  subsection Clp\n    set Crossover = " + c +
           "\n  end\nend\n";
  }

  bool
  kept_interior(const masonry::Json &s)
  {
    return s.at("lp_message").get<std::string>().find("no crossover") !=
           std::string::npos;
  }

  /** Example @p name of prm/examples at 12 x 16 blocks per half with no
   *  tension no sliding joints. */
  std::string
  example(const std::string &name)
  {
    const std::string text = example_text(name);
    check(!text.empty(), name + " is read");
    return text +
           "subsection Settlement\n  set Blocks along u = 12\n"
           "  set Blocks along v = 16\n  set Write picture = false\nend\n"
           "subsection Interface model\n" +
           no_tension + "end\n";
  }

  /** Run @p prm with both settings; check the statuses, the interior point
   *  and the cracks; return the two summaries (never, always). */
  std::pair<masonry::Json, masonry::Json>
  both(const std::string &name, const std::string &prm)
  {
    const masonry::Json never = run(name + "_never", prm + crossover("never"));
    const masonry::Json always =
      run(name + "_always", prm + crossover("always"));
    const bool optimal = never.at("status").get<std::string>() == "optimal" &&
                         always.at("status").get<std::string>() == "optimal";
    check(optimal && kept_interior(never) && !kept_interior(always),
          name + ": `never' keeps the interior point");
    check(optimal &&
            never.at("n_cracks").get<double>() ==
              always.at("n_cracks").get<double>() &&
            never.at("n_hinges").get<double>() ==
              always.at("n_hinges").get<double>(),
          name + ": the same cracks and hinges as the vertex");
    return {never, always};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  {
    const auto [never, always] =
      both("arch",
           arch_prm(5, 1, 200, "0; 0; -0.01") + "subsection Interface model\n" +
             no_tension + "end\n");
    const double error = relative(never.at("objective").get<double>(),
                                  always.at("objective").get<double>());
    if (!(error <= 1e-8))
      std::cout << "  relative difference " << error << "\n";
    check(always.at("objective").get<double>() > 0 && error <= 1e-8,
          "arch: the same optimum as the vertex (1e-8)");
  }
  {
    std::string limit = arch_limit_load_prm();
    limit.replace(limit.find("Blocks along u = 16"),
                  19,
                  "Blocks along u = 200");
    limit += "subsection Interface model\n" + no_tension + "end\n";
    const masonry::Json never = run("limit_never", limit + crossover("never"));
    const masonry::Json always =
      run("limit_always", limit + crossover("always"));
    const bool optimal = never.at("status").get<std::string>() == "optimal" &&
                         always.at("status").get<std::string>() == "optimal";
    const double error =
      optimal ? relative(never.at("load_multiplier").get<double>(),
                         always.at("load_multiplier").get<double>()) :
                1.;
    if (!(error <= 1e-12))
      std::cout << "  relative difference " << error << "\n";
    check(optimal && !kept_interior(never) && error <= 1e-12,
          "limit load: the simplex's vertex with either setting (1e-12)");
  }
  {
    const auto [never, always] =
      both("bothwell", example("bothwell-vertical-settlement"));
    const double scale = never.at("total_weight").get<double>() *
                         never.at("max_settlement").get<double>();
    const double difference = std::abs(never.at("objective").get<double>() -
                                       always.at("objective").get<double>());
    if (!(difference <= 1e-8 * scale))
      std::cout << "  difference " << difference << " J, W delta " << scale
                << " J\n";
    check(std::abs(always.at("objective").get<double>()) <= 1e-8 * scale &&
            difference <= 1e-8 * scale,
          "bothwell: the optimum 0 of the vertex to 1e-8 W delta");
  }
  for (const std::string c : {"never", "always"})
    {
      const masonry::Json spreading =
        run("spreading_" + c,
            example("bothwell-horizontal-settlement") + crossover(c) +
              "subsection Settlement\n  set Check support motion = false\n"
              "end\n");
      check(spreading.at("status").get<std::string>() == "incompatible",
            "bothwell, horizontal settlement, Crossover = " + c +
              ": incompatible");
    }
}
