/**
 * @file
 * The `Optimiser` plugin of pagmo's simple genetic algorithm (sga). Compiled
 * twice (see pagmo_runner.h): the plugin into libmasonry, the factory into
 * libmasonry_pagmo.so.
 */
#include <masonry/adaptation/pagmo_runner.h>

#ifdef MASONRY_PAGMO_FACTORIES
// the factory, in libmasonry_pagmo.so (pagmo; no deal.II header)
#  include <pagmo/algorithm.hpp>
#  include <pagmo/algorithms/sga.hpp>

namespace
{
  pagmo::algorithm
  create(const masonry::adaptation::PagmoSettings &s)
  {
    return pagmo::algorithm{pagmo::sga(1u,
                                       s.parameters[0],
                                       1.,
                                       s.parameters[1],
                                       1.,
                                       2u,
                                       "exponential",
                                       "polynomial",
                                       "tournament",
                                       s.seed)};
  }
} // namespace

MASONRY_REGISTER_PAGMO_FACTORY("genetic", &create)

#else
// the plugin (name, description, entries), in libmasonry: no pagmo header
MASONRY_REGISTER_PAGMO_ALGORITHM(
  "genetic",
  "pagmo's simple genetic algorithm (sga: exponential crossover, "
  "polynomial mutation, tournament selection), the seed paper's method.",
  {{"Crossover probability",
    "0.9",
    0,
    1,
    "Probability of crossover (dimensionless)."},
   {"Mutation probability",
    "0.1",
    0,
    1,
    "Probability that a gene mutates (dimensionless; polynomial mutation)."}},
  nullptr)

#endif
