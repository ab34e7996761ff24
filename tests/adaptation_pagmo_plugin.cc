// A new pagmo algorithm is one file: this test file registers pagmo's
// self-adaptive differential evolution (sade) with one entry of its own,
// exactly as source/adaptation/pagmo/*.cc do, and runs it through the
// island loop of run_pagmo on a concave fitness whose maximum is known:
// f(x) = -sum (x_i - 0.3)^2 on [0, 1]^3, maximum 0 at x = (0.3, 0.3, 0.3).
// No edit outside this file is needed, and (like the plugin files) it
// includes pagmo but no deal.II header.

#include <masonry/adaptation/pagmo_runner.h>

#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/sade.hpp>

#include <cmath>
#include <iostream>

namespace
{
  unsigned int n_created = 0;

  pagmo::algorithm
  create(const masonry::adaptation::PagmoSettings &s)
  {
    ++n_created;
    // variant 2 (rand/1/exp), jDE self-adaptation; parameters[0] = ftol
    return pagmo::algorithm{
      pagmo::sade(1u, 2u, 1u, s.parameters[0], 1e-6, false, s.seed)};
  }
} // namespace

MASONRY_REGISTER_PAGMO_ALGORITHM(
  "self-adaptive differential evolution",
  "pagmo's sade, registered by a test file.",
  {{"Tolerance", "1e-6", 0, 1, "Stopping tolerance on f (dimensionless)."}},
  &create)

int
main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  masonry::adaptation::PagmoSettings settings;
  settings.create            = &create;
  settings.population_size   = 12;
  settings.generations       = 60;
  settings.seed              = 3;
  settings.stall_generations = 0;
  settings.parameters        = {1e-6};
  const masonry::adaptation::Fitness fitness =
    [](const std::vector<double> &x) {
      double f = 0;
      for (const double v : x)
        f -= (v - 0.3) * (v - 0.3);
      return f;
    };
  const auto result =
    masonry::adaptation::run_pagmo(MPI_COMM_WORLD,
                                   settings,
                                   {fitness, fitness},
                                   {0.9, 0.9, 0.9},
                                   [](const masonry::adaptation::Generation &) {
                                   });
  double distance = 0;
  for (const double v : result.best_genes)
    distance = std::max(distance, std::abs(v - 0.3));
  std::cout << (n_created == 2 ? "OK" : "FAILED")
            << " the registered factory built one algorithm per island (2)"
            << std::endl;
  std::cout << (result.best_fitness > -1e-4 && distance < 1e-2 ? "OK" :
                                                                 "FAILED")
            << " best fitness within 1e-4 of the maximum 0, genes within "
               "1e-2 of 0.3 (start 0.9)"
            << std::endl;
  MPI_Finalize();
}
