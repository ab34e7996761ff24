/**
 * @file
 * The linear solvers of the Newton corrections, one object chosen once from
 * `Linear solver': a direct solver (MUMPS or KLU through Amesos, symbolic
 * analysis once per run) or an AMG-preconditioned Krylov solver (CG or
 * GMRES) that falls back to MUMPS for the rest of the run when it fails.
 */
#ifndef masonry_brickwork_model_linear_solvers_h
#define masonry_brickwork_model_linear_solvers_h

#include <masonry/brickwork/wallette.h>

#include <deal.II/base/conditional_ostream.h>

#include <memory>
#include <stdexcept>

#include "system.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** Counters of the solves (summary.json). */
      struct SolverStatistics
      {
        unsigned int n_solves = 0, n_factorisations_reused = 0;
        /** Solves done by GMRES with an earlier factorisation
         * (`Factorisation reuse iterations'), and their iterations. */
        unsigned int n_reuse_solves = 0, n_reuse_iterations = 0;
        /** Numeric factorisations, and those of them in which MUMPS found
         * null pivots (a singular tangent: parts free in some direction). */
        unsigned int n_factorisations = 0, n_null_pivot_factorisations = 0;
        /** Solves with the kept factorisation of an earlier tangent
         * (chord steps of Newton). */
        unsigned int n_chord_solves = 0;
        /** Krylov solves that did not converge and were done by MUMPS. */
        unsigned int n_direct_fallbacks = 0;
        /** Wall time in solves, s. */
        double seconds = 0;
      };

      /** A linear solve that failed: a one-line message (MUMPS: its
       * INFOG(1), INFOG(2) and what they mean). */
      class LinearSolverFailure : public std::runtime_error
      {
      public:
        using std::runtime_error::runtime_error;
      };

      /** Solves system.matrix du = rhs. */
      class LinearSolver
      {
      public:
        virtual ~LinearSolver() = default;

        /**
         * Solve with the current matrix of @p system. @p initial_tangent:
         * the matrix is the initial (elastic) tangent, so a factorisation
         * or preconditioner made for an earlier initial tangent is kept.
         */
        void
        solve(System               &system,
              System::Vector       &du,
              const System::Vector &rhs,
              const bool            initial_tangent);

        /** Whether a factorisation of an earlier tangent is kept that
         * solve_with_kept_factors() can use. */
        virtual bool
        has_kept_factors() const
        {
          return false;
        }

        /** du = the kept factorisation's inverse times @p rhs (a chord
         * step of Newton: the tangent is not factorised anew); only when
         * has_kept_factors(). */
        virtual void
        solve_with_kept_factors(System               &system,
                                System::Vector       &du,
                                const System::Vector &rhs);

        /** The matrix changed its structure of values for good (cells were
         * deleted): a kept factorisation or preconditioner of the initial
         * tangent is no longer that of the new initial tangent. */
        virtual void
        forget() = 0;

        /** Write or read what changes the later solves (a fallback that
         * happened) and the counters. */
        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          bool fell_back = fallen_back();
          ar &statistics.n_solves &statistics.n_direct_fallbacks &fell_back;
          if (Archive::is_loading::value && fell_back)
            set_fallen_back();
        }

        SolverStatistics statistics;

      protected:
        /** The solve itself; @p reuse: the kept factorisation or
         * preconditioner is valid for this matrix. */
        virtual void
        do_solve(System               &system,
                 System::Vector       &du,
                 const System::Vector &rhs,
                 const bool            initial_tangent,
                 const bool            reuse) = 0;
        /** Whether the kept factorisation or preconditioner is that of an
         * initial tangent. */
        virtual bool
        kept_is_initial() const = 0;
        /** Whether a Krylov solver has given up (default: never). */
        virtual bool
        fallen_back() const
        {
          return false;
        }
        virtual void
        set_fallen_back()
        {}
      };

      /** The solver of @p settings; notes go to @p pcout. */
      std::unique_ptr<LinearSolver>
      create_linear_solver(const LinearSolverSettings &settings,
                           dealii::ConditionalOStream &pcout);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
