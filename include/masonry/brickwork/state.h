/**
 * @file
 * The state of an integration point as a law declares it: named variables
 * of a few components each, stored by the model in flat arrays of doubles.
 * The model never names a variable of a law; it stores, extrapolates,
 * checkpoints and writes what the law declares.
 */
#ifndef masonry_brickwork_state_h
#define masonry_brickwork_state_h

#include <deal.II/base/array_view.h>

#include <string>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    /** One state variable of a law: a name and its number of components. */
    struct StateVariable
    {
      /** Name in snake_case (VTU output, checkpoints). */
      std::string name;
      /** Number of doubles (1: a scalar, 6: a symmetric tensor). */
      unsigned int n_components = 1;
    };

    /** The state of one point, writable: the law's variables in order. */
    using StateView = dealii::ArrayView<double>;
    /** The state of one point, read only. */
    using ConstStateView = dealii::ArrayView<const double>;

    /** Number of doubles of the state @p variables. */
    unsigned int
    n_state_values(const std::vector<StateVariable> &variables);

    /**
     * One name per double of @p variables: the name itself for a scalar,
     * name_0, name_1, ... for a variable of several components.
     */
    std::vector<std::string>
    component_names(const std::vector<StateVariable> &variables);

    /**
     * A value a law computes from its inputs (a penalty from the moduli, a
     * strength from another strength, ...): printed in log.txt and written
     * to summary.json under `derived_values', so that a run shows every
     * number it used that was not given.
     */
    struct DerivedValue
    {
      /** Name in snake_case (the key in summary.json). */
      std::string name;
      /** The value in SI units. */
      double value = 0;
      /** Its unit ("Pa", "Pa/m", "m", "-", ...). */
      std::string unit;
      /** How it was obtained (formula and inputs), for log.txt. */
      std::string how;
    };
  } // namespace brickwork
} // namespace masonry

#endif
