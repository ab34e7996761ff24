/**
 * @file
 * `Linear solver = direct klu': Amesos KLU.
 */
#include "direct_solver.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      namespace
      {
        /** KLU (serial: Amesos gathers the matrix on one rank). */
        class DirectKlu : public DirectSolver
        {
        public:
          DirectKlu()
            : DirectSolver("Amesos_Klu")
          {}

          static void
          declare_parameters(dealii::ParameterHandler &)
          {}
        };
      } // namespace
    }   // namespace model
  }     // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_LINEAR_SOLVER(masonry::brickwork::model::DirectKlu,
                               "direct klu",
                               "Amesos KLU (serial, gathers the matrix).")
