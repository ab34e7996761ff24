/**
 * The nonlocal average of the units' tensile measure (`Nonlocal length',
 * source/brickwork/assembly/nonlocal.h) against closed forms:
 *
 * (a) the average alone, on a grid of 11 x 11 x 11 points 5 mm apart with
 *     equal volumes, R = 20 mm: a uniform field is unchanged at every point
 *     (also with a dead neighbour that holds another value); a linear field
 *     f = 1 + 2 x - 3 y + 5 z (x in m) averages to its value at the centre,
 *     whose sphere lies inside the grid (the bell weights are symmetric);
 *     the points of one group never see another group's values; two points
 *     at r = 12 mm with volumes V0, V1 and values 0, 1: the average at the
 *     first is w V1 / (V0 + w V1), w = (1 - r^2 / R^2)^2.
 * (b) the law `damage plasticity': nonlocal_measures() of a uniaxial
 *     strain e_xx = e are tau_t = (lambda + 2 mu) e (the largest principal
 *     effective stress) and, for e_xx = -e, tau_c = (2 mu - alpha (3 lambda
 *     + 2 mu)) e / (1 - alpha) (Lubliner's measure, alpha = (r - 1) / (2 r
 *     - 1), r = `Biaxial to uniaxial strength ratio'); with
 *     BrickPoint::tensile_factor rho the tensile damage starts where rho
 *     (lambda + 2 mu) e = f_t, i.e. at the local stress f_t / rho, and with
 *     compressive_factor rho the compressive envelope strain kappa_c leaves
 *     0 where rho tau_c = `Elastic limit ratio' f_c (rho = 0.5, 1, 2; both
 *     `Tensile plastic flow' values; 0.1 % below: nothing, 0.1 % above:
 *     onset).
 * (c) converged_stress() (what the deletion and solution.pvd read) uses
 *     the step's factors, see converged_checks().
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <iostream>

#include "../source/brickwork/assembly/nonlocal.h"
#include "../source/brickwork/solution/deletion.h"
#include "vault_tests.h"

using namespace dealii;
using namespace masonry::brickwork;
using namespace masonry::brickwork::model;
using vault_tests::check;

namespace
{
  std::unique_ptr<BrickMaterial>
  unit(const std::string &entries)
  {
    ParameterHandler prm;
    masonry::plugins::Registry<BrickMaterial>::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Brick material\nset Model = damage plasticity\n"
      "subsection Damage plasticity\nset Young's modulus = 10e9\n"
      "set Poisson's ratio = 0.15\nset Tensile strength = 2e6\n" +
      entries + "end\nend\n");
    return masonry::plugins::Registry<BrickMaterial>::create(prm);
  }

  void
  average_checks()
  {
    const double              h = 0.005, R = 0.02;
    std::vector<Point<3>>     x;
    std::vector<unsigned int> index;
    for (unsigned int i = 0; i < 11; ++i)
      for (unsigned int j = 0; j < 11; ++j)
        for (unsigned int k = 0; k < 11; ++k)
          x.emplace_back(i * h, j * h, k * h);
    const unsigned int        n = x.size(), centre = (5 * 11 + 5) * 11 + 5;
    const std::vector<double> volume(n, h * h * h);
    std::vector<unsigned int> group(n, 0);
    std::vector<char>         mine(n, 1), alive(n, 1);
    const NonlocalAverage     average(x, volume, group, mine, R);

    std::vector<double> f(n, 3.);
    double              error = 0;
    for (unsigned int p = 0; p < n; ++p)
      error = std::max(error, std::abs(average.average(p, f, alive) - 3));
    // a dead neighbour of the centre with another value takes no part
    alive[centre + 1] = 0;
    f[centre + 1]     = 1e6;
    error = std::max(error, std::abs(average.average(centre, f, alive) - 3));
    check(error < 1e-12, "a uniform field is unchanged (1e-12)");
    check(average.n_neighbours(centre) > 100,
          "the centre averages over more than 100 points");

    alive.assign(n, 1);
    for (unsigned int p = 0; p < n; ++p)
      f[p] = 1 + 2 * x[p][0] - 3 * x[p][1] + 5 * x[p][2];
    check(std::abs(average.average(centre, f, alive) - f[centre]) < 1e-12,
          "a linear field's average at an interior point is its value "
          "(1e-12)");

    // two groups: x < 0.0275 and the rest
    for (unsigned int p = 0; p < n; ++p)
      {
        group[p] = x[p][0] < 0.0275 ? 0 : 1;
        f[p]     = group[p] == 0 ? 0. : 100.;
      }
    const NonlocalAverage split(x, volume, group, mine, R);
    double                largest = 0;
    for (unsigned int p = 0; p < n; ++p)
      if (group[p] == 0)
        largest = std::max(largest, std::abs(split.average(p, f, alive)));
    check(largest == 0, "a group does not see another group's values");

    const double          r = 0.012, V0 = 2e-6, V1 = 5e-6;
    const NonlocalAverage pair(
      {Point<3>(0, 0, 0), Point<3>(0, r, 0)}, {V0, V1}, {7, 7}, {1, 1}, R);
    const double w = std::pow(1 - r * r / (R * R), 2);
    check(std::abs(pair.average(0, {0., 1.}, {1, 1}) - w * V1 / (V0 + w * V1)) <
            1e-14,
          "two points: the average is w V1 / (V0 + w V1), w = (1 - r^2 / "
          "R^2)^2 (1e-14)");
  }

  void
  law_checks()
  {
    const double E = 10e9, nu = 0.15, f_t = 2e6;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
                 mu     = E / (2 * (1 + nu));
    for (const std::string flow : {"elastic", "crack"})
      {
        const auto law = unit("set Nonlocal length = 0.03\n"
                              "set Tensile plastic flow = " +
                              flow + "\n");
        const masonry::brickwork::NonlocalMeasures *measures =
          masonry::brickwork::nonlocal_of(*law);
        check(measures && measures->nonlocal_length() == 0.03,
              "`Nonlocal length' is the law's radius");
        unsigned int n = 0;
        for (const auto &v : law->state_variables())
          n += v.n_components;
        std::vector<double> old(n, 0.), updated(n, 0.), d(2);
        law->initial_state(old);
        SymmetricTensor<2, 3> strain;
        strain[0][0] = 1e-4;
        BrickPoint point;
        point.characteristic_length = 0.05;
        const double alpha          = 0.16 / 1.32;
        const double tau_c =
          (2 * mu - alpha * (3 * lambda + 2 * mu)) * 1e-4 / (1 - alpha);
        check(std::abs(measures->nonlocal_measures(strain, old, point)[0] -
                       (lambda + 2 * mu) * 1e-4) < 1e-6 &&
                std::abs(measures->nonlocal_measures(-strain, old, point)[1] -
                         tau_c) < 1e-6,
              "the measures of e_xx = +-e are (lambda + 2 mu) e and tau_c (" +
                flow + ")");
        bool onset = true;
        for (const double rho : {0.5, 1., 2.})
          for (const double factor : {0.999, 1.001})
            {
              point.tensile_factor = rho;
              strain[0][0]         = factor * f_t / (rho * (lambda + 2 * mu));
              SymmetricTensor<2, 3> stress;
              law->update_state(strain, old, point, updated, stress);
              law->damages(updated, d);
              onset = onset && ((factor < 1) == (d[0] == 0));
            }
        check(onset,
              "the tensile damage starts at the local stress f_t / rho "
              "(rho = 0.5, 1, 2; +-0.1 %; " +
                flow + ")");
        // compression: the envelope strain kappa_c (state entry 9) leaves 0
        // at rho tau_c = 0.4 f_c (the defaults: f_c = 20 MPa)
        point.tensile_factor = 1;
        for (const double rho : {0.5, 1., 2.})
          for (const double factor : {0.999, 1.001})
            {
              point.compressive_factor = rho;
              strain[0][0] = -factor * 0.4 * 20e6 / (rho * tau_c / 1e-4);
              SymmetricTensor<2, 3> stress;
              law->update_state(strain, old, point, updated, stress);
              onset = onset && ((factor < 1) == (updated[9] == 0));
            }
        check(onset,
              "the compressive envelope starts at rho tau_c = 0.4 f_c "
              "(rho = 0.5, 1, 2; +-0.1 %; " +
                flow + ")");
      }
  }

  /**
   * (c) What the deletion and the output read, converged_stress(): the
   * law at the converged state with the step's factors
   * (Specimen::nonlocal_factors). One cell of 8 points, rho_t = rho_c =
   * 0.5 at every point. At a strain whose local measure is 1.5 times the
   * onset (tension: (lambda + 2 mu) e = 1.5 f_t; compression: tau_c = 1.5
   * x 0.4 f_c) the step's update leaves the point elastic (averaged
   * measure 0.75 times the onset), so the stress is C0 : e exactly (with
   * the local measures the point would crack or crush there, as the
   * deletion and the output did before); at 3 f_t the update cracks the
   * point, and its converged state at the same strain gives back the
   * update's stress (no further loading; 1e-9 f_t).
   */
  void
  converged_checks()
  {
    const double E = 10e9, nu = 0.15, f_t = 2e6;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
                 mu     = E / (2 * (1 + nu));
    const double alpha  = 0.16 / 1.32;
    // tau_c of e_xx = -1
    const double tau_c_unit =
      (2 * mu - alpha * (3 * lambda + 2 * mu)) / (1 - alpha);
    for (const std::string flow : {"elastic", "crack"})
      {
        const auto   law = unit("set Nonlocal length = 0.03\n"
                                "set Tensile plastic flow = " +
                              flow + "\n");
        unsigned int n   = 0;
        for (const auto &v : law->state_variables())
          n += v.n_components;
        std::vector<double> initial(n);
        law->initial_state(initial);
        // the law as the units' of a law set, with its point states
        masonry::brickwork::LawSet laws;
        laws.add_region_law(*law, "Brick material/Model", "");
        LawStates states;
        states.bricks.resize(1);
        states.bricks[0].initialize(8, initial, {});
        Specimen specimen;
        specimen.cell_length      = {0.05};
        specimen.cell_factor      = {1.};
        specimen.cell_region      = {0};
        specimen.nonlocal_factors = {
          {std::vector<double>(8, 0.5), std::vector<double>(8, 0.5)}};
        double elastic_error = 0;
        for (const double e :
             {1.5 * f_t / (lambda + 2 * mu), -1.5 * 0.4 * 20e6 / tau_c_unit})
          for (unsigned int q = 0; q < 8; ++q)
            {
              SymmetricTensor<2, 3> strain;
              strain[0][0] = e;
              SymmetricTensor<2, 3> expected =
                lambda * e * unit_symmetric_tensor<3>();
              expected[0][0] += 2 * mu * e;
              elastic_error = std::max(
                elastic_error,
                (converged_stress(laws, strain, states, specimen, 0, q) -
                 expected)
                    .norm() /
                  f_t);
            }
        check(elastic_error < 1e-9,
              "local measure 1.5 x the onset, averaged 0.75 x: the "
              "converged stress is C0 : e (1e-9 f_t; " +
                flow + ")");
        // the step's update at 3 f_t with the factors cracks the point
        SymmetricTensor<2, 3> strain, stress;
        strain[0][0] = 3 * f_t / (lambda + 2 * mu);
        BrickPoint point;
        point.characteristic_length = 0.05;
        point.tensile_factor        = 0.5;
        point.compressive_factor    = 0.5;
        std::vector<double> updated(n), d(2);
        law->update_state(strain, initial, point, updated, stress);
        law->damages(updated, d);
        states.bricks[0].initialize(8, updated, {});
        const double error =
          (converged_stress(laws, strain, states, specimen, 0, 3) - stress)
            .norm() /
          f_t;
        check(d[0] > 0 && error < 1e-9,
              "a point cracked by the step (averaged 1.5 f_t) gives back "
              "the step's stress at its converged state (1e-9 f_t; " +
                flow + ")");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  average_checks();
  law_checks();
  converged_checks();
}
