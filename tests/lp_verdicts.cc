/**
 * The LP's own verdicts and the check of every optimum
 * (doc/rigid-blocks.md, Statuses):
 *
 * - Mechanisms: a semicircular arch (R = 3 m) of thickness t = 0.15 m,
 *   t/R = 0.05, below the 0.1075 that a semicircular arch of no-tension
 *   joints needs to stand under its own weight (Milankovitch; Heyman), on
 *   unilateral supports with a settlement of 1 cm outwards: `mechanism`,
 *   with Mohr-Coulomb joints without cohesion and tensile strength (the
 *   barrier route, whose diverging dual is decided by the ray LP: the
 *   mechanism found moves blocks) and with no tension no sliding joints
 *   (the simplex route, decided by phase 1); GLPK agrees. At t = 0.5 m
 *   (t/R = 0.17) the same arches stand: `optimal`.
 * - An incompatible settlement that the direct check cannot see: a barrel
 *   vault with no tension no sliding joints bonded to both springings,
 *   whose right springing moves 1 cm along the axis (a rigid motion of
 *   every supported block; the rings between the springings would have to
 *   slide). GLPK's simplex, an independent solver, finds the LP
 *   infeasible; masonry's default route says `incompatible` by its phase
 *   1 and names a joint (kind `lp`), with a least total misfit > 0.
 * - GLPK's optimum checked: a dome (span 9.63 m, rise 4.09 m, 4 x 3 x 3
 *   blocks, Mohr-Coulomb joints without a cap, unilateral, horizontal
 *   settlement 1 cm x x/span) for which GLPK's dual simplex returns a
 *   point that violates a row by about 2e-3 (its tolerances apply to its
 *   scaled problem): the check sees it and the re-solve on the unscaled
 *   problem passes, with Clp's optimum (1e-7).
 * - No silent "optimal" from any back-end: a back-end registered here
 *   returns Clp's optimum with one block's velocity moved by 1e-3 and does
 *   not check it; the run warns (log.txt), and summary.json has
 *   `lp_check` = `failed` and a violation of at least 1e-4 (the row of the
 *   jump across the thickness at the springing, radial there, moves by
 *   about 1e-3).
 */
#include <masonry/lp/interface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include "vault_tests.h"

using namespace vault_tests;

namespace
{
  /** Clp's optimum, perturbed and unchecked (see the file's comment). */
  class PerturbedClp : public masonry::lp::Interface
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &)
    {}

    masonry::lp::Solution
    solve(const masonry::lp::LinearProgram &lp) const override
    {
      dealii::ParameterHandler prm;
      masonry::plugins::Registry<masonry::lp::Interface>::declare_parameters(
        prm);
      const auto clp =
        masonry::plugins::Registry<masonry::lp::Interface>::create(prm, "clp");
      masonry::lp::Solution s = clp->solve(lp);
      if (s.status == masonry::lp::Status::optimal)
        {
          s.x[0] += 1e-3;
          s.objective = lp.objective_value(s.x);
          s.checked   = false;
        }
      return s;
    }
  };

  const std::string mohr_coulomb_no_cohesion =
    "subsection Interface model\n  set Model = mohr coulomb\n"
    "  subsection Mohr coulomb\n    set Cohesion = 0\n"
    "    set Friction coefficient = 0.6\n    set Tensile strength = 0\n"
    "    set Compressive strength = 3e5\n  end\nend\n";
  const std::string no_tension =
    "subsection Interface model\n  set Model = no tension no sliding\nend\n";

  std::string
  text(const masonry::Json &s, const std::string &key)
  {
    return s.contains(key) ? s.at(key).get<std::string>() : "";
  }
} // namespace

