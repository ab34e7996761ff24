/**
 * `Crossover = never` (subsection LP solver/Clp): Clp's barrier stops at its
 * interior point, mapped back from the explicit dual LP (`automatic`) or
 * taken as it is (`barrier`), when that point checks out on the LP.
 *
 * - A semicircular arch (mean radius 5 m, thickness 1 m, 16 blocks per half,
 *   Mohr-Coulomb joints with cohesion, tension cut-off and compression cap)
 *   under a settlement of one springing, and its limit load under a
 *   horizontal acceleration: with `never` the run reports that it kept the
 *   interior point (lp_message), and its optimum equals the vertex of
 *   `Crossover = always` (an independent solve: barrier, crossover and the
 *   simplex's clean-up) to 1e-8 relative, for `automatic` and for
 *   `barrier`; also the limit load at 200 blocks per half, whose dual LP
 *   has a dense column (the load multiplier's) that the barrier's
 *   factorisation takes as dense when its point may be kept.
 * - With the default settings (no `Crossover` entry) the settlement run
 *   keeps the interior point: `never` is the default.
 * - The statuses stay the simplex's: the same arch at t/R = 0.06 without
 *   settlement and cohesionless joints (well below the minimum thickness)
 *   is a `mechanism`; two blocks with bonded supports, one settling, cannot
 *   follow without slip at the crown, which cohesionless associative joints
 *   allow only with opening: `incompatible` (the LP's own verdict, with
 *   `Check support motion = false`: the direct check sees this one).
 */
#include <deal.II/base/mpi.h>

#include "vault_tests.h"

using namespace vault_tests;

namespace
{
  const std::string mohr_coulomb = mohr_coulomb_joints();

  const std::string cohesionless =
    "subsection Interface model\n  set Model = mohr coulomb\n"
    "  subsection Mohr coulomb\n    set Friction coefficient = 0.6\n"
    "  end\nend\n";

  std::string
  solver(const std::string &algorithm, const std::string &crossover)
  {
    return "subsection LP solver\n  subsection Clp\n    set Algorithm = " +
           algorithm + "\n    set Crossover = " + crossover + "\n  end\nend\n";
  }

  bool
  kept_interior(const masonry::Json &s)
  {
    return s.at("lp_message").get<std::string>().find("no crossover") !=
           std::string::npos;
  }

  void
  compare(const std::string &name,
          const std::string &file,
          const std::string &prm,
          const std::string &key)
  {
    for (const std::string a : {"automatic", "barrier"})
      {
        const std::string   f = file + "_" + a;
        const masonry::Json vertex =
          run(f + "_always", prm + solver(a, "always"));
        const masonry::Json interior =
          run(f + "_never", prm + solver(a, "never"));
        const bool optimal =
          vertex.at("status").get<std::string>() == "optimal" &&
          interior.at("status").get<std::string>() == "optimal";
        check(optimal && kept_interior(interior) && !kept_interior(vertex),
              name + ", " + a + ": `never' keeps the interior point");
        const double error = optimal ? relative(interior.at(key).get<double>(),
                                                vertex.at(key).get<double>()) :
                                       1.;
        if (!(error <= 1e-8))
          std::cout << "  relative difference " << error << "\n";
        check(error <= 1e-8,
              name + ", " + a + ": the same optimum as the vertex (1e-8)");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        settlement =
    arch_prm(5, 1, 16, "0; 0; -0.01") + mohr_coulomb;
  compare("settlement", "settlement", settlement, "objective");
  compare("limit load", "limit", arch_limit_load_prm(), "load_multiplier");
  // 200 blocks per half: the multiplier's column of the dual LP has 400
  // entries, a dense column for the barrier's factorisation
  std::string fine = arch_limit_load_prm();
  fine.replace(fine.find("Blocks along u = 16"), 19, "Blocks along u = 200");
  compare("limit load, 200 blocks per half",
          "limit_fine",
          fine,
          "load_multiplier");
  // `never' is the default (since 2026-11-29): a run without the entry
  // keeps the interior point
  const masonry::Json by_default = run("settlement_default", settlement);
  check(by_default.at("status").get<std::string>() == "optimal" &&
          kept_interior(by_default),
        "settlement, default settings: the interior point is kept");

  for (const std::string c : {"always", "never"})
    {
      const masonry::Json thin = run("thin_" + c,
                                     arch_prm(5, 0.3, 16, "0; 0; 0") +
                                       cohesionless + solver("automatic", c));
      check(thin.at("status").get<std::string>() == "mechanism",
            "t/R = 0.06, cohesionless, Crossover = " + c + ": mechanism");
      const masonry::Json bonded =
        run("bonded_" + c,
            arch_prm(5, 1, 1, "0; 0; -0.01", "bonded") + cohesionless +
              solver("automatic", c) +
              "subsection Settlement\n  set Check support motion = false\n"
              "end\n");
      check(bonded.at("status").get<std::string>() == "incompatible",
            "two blocks, bonded supports, Crossover = " + c + ": incompatible");
    }
}
