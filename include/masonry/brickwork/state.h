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

    /**
     * What every law of the model (brick material, interface law) declares
     * about the state of its points, so that the model stores, initialises,
     * checkpoints, reports and extrapolates it without naming one of its
     * variables: the state variables, their initial values, the reported
     * quantities (averaged over the points of a cell or a joint face in the
     * VTU output), the damage variables and the values derived from the
     * inputs.
     */
    class PointLaw
    {
    public:
      virtual ~PointLaw() = default;

      /**
       * The state variables of a point (names, sizes): what the law's
       * evaluation reads from the old state and writes to the updated one.
       * None by default.
       */
      virtual std::vector<StateVariable>
      state_variables() const;

      /** The state of a point before any loading: zeros by default. */
      virtual void
      initial_state(StateView state) const;

      /**
       * Names of the quantities written for each cell or joint face
       * (averaged over its points) to the VTU/HDF5 output; by default every
       * component of the state variables.
       */
      virtual std::vector<std::string>
      reported_quantities() const;

      /** The values of reported_quantities() for @p state. */
      virtual void
      report(ConstStateView state, dealii::ArrayView<double> values) const;

      /**
       * Names of the damage variables (0 intact to 1), reported as their
       * largest value (a brick material's in curve.csv as brick_NAME and in
       * summary.json as max_brick_NAME; an interface law's as max_damage in
       * curve.csv) and whose extrapolation error controls the IMPL-EX step;
       * a damaged joint point has no initial tangent. None by default.
       */
      virtual std::vector<std::string>
      damage_names() const;

      /** The values of damage_names() for @p state. */
      virtual void
      damages(ConstStateView state, dealii::ArrayView<double> values) const;

      /**
       * The values this law computed from its inputs (see DerivedValue);
       * none by default.
       */
      virtual std::vector<DerivedValue>
      derived_values() const;
    };
  } // namespace brickwork
} // namespace masonry

#endif
