/**
 * The closed-form IMPL-EX tangent of the `damage plasticity' brick law
 * against central differences of its own stress: with the damages and the
 * plastic strain extrapolated and frozen, the stress (1 - d_t) P(s) +
 * (1 - d_c) (s - P(s)) depends on the strain only through the spectral
 * positive part P, whose derivative the law writes in closed form. The test
 * differentiates the stress numerically (h = 1e-6 of the strain, error
 * O(h^2)) at 200 random strains (tension, compression and mixed principal
 * values, repeated principal values, the blended band near zero) and
 * random damages and plastic strains, and compares the tangents to 1e-5 of
 * |C0|. Also: at zero damage the tangent is C0 exactly (to round-off).
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <iostream>
#include <random>

#include "vault_tests.h"

using namespace dealii;
using masonry::brickwork::BrickMaterial;
using masonry::brickwork::BrickPoint;

namespace
{
  /** A state of the material's own layout with the given damages and
   * plastic strain (the other variables zero). */
  std::vector<double>
  state(const BrickMaterial         &material,
        const double                 damage_t,
        const double                 damage_c,
        const SymmetricTensor<2, 3> &plastic)
  {
    std::vector<double> v;
    for (const auto &var : material.state_variables())
      if (var.name == "damage_tension")
        v.push_back(damage_t);
      else if (var.name == "damage_compression")
        v.push_back(damage_c);
      else if (var.name == "plastic_strain")
        for (unsigned int k = 0; k < 6; ++k)
          v.push_back(plastic.access_raw_entry(k));
      else
        v.insert(v.end(), var.n_components, 0.);
    return v;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ParameterHandler                 prm;
  masonry::plugins::Registry<BrickMaterial>::declare_parameters(prm);
  prm.parse_input_from_string("subsection Brick material\n"
                              "set Model = damage plasticity\n"
                              "end\n");
  const auto material = masonry::plugins::Registry<BrickMaterial>::create(prm);
  const SymmetricTensor<4, 3> C0 = material->elastic_stiffness();

  std::mt19937                           random(7);
  std::uniform_real_distribution<double> u(-1, 1), d(0, 0.9);
  const double                           e0    = 2e-3; // strain scale
  double                                 worst = 0, worst_intact = 0;
  BrickPoint                             point;
  for (unsigned int n = 0; n < 200; ++n)
    {
      SymmetricTensor<2, 3> strain;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          strain[i][j] = e0 * u(random);
      if (n % 10 == 1) // a repeated principal value (pure pressure + shear)
        strain = -e0 * unit_symmetric_tensor<3>() +
                 SymmetricTensor<2, 3>({0., 0., 0., e0 * u(random), 0., 0.});
      if (n % 10 == 2) // lateral principal values in the blended band
        strain = SymmetricTensor<2, 3>(
          {1e-8 * u(random), 2e-8 * u(random), -e0, 0., 0., 0.});
      double                older_t = 0, older_c = 0, old_t = 0, old_c = 0;
      SymmetricTensor<2, 3> older_p, old_p;
      const bool            intact = n % 10 == 3;
      if (!intact)
        {
          older_t = d(random);
          older_c = d(random);
          old_t   = older_t + 0.1 * d(random);
          old_c   = older_c + 0.1 * d(random);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = i; j < 3; ++j)
              {
                older_p[i][j] = 0.2 * e0 * u(random);
                old_p[i][j]   = older_p[i][j] + 0.05 * e0 * u(random);
              }
        }
      const std::vector<double> old = state(*material, old_t, old_c, old_p),
                                older =
                                  state(*material, older_t, older_c, older_p);
      const double          ratio = intact ? 0. : 1.5 * d(random);
      SymmetricTensor<2, 3> stress, sp, sm;
      SymmetricTensor<4, 3> C, scratch;
      material->evaluate_extrapolated(
        strain, old, older, ratio, point, stress, C);
      SymmetricTensor<4, 3> numerical;
      const double          h = 1e-6 * e0;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          {
            SymmetricTensor<2, 3> p = strain, m = strain;
            p[i][j] += h;
            m[i][j] -= h;
            material->evaluate_extrapolated(
              p, old, older, ratio, point, sp, scratch);
            material->evaluate_extrapolated(
              m, old, older, ratio, point, sm, scratch);
            const SymmetricTensor<2, 3> ds =
              (sp - sm) / (2 * h * (i == j ? 1 : 2));
            for (unsigned int k = 0; k < 3; ++k)
              for (unsigned int l = k; l < 3; ++l)
                numerical[k][l][i][j] = ds[k][l];
          }
      const double error = (C - numerical).norm() / C0.norm();
      worst              = std::max(worst, error);
      if (intact)
        worst_intact = std::max(worst_intact, (C - C0).norm() / C0.norm());
    }
  vault_tests::check(worst < 1e-5,
                     "closed-form IMPL-EX tangent = central differences of "
                     "the stress (1e-5 of |C0|, 200 random states)");
  vault_tests::check(worst_intact < 1e-12,
                     "intact, no plastic strain: the tangent is C0");
}
