/**
 * @file
 * The `Optimiser` plugin of pagmo's particle swarm optimisation (pso). Compiled
 * twice (see pagmo_runner.h): the plugin into libmasonry, the factory into
 * libmasonry_pagmo.so.
 */
#include <masonry/adaptation/pagmo_runner.h>

#ifdef MASONRY_PAGMO_FACTORIES
// the factory, in libmasonry_pagmo.so (pagmo; no deal.II header)
#  include <pagmo/algorithm.hpp>
#  include <pagmo/algorithms/pso.hpp>

namespace
{
  pagmo::algorithm
  create(const masonry::adaptation::PagmoSettings &s)
  {
    return pagmo::algorithm{pagmo::pso(
      1u, s.parameters[0], 2.05, 2.05, 0.5, 5u, 2u, 4u, true, s.seed)};
  }
} // namespace

MASONRY_REGISTER_PAGMO_FACTORY("particle swarm", &create)

#else
// the plugin (name, description, entries), in libmasonry: no pagmo header
MASONRY_REGISTER_PAGMO_ALGORITHM(
  "particle swarm",
  "pagmo's particle swarm optimisation (pso, constriction variant).",
  {{"Inertia", "0.7298", 0, 1, "Inertia weight ω (dimensionless)."}},
  nullptr)

#endif
