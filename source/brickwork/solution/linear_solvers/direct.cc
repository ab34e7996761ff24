/**
 * @file
 * `Linear solver = direct': sparse LU by MUMPS through Amesos.
 */
#include <masonry/core/parameters.h>

#include "direct_solver.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      namespace
      {
        /** MUMPS, with the optional GMRES on the last factorisation. */
        class Direct : public DirectSolver
        {
        public:
          Direct()
            : DirectSolver("Amesos_Mumps")
          {}

          static void
          declare_parameters(dealii::ParameterHandler &prm)
          {
            declare_ranged_iterations(
              prm,
              "Factorisation reuse iterations",
              "0",
              0,
              1000,
              "`Linear solver = direct' only: a Newton correction is first "
              "solved by GMRES with the last LU factorisation (of an earlier "
              "tangent) as the preconditioner, to `Linear solver tolerance'; "
              "when GMRES needs more than this many iterations the tangent "
              "is factorised anew and solved directly (dimensionless count; "
              "0: every solve factorises). Saves factorisations while the "
              "tangent changes little (elastic legs, IMPL-EX steps); the "
              "Newton iterates differ from those of the direct solve by the "
              "linear tolerance, the converged states by the `Newton "
              "tolerance'.");
          }

          void
          parse_parameters(dealii::ParameterHandler &prm) override
          {
            reuse_iterations =
              prm.get_integer("Factorisation reuse iterations");
          }
        };
      } // namespace
    }   // namespace model
  }     // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_LINEAR_SOLVER(
  masonry::brickwork::model::Direct,
  "direct",
  "Sparse LU by MUMPS through Trilinos Amesos (parallel); below some 10^5 "
  "DOFs usually the fastest for damaged wallettes.")
