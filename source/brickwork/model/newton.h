/**
 * @file
 * Newton-Raphson for one load step, with a backtracking line search and
 * chord corrections near the solution.
 */
#ifndef masonry_brickwork_model_newton_h
#define masonry_brickwork_model_newton_h

#include <masonry/brickwork/wallette.h>

#include <string>

#include "assembler.h"
#include "linear_solvers.h"
#include "system.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** Solves the equilibrium of a step by Newton-Raphson. */
      class Newton
      {
      public:
        /**
         * @p minimum_force: the force the residual is measured against
         * when nothing is loaded (N), a fraction of the elastic force of
         * the whole applied displacement.
         */
        Newton(const NewtonSettings &settings, const double minimum_force);

        /**
         * Move the platen to @p displacement (m) and iterate from the
         * current solution; whether the step converged, and the number of
         * @p iterations (Newton corrections, each with a new tangent: a
         * full correction that leaves at most `Newton chord contraction' of
         * the residual is followed by chord corrections with the same
         * factorisation while each does as well, not counted here and not
         * against `Maximum Newton iterations'). A material or solver failure
         * counts as no convergence (the caller cuts the step back). A step that
         * failed on a number that is not finite names where in @p non_finite
         * (else it is left empty): "the stresses of the bricks (Newton
         * iteration 2)", ...; @p failure: why a step that did not converge
         * failed, in a few words ("MUMPS could not factorise the tangent:
         * INFOG(1) = -10, ... (Newton iteration 3)", "the residual ... after 50
         * Newton iterations").
         *
         * @p reference: the largest norm of the platen reactions of the
         * converged steps so far (N); with `Residual reference = largest
         * reaction' the residual is measured against it when the present
         * reactions are smaller. @p reaction: the norm of the platen
         * reactions of the converged state (N).
         */
        bool
        solve_step(System       &system,
                   Assembler    &assembler,
                   LinearSolver &solver,
                   const double  displacement,
                   const double  time_step,
                   const double  reference,
                   unsigned int &iterations,
                   double       &reaction,
                   std::string  &non_finite,
                   std::string  &failure) const;

      private:
        /** Whether the residual @p norm is small against the reactions
         * (@p all: the norm of the internal forces with them) or the
         * @p reference force; @p reaction: the norm of the reactions. */
        bool
        converged(const double norm,
                  const double all,
                  const double reference,
                  double      &reaction) const;

        /** The line search after the correction @p du from @p u_start;
         * true when it lands on a converged state. Otherwise the step length
         * taken and the residual norm there in @p accepted_alpha and
         * @p accepted_norm. */
        bool
        line_search(System               &system,
                    Assembler            &assembler,
                    const System::Vector &u_start,
                    const System::Vector &du,
                    const double          norm0,
                    const double          time_step,
                    const double          reference,
                    double               &reaction,
                    double               &accepted_alpha,
                    double               &accepted_norm) const;

        NewtonSettings settings;
        double         minimum_force;
      };
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
