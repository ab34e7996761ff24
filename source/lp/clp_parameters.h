/**
 * @file
 * The entries of `subsection LP solver / subsection Clp`: their texts are
 * the reference of the `clp` back-end (source/lp/clp.cc). Private to it.
 */
#ifndef masonry_lp_clp_parameters_h
#define masonry_lp_clp_parameters_h

namespace dealii
{
  class ParameterHandler;
}

namespace masonry
{
  namespace lp
  {
    /** Declare `Algorithm`, `Crossover`, `Interior point tolerance` and
     *  `Presolve` in the current subsection. */
    void
    declare_clp_parameters(dealii::ParameterHandler &prm);
  } // namespace lp
} // namespace masonry

#endif
