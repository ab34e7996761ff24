/**
 * @file
 * `Linear solver = cg amg'.
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
        class CgAmg : public KrylovWithFallback
        {
        public:
          CgAmg()
            : KrylovWithFallback(true)
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
  masonry::brickwork::model::CgAmg,
  "cg amg",
  "Conjugate gradients with Trilinos ML algebraic multigrid (for symmetric "
  "tangents: elastic joints), to `Linear solver tolerance'.")
