/**
 * @file
 * The `Optimiser` plugin of pagmo's differential evolution (de). Compiled twice
 * (see pagmo_runner.h): the plugin into libmasonry, the factory into
 * libmasonry_pagmo.so.
 */
#include <masonry/adaptation/pagmo_runner.h>

#ifdef MASONRY_PAGMO_FACTORIES
// the factory, in libmasonry_pagmo.so (pagmo; no deal.II header)
#  include <pagmo/algorithm.hpp>
#  include <pagmo/algorithms/de.hpp>

namespace
{
  pagmo::algorithm
  create(const masonry::adaptation::PagmoSettings &s)
  {
    return pagmo::algorithm{
      pagmo::de(1u, s.parameters[0], s.parameters[1], 2u, 0., 0., s.seed)};
  }
} // namespace

MASONRY_REGISTER_PAGMO_FACTORY("differential evolution", &create)

#else
// the plugin (name, description, entries), in libmasonry: no pagmo header
MASONRY_REGISTER_PAGMO_ALGORITHM(
  "differential evolution",
  "pagmo's differential evolution (de, variant rand/1/exp).",
  {{"Weight", "0.8", 0, 2, "Differential weight F (dimensionless)."},
   {"Crossover probability",
    "0.9",
    0,
    1,
    "Crossover probability CR (dimensionless)."}},
  nullptr)

#endif