MASONRY_REGISTER_LP_SOLVER(PerturbedClp,
                           "perturbed clp",
                           "Clp's optimum moved by 1e-3 (a test).")

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // mechanisms, and the same arches standing when thick
  for (const auto &[name, joints] :
       {std::make_pair(std::string("mohr-coulomb"), mohr_coulomb_no_cohesion),
        std::make_pair(std::string("no-tension"), no_tension)})
    {
      const masonry::Json thin =
        run("thin-" + name, arch_prm(3, 0.15, 8, "0.01; 0; 0") + joints);
      const masonry::Json glpk =
        run("thin-" + name + "-glpk",
            arch_prm(3, 0.15, 8, "0.01; 0; 0", "unilateral", "glpk") + joints);
      const masonry::Json thick =
        run("thick-" + name, arch_prm(3, 0.5, 8, "0.01; 0; 0") + joints);
      check(thin.at("status").get<std::string>() == "mechanism" &&
              glpk.at("status").get<std::string>() == "mechanism",
            name + ": t/R = 0.05 is a mechanism (Clp and GLPK)");
      check(thick.at("status").get<std::string>() == "optimal",
            name + ": t/R = 0.17 stands");
      if (name == "mohr-coulomb")
        check(thin.at("mechanism_blocks").get<double>() > 0 &&
                text(thin, "lp_message").find("ray") != std::string::npos,
              name + ": decided by the ray LP, whose mechanism moves blocks");
    }

  // incompatible beyond the direct check
  {
    std::string prm =
      barrel_prm(4, "0; 0.01; 0", "  set Model = no tension no sliding\n");
    const std::string at = "subsection Settlement\n";
    prm.insert(prm.find(at) + at.size(), "  set Support contact = bonded\n");
    const masonry::Json clp = run("axial", prm);
    const masonry::Json glpk =
      run("axial-glpk",
          prm + "subsection LP solver\n  set Solver = glpk\nend\n");
    check(glpk.at("status").get<std::string>() == "incompatible",
          "axial shift of a bonded springing: GLPK finds the LP infeasible");
    check(clp.at("support_check").at("largest_misfit").get<double>() < 1e-12 &&
            clp.at("status").get<std::string>() == "incompatible" &&
            clp.at("incompatibility").at("kind").get<std::string>() == "lp" &&
            clp.at("incompatibility").at("total_misfit").get<double>() > 0,
          "the direct check passes it; the LP's phase 1 finds it "
          "incompatible and names a joint");
  }

  // GLPK's optimum that fails the check, solved again
  {
    const std::string dome =
      "set Analysis = settlement\n"
      "subsection Geometry model\n  set Model name = dome\n"
      "  set Thickness = 0.840151\n  set Density = 2083.9\n"
      "  subsection Dome\n    set Span = 9.62758\n    set Rise = 4.08517\n"
      "  end\nend\n"
      "subsection Settlement\n  set Blocks along u = 3\n"
      "  set Blocks along v = 3\n  set Stations per edge = 2\n"
      "  set Supported edges = springing\n  set Settling edges = springing\n"
      "  set Settlement = 0.01*x/9.62758; 0; 0\n"
      "  set Write picture = false\nend\n"
      "subsection Interface model\n  set Model = mohr coulomb\n"
      "  subsection Mohr coulomb\n    set Cohesion = 31814.2\n"
      "    set Friction coefficient = 0.628634\n"
      "    set Tensile strength = 0\n    set Compressive strength = 0\n"
      "  end\nend\n";
    const masonry::Json clp = run("dome-clp", dome);
    const masonry::Json glpk =
      run("dome-glpk",
          dome + "subsection LP solver\n  set Solver = glpk\nend\n");
    const std::string message = text(glpk, "lp_message");
    check(message.find("failed the check") != std::string::npos &&
            message.find("solved again") != std::string::npos,
          "GLPK's first optimum fails the check and is solved again");
    check(text(glpk, "lp_check") == "passed" &&
            glpk.at("lp_max_violation").get<double>() < 1e-6 &&
            relative(glpk.at("lp_objective").get<double>(),
                     clp.at("lp_objective").get<double>()) < 1e-7,
          "the re-solved optimum passes, with Clp's optimum (1e-7)");
  }

  // an unchecked optimum from a plugin back-end is checked and warned of
  {
    const masonry::Json s =
      run("perturbed",
          arch_prm(3, 0.5, 8, "0; 0; -0.01", "unilateral", "perturbed clp"));
    std::ifstream     in("results/perturbed/log.txt");
    std::stringstream log;
    log << in.rdbuf();
    check(text(s, "lp_check") == "failed" &&
            s.at("lp_max_violation").get<double>() >= 1e-4 &&
            log.str().find(
              "Warning: the LP solver's optimum fails the check") !=
              std::string::npos,
          "a plugin's unchecked optimum off by 1e-3: warned, lp_check failed");
  }
}
