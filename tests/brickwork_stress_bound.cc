/**
 * The physical bound on a wallette's platen stress that stops a run whose
 * solution has run away (source/brickwork/solution/bounds.h):
 *
 * (a) an elastic prism under constrained uniaxial strain e carries exactly
 *     M e, M = E (1 - nu) / ((1 + nu) (1 - 2 nu)) (the stiffest a wallette
 *     of that material can be): never beyond the bound, at any strain;
 * (b) the runaway of the double cyclic example (2026-11-25, unit f_c =
 *     16 MPa, E = 8 GPa, nu = 0.2): 1.6e12 MPa at strain 0.0003 is beyond
 *     the bound, while its sound first peak, 9.0 MPa at strain 0.003, is
 *     within it;
 * (c) the reason names the stress and the bound.
 */
#include <cmath>
#include <iostream>

#include "../source/brickwork/solution/bounds.h"
#include "vault_tests.h"

using namespace masonry::brickwork::model;
using vault_tests::check;

int
main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  const double E = 8e9, nu = 0.2, f_c = 16e6;
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));

  bool elastic = true;
  for (const double e : {0., 1e-6, -1e-4, 1e-3, 0.01, -0.05, 0.5})
    elastic = elastic && runaway_problem(M * e, e, 0, M).empty() &&
              runaway_problem(M * e + f_c, e, f_c, M).empty();
  check(elastic, "M e (and M e + f_c) is within the bound at every strain (a)");
  check(
    !runaway_problem(1.1 * stress_bound_factor * M * 0.01, 0.01, 0, M).empty(),
    "1.1 x the factor x M e is beyond it (a)");

  check(!runaway_problem(1.6e18, 3e-4, f_c, M).empty(),
        "1.6e12 MPa at strain 0.0003 is a runaway (b)");
  check(!runaway_problem(-1.6e18, 3e-4, f_c, M).empty(),
        "so is -1.6e12 MPa (b)");
  check(runaway_problem(9.0e6, 3e-3, f_c, M).empty(),
        "the sound peak 9.0 MPa at strain 0.003 is not (b)");

  const std::string why = runaway_problem(1.6e18, 3e-4, f_c, M);
  check(why.find("1.6e+12 MPa") != std::string::npos &&
          why.find("ran away") != std::string::npos,
        "the reason names the stress (c)");
  MPI_Finalize();
}
