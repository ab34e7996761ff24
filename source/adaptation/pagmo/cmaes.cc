/**
 * @file
 * The `Optimiser` plugin of pagmo's covariance matrix adaptation evolution
 * strategy (cmaes). Compiled twice (see pagmo_runner.h): the plugin
 * into libmasonry, the factory into libmasonry_pagmo.so.
 */
#include <masonry/adaptation/pagmo_runner.h>

#ifdef MASONRY_PAGMO_FACTORIES
// the factory, in libmasonry_pagmo.so (pagmo; no deal.II header)
#  include <pagmo/algorithm.hpp>
#  include <pagmo/algorithms/cmaes.hpp>

namespace
{
  pagmo::algorithm
  create(const masonry::adaptation::PagmoSettings &s)
  {
    return pagmo::algorithm{pagmo::cmaes(
      1u, -1, -1, -1, -1, s.parameters[0], 0., 0., true, true, s.seed)};
  }
} // namespace

MASONRY_REGISTER_PAGMO_FACTORY("cmaes", &create)

#else
// the plugin (name, description, entries), in libmasonry: no pagmo header
MASONRY_REGISTER_PAGMO_ALGORITHM(
  "cmaes",
  "pagmo's covariance matrix adaptation evolution strategy (cmaes, bounds "
  "enforced).",
  {{"Initial step",
    "0.2",
    0,
    1,
    "Initial step size σ₀ in gene space (dimensionless, genes lie in [0, "
    "1])."}},
  nullptr)

#endif
