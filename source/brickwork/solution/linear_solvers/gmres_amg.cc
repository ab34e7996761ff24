/**
 * @file
 * `Linear solver = gmres amg'.
 */
#include "krylov.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      namespace
      {
        /** See krylov.h. */
        class GmresAmg : public KrylovWithFallback
        {
        public:
          GmresAmg()
            : KrylovWithFallback(false)
          {}

          static void
          declare_parameters(dealii::ParameterHandler &)
          {}
        };
      } // namespace
    }   // namespace model
  }     // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_LINEAR_SOLVER(
  masonry::brickwork::model::GmresAmg,
  "gmres amg",
  "GMRES with Trilinos ML algebraic multigrid (any tangent), to `Linear "
  "solver tolerance'.")
