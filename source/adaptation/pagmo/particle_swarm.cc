/**
 * @file
 * The `Optimiser` plugin of pagmo's particle swarm optimisation (pso). pagmo
 * only: no deal.II header may be included here (see pagmo_runner.h).
 */
#include <masonry/adaptation/pagmo_runner.h>

#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/pso.hpp>

namespace
{
  pagmo::algorithm
  create(const masonry::adaptation::PagmoSettings &s)
  {
    return pagmo::algorithm{pagmo::pso(
      1u, s.parameters[0], 2.05, 2.05, 0.5, 5u, 2u, 4u, true, s.seed)};
  }
} // namespace

MASONRY_REGISTER_PAGMO_ALGORITHM(
  "particle swarm",
  "pagmo's particle swarm optimisation (pso, constriction variant).",
  {{"Inertia", "0.7298", 0, 1, "Inertia weight ω (dimensionless)."}},
  &create)
