/**
 * The two integrators on their own (issue 15), on the bilinear joint law in
 * pure opening (delta_0 = f_t / k_n, final opening delta_f = 2 G_I / f_t).
 * Implicit: the traction at an opening delta between them is (1 - d) k_n
 * delta with the closed-form damage d = delta_f (delta - delta_0) /
 * (delta (delta_f - delta_0)), and the point's new state holds d while the
 * converged one is unchanged. IMPL-EX: the damage is extrapolated from the
 * two converged states, d_old + r (d_old - d_older), capped at 1, and the
 * state is not touched within the step. Accepting a step keeps the older
 * state only for IMPL-EX; a brick point is elastic for IMPL-EX only when
 * both converged states are.
 */
#include <masonry/core/plugins.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <iostream>

#include "../source/brickwork/assembly/integrator.h"
#include "vault_tests.h"

using namespace dealii;
using namespace masonry::brickwork;
using namespace masonry::brickwork::model;

namespace
{
  /** The offset of state variable @p name of @p variables. */
  unsigned int
  offset(const std::vector<StateVariable> &variables, const std::string &name)
  {
    unsigned int o = 0;
    for (const auto &v : variables)
      {
        if (v.name == name)
          return o;
        o += v.n_components;
      }
    AssertThrow(false, ExcMessage("no state variable " + name));
    return 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ParameterHandler                 prm;
  masonry::plugins::Registry<InterfaceLaw>::declare_parameters(prm);
  masonry::plugins::Registry<BrickMaterial>::declare_parameters(prm);
  masonry::plugins::Registry<Integrator>::declare_parameters(prm);
  prm.parse_input_from_string(
    "subsection Interface law\nset Law = bilinear\n"
    "set Normal stiffness = 2.5e11\nset Shear stiffness = 1e11\n"
    "subsection Bilinear\nset Tensile strength = 0.2e6\n"
    "set Mode I fracture energy = 15\nend\nend\n"
    "subsection Brick material\nset Model = damage plasticity\nend\n");
  const auto law      = masonry::plugins::Registry<InterfaceLaw>::create(prm);
  const auto material = masonry::plugins::Registry<BrickMaterial>::create(prm);
  const double kn = 2.5e11, ft = 0.2e6, GI = 15;
  const double d0 = ft / kn, df = 2 * GI / ft, delta = 0.4 * d0 + 0.6 * df;
  const double d_exact = df * (delta - d0) / (delta * (df - d0));
  const Local3 jump{{delta, 0, 0}};
  const auto   variables = law->state_variables();
  const unsigned int  n  = n_state_values(variables);
  const unsigned int  id = offset(variables, "damage");
  InterfacePoint      point;
  Local3              t;
  Local33             D;
  std::vector<double> damage(1);

  const auto implicit =
    masonry::plugins::Registry<Integrator>::create(prm, "implicit");
  PointStates states;
  states.initialize(1, std::vector<double>(n, 0.), {0});
  implicit->joint_response(*law, jump, states, 0, point, t, D);
  law->damages(states.updated(0), damage);
  vault_tests::check(std::abs(t[0] - (1 - d_exact) * kn * delta) < 1e-10 * ft &&
                       std::abs(damage[0] - d_exact) < 1e-12 &&
                       states.old(0)[id] == 0,
                     "implicit: traction (1 - d) k_n delta with the "
                     "closed-form damage, the new state holds d");
  vault_tests::check(!implicit->keeps_older() &&
                       implicit->step_state(states, 0)[id] == damage[0],
                     "implicit: the step's tangent comes from the new state, "
                     "no older state kept");

  const auto implex =
    masonry::plugins::Registry<Integrator>::create(prm, "implex");
  std::vector<double> old(n, 0.), older(n, 0.);
  old[id]   = 0.4;
  older[id] = 0.2;
  PointStates s2;
  s2.initialize(1, older, {0});
  s2.updated(0)[id] = 0.4;
  s2.accept(0, true); // older = 0.2, old = 0.4
  implex->set_ratio(0.5);
  implex->joint_response(*law, jump, s2, 0, point, t, D);
  const bool frozen =
    s2.updated(0)[id] == 0.4 && s2.old(0)[id] == 0.4 && s2.older(0)[id] == 0.2;
  vault_tests::check(std::abs(t[0] - 0.5 * kn * delta) < 1e-10 * ft &&
                       std::abs(D[0][0] - 0.5 * kn) < 1e-6 && frozen,
                     "IMPL-EX: damage 0.4 + 0.5 (0.4 - 0.2) = 0.5 frozen in "
                     "the step, traction and tangent 0.5 k_n, states "
                     "untouched");
  implex->set_ratio(10);
  vault_tests::check(implex->extrapolated(0.4, 0.2) == 1 &&
                       implex->keeps_older() &&
                       implex->step_state(s2, 0)[id] == 0.4,
                     "IMPL-EX: the extrapolated damage is capped at 1; "
                     "accepting keeps the older state; the step's tangent "
                     "comes from the converged state");

  // bricks: a small strain from an intact state is elastic; for IMPL-EX
  // the older state must be intact too
  const unsigned int nb = n_state_values(material->state_variables());
  const unsigned int ic =
    offset(material->state_variables(), "damage_compression");
  std::vector<double> damaged(nb, 0.);
  damaged[ic] = 0.1;
  PointStates bricks;
  bricks.initialize(1, damaged, {0});
  bricks.updated(0)[ic] = 0;
  bricks.accept(0, true); // older damaged, old intact
  SymmetricTensor<2, 3> strain;
  strain[2][2] = -1e-5;
  BrickPoint bp;
  vault_tests::check(
    implicit->brick_is_elastic(*material, strain, bricks, 0, bp) &&
      !implex->brick_is_elastic(*material, strain, bricks, 0, bp),
    "bricks: elastic from an intact state (implicit); not for "
    "IMPL-EX while the older state is damaged");
}
