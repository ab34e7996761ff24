/**
 * @file
 * Newton-Raphson for one load step, with a backtracking line search and
 * chord corrections near the solution.
 */
#ifndef masonry_brickwork_model_newton_h
#define masonry_brickwork_model_newton_h

#include <masonry/brickwork/linear_solver.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

#include "../assembly/assembler.h"
#include "../assembly/system.h"
#include "step_controller.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** Newton-Raphson (`Maximum Newton iterations', `Newton tolerance',
       * `Line search', `Predictor', `Newton chord contraction', `Residual
       * reference'). */
      struct NewtonSettings
      {
        /** Iterations and relative residual tolerance. */
        unsigned int max_newton       = 20;
        double       newton_tolerance = 1e-8;
        bool         line_search      = true;
        /** First iterate of a step: the last converged solution plus the
         * last step's displacement increment scaled to this step
         * (`Predictor' = extrapolated), or the last converged solution with
         * only the platen moved (constant). */
        bool extrapolated_predictor = false;
        /** The residual is measured against the largest of the platen
         * reactions of the iterate and of every converged step so far
         * (`Residual reference' = largest reaction), not against the
         * present reactions only (present reaction). */
        bool largest_reaction_reference = false;
        /** A full Newton correction that left at most this fraction of the
         * residual is followed by chord corrections with the same LU
         * factorisation while each leaves at most this fraction (`Newton
         * chord contraction'; 0: none). */
        double chord_contraction = 0.1;
        /** A step starts with chord corrections with the factorisation kept
         * from the step before (`Newton chord across steps'). */
        bool chord_across_steps = false;

        /** Declare the entries in the present subsection. */
        static void
        declare_parameters(dealii::ParameterHandler &prm);
        /** Read them; errors name the entry. */
        void
        parse_parameters(dealii::ParameterHandler &prm);
      };

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

        /** The iterations allowed per step. */
        unsigned int
        max_iterations() const
        {
          return settings.max_newton;
        }

        /** The first iterate of a step whose extrapolation ratio is
         * @p ratio (0: none): with `Predictor = extrapolated' the last
         * step's increment scaled by it is added to system.u. */
        void
        predict(System &system, const double ratio) const;

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
                   StepOutcome  &outcome) const;

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
