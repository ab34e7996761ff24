/**
 * Semicircular arch (radial joints) under a vertical settlement of one
 * springing.
 *
 * - The work of self weight converges as blocks are added; the reference is
 *   a fine mesh of 256 blocks per half (512 blocks). The error table goes to
 *   convergence.csv in the test's directory; the test asserts that the error
 * decreases monotonically and is below 1 % from 16 blocks per half on.
 * - The mechanism has three hinges (rigid-block theory of arches under a
 *   support displacement: a three-hinge mechanism, Ochsendorf 2002).
 * - Clp and GLPK give the same optimum (relative 1e-8).
 * - An arch well below the minimum thickness (t/R = 0.06 < 0.1074) cannot
 *   stand: `mechanism`. Two blocks with bonded supports cannot follow a
 *   settlement of one springing without sliding at the crown:
 *   `incompatible`.
 */
#include <deal.II/base/mpi.h>

#include "vault_tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace vault_tests;
  const double R = 5, t = 1;
  const double reference = run("arch_ref", arch_prm(R, t, 256, "0; 0; -0.01"))
                             .at("external_work")
                             .get<double>();

  double        previous = 1e300;
  bool          monotone = true, converged = true, three_hinges = true;
  std::ofstream table("convergence.csv"); // the error table, not compared
  table << "blocks per half, work [J], relative error\n";
  for (const unsigned int n : {4u, 8u, 16u, 32u, 64u})
    {
      const masonry::Json s =
        run("arch_" + std::to_string(n), arch_prm(R, t, n, "0; 0; -0.01"));
      const double error =
        relative(s.at("external_work").get<double>(), reference);
      table << n << ", " << s.at("external_work").get<double>() << ", " << error
            << "\n";
      monotone     = monotone && error <= previous;
      converged    = converged && (n < 16 || error < 1e-2);
      three_hinges = three_hinges && s.at("n_hinges").get<double>() == 3;
      previous     = error;
      if (n == 16)
        {
          const masonry::Json g =
            run("arch_glpk",
                arch_prm(R, t, n, "0; 0; -0.01", "unilateral", "glpk"));
          check(relative(g.at("external_work").get<double>(),
                         s.at("external_work").get<double>()) < 1e-8,
                "Clp and GLPK agree to 1e-8 (16 blocks per half)");
        }
    }
  check(monotone, "the error decreases as blocks are added");
  check(converged, "error < 1 % from 16 blocks per half on");
  check(three_hinges, "three hinges on every mesh");

  const masonry::Json thin =
    run("arch_thin", arch_prm(R, 0.06 * R, 16, "0; 0; 0"));
  check(thin.at("status").get<std::string>() == "mechanism",
        "t/R = 0.06 without settlement: mechanism");
  const masonry::Json bonded =
    run("arch_bonded", arch_prm(R, t, 1, "0; 0; -0.01", "bonded"));
  check(bonded.at("status").get<std::string>() == "incompatible",
        "two blocks, bonded supports, one settles: incompatible");
}
