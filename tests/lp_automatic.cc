/**
 * `Algorithm = automatic` (Clp's explicit dual by the barrier for
 * Mohr–Coulomb LPs, by the primal simplex for no tension no sliding, then
 * the primal simplex on the LP) never returns a worse optimum than an
 * explicit algorithm (dual simplex, primal simplex, barrier with crossover)
 * on mechanism LPs of a semicircular arch (mean radius 5 m, thickness 1 m, 16
 * blocks per half): the settlement of one springing with no tension no sliding
 * and with Mohr–Coulomb joints (maximised work), and the limit load under a
 * horizontal acceleration with Mohr–Coulomb joints (minimised multiplier);
 * and, against the two simplex methods only, the settlement of a barrel of
 * 16 x 12 blocks per half with no tension no sliding (the dual LP's primal
 * simplex from a basis of its free columns).
 * The joints have a tension cut-off and a compression cap, which the
 * automatic route turns into bounds of the normal forces of the dual.
 * "Worse" is measured relative to the explicit algorithm's optimum with a
 * tolerance of 1e-8; every explicit algorithm must reach the same status.
 */
#include <deal.II/base/mpi.h>

#include <string>
#include <vector>

#include "vault_tests.h"

using namespace vault_tests;

namespace
{
  const std::string mohr_coulomb = mohr_coulomb_joints();

  std::string
  algorithm(const std::string &a)
  {
    return "subsection LP solver\n  subsection Clp\n    set Algorithm = " + a +
           "\n  end\nend\n";
  }

  /** Run @p prm with every algorithm; @p key is maximised if @p maximise. */
  void
  compare(const std::string              &name,
          const std::string              &file,
          const std::string              &prm,
          const std::string              &key,
          const bool                      maximise,
          const std::vector<std::string> &algorithms = {"dual simplex",
                                                        "primal simplex",
                                                        "barrier"})
  {
    const masonry::Json automatic =
      run(file + "_automatic", prm + algorithm("automatic"));
    const double best = automatic.at(key).get<double>();
    bool         ok   = automatic.at("status").get<std::string>() == "optimal";
    for (const std::string &a : algorithms)
      {
        const masonry::Json s =
          run(file + "_" + a.substr(0, a.find(' ')), prm + algorithm(a));
        if (s.at("status").get<std::string>() != "optimal")
          {
            ok = false;
            std::cout << "  " << a << ": " << s.at("status").get<std::string>()
                      << "\n";
            continue;
          }
        const double v = s.at(key).get<double>();
        const double worse =
          (maximise ? v - best : best - v) / std::max(std::abs(v), 1e-300);
        if (worse > 1e-8)
          {
            ok = false;
            std::cout << "  " << a << ": " << std::setprecision(17) << v
                      << ", automatic " << best << "\n";
          }
      }
    check(ok,
          name + ": automatic is optimal and no worse than " +
            (algorithms.size() == 3 ?
               "dual simplex, primal simplex or barrier" :
               "dual simplex or primal simplex") +
            " (1e-8)");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string settlement = arch_prm(5, 1, 16, "0; 0; -0.01");
  compare(
    "settlement, no tension no sliding", "nt", settlement, "objective", true);
  compare("settlement, Mohr-Coulomb",
          "mc",
          settlement + mohr_coulomb,
          "objective",
          true);
  compare("limit load, Mohr-Coulomb",
          "limit",
          arch_limit_load_prm(),
          "load_multiplier",
          false);
  // the no-tension route from a basis of the dual LP's free columns (the
  // tangential forces), taken from 2000 rows of the dual LP (LP columns) up:
  // 16 x 12 blocks per half, a settlement varying along the depth, 2304
  // columns (the barrier, slow on these LPs, left out)
  std::string barrel = arch_prm(5, 1, 16, "0; 0; -0.01*y");
  barrel.replace(barrel.find("Blocks along v = 1"), 18, "Blocks along v = 12");
  compare("settlement, no tension no sliding, 16 x 12 blocks per half",
          "nt_barrel",
          barrel,
          "objective",
          true,
          {"dual simplex", "primal simplex"});
}
