/**
 * @file
 * pagmo's self-adaptive differential evolution (sade) as a mesh-adaptation
 * optimiser of masonry, in a library of its own: one file that defines how
 * to build the algorithm from the run's settings (its factory) and
 * registers it with its name, description and entries. It includes pagmo
 * and masonry/adaptation/pagmo_runner.h, but no deal.II header (pagmo's
 * serialisation of std::tuple clashes with deal.II's).
 */
#include <masonry/adaptation/pagmo_runner.h>

#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/sade.hpp>

namespace
{
  /**
   * One generation of sade per evolve() call (masonry migrates the best
   * block layout between islands after each generation). The entries'
   * values come in the order in which they are registered below.
   */
  pagmo::algorithm
  create(const masonry::adaptation::PagmoSettings &settings)
  {
    const unsigned int variant    = 2; // rand/1/exp
    const unsigned int adaptation = 1; // jDE (Brest et al. 2006)
    return pagmo::algorithm{pagmo::sade(1u,
                                        variant,
                                        adaptation,
                                        settings.parameters[0], // ftol
                                        settings.parameters[0], // xtol
                                        false,
                                        settings.seed)};
  }
} // namespace

MASONRY_REGISTER_PAGMO_ALGORITHM(
  "self-adaptive differential evolution",
  "pagmo's self-adaptive differential evolution (sade, variant rand/1/exp), "
  "from the library built by contrib/examples/optimiser.",
  {{"Tolerance",
    "1e-6",
    0,
    1,
    "A generation in which the population's fitness values and genes "
    "differ by less than this (dimensionless) ends the evolution of an "
    "island."}},
  &create)
