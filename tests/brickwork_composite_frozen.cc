/**
 * The IMPL-EX response of the `composite' interface law
 * (CompositeInterface::evaluate_extrapolated) at a crack in mode I, with the
 * plastic normal jump extrapolated to u_p* = u_p,old + r (u_p,old -
 * u_p,older) and the crack opening to w* likewise (r = 1):
 *
 * (a) a crack that opened in the last step (w_old > w_older) is frozen
 *     linear on both sides of u_p*: at the old jump u_n,old < u_p* the
 *     traction is k_n (u_n - u_p*) < 0 with tangent k_n, and the response
 *     is the same straight line above u_p*;
 * (b) a crack that did not open in the last step (older = old: a resting
 *     crack, or the floor correction's frozen states) keeps the closure
 *     gap: no traction and no normal stiffness in [u_p - w, u_p], contact
 *     k_n (u_n - (u_p - w)) below it.
 *
 * (a) fails if the closure gap is applied to opening cracks (before
 * 2026-11-28: t = 0 and tangent 0 at the old jump).
 */
#include <masonry/brickwork/interface_law.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "vault_tests.h"

using namespace dealii;
using namespace masonry::brickwork;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ParameterHandler                 prm;
  masonry::plugins::Registry<InterfaceLaw>::declare_parameters(prm);
  prm.parse_input_from_string(
    "subsection Interface law\nset Law = composite\n"
    "set Normal stiffness = 1e12\nset Shear stiffness = 4e11\n"
    "subsection Composite\nset Tensile strength = 0.25e6\n"
    "set Mode I fracture energy = 18\nend\nend\n");
  const auto   law      = masonry::plugins::Registry<InterfaceLaw>::create(prm);
  const double kn       = 1e12;
  const unsigned int  n = 6; // plastic jump (3), crack opening, xi, kappa_3
  std::vector<double> zero(n, 0.), older(n), old(n), scratch(n);
  InterfacePoint      point;
  Local3              t;
  Local33             D;
  // two converged steps of a softening crack in pure opening
  const double u_older = 2e-6, u_old = 3e-6;
  law->evaluate({{u_older, 0, 0}}, zero, point, older, t, D);
  law->evaluate({{u_old, 0, 0}}, older, point, old, t, D);
  const double up_star = 2 * old[0] - older[0];
  const double w_star  = 2 * old[3] - older[3];
  vault_tests::check(old[3] > older[3] && older[3] > 0 && u_old < up_star,
                     "the crack opened in the last step and its "
                     "extrapolated plastic jump lies beyond the old jump");

  // (a) opening: linear on both sides of u_p*
  bool linear = true;
  for (const double u : {u_old, up_star - 0.5 * w_star, up_star + 1e-7})
    {
      law->evaluate_extrapolated({{u, 0, 0}}, old, older, 1., point, t, D);
      linear = linear &&
               std::abs(t[0] - kn * (u - up_star)) < 1e-9 * kn * 1e-7 &&
               D[0][0] == kn;
    }
  vault_tests::check(linear,
                     "opening crack: t_n = k_n (u_n - u_p*), tangent k_n, "
                     "at the old jump, inside [u_p* - w*, u_p*] and above "
                     "u_p* (1e-9)");

  // (b) resting crack: the closure gap of the converged state
  const double up = old[0], w = old[3];
  law->evaluate_extrapolated({{up - 0.5 * w, 0, 0}}, old, old, 1., point, t, D);
  const bool gap = t[0] == 0 && D[0][0] == 0;
  law->evaluate_extrapolated(
    {{up - w - 1e-7, 0, 0}}, old, old, 1., point, t, D);
  const bool contact =
    std::abs(t[0] + kn * 1e-7) < 1e-9 * kn * 1e-7 && D[0][0] == kn;
  vault_tests::check(gap && contact,
                     "resting crack: no traction or normal stiffness in "
                     "the closure gap, contact k_n below it");
}
