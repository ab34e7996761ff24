/**
 * @file
 * CG or GMRES with Trilinos ML AMG, falling back to MUMPS for the rest of
 * the run when a solve fails: the plugins `cg amg' and `gmres amg'
 * (cg_amg.cc, gmres_amg.cc) are this class.
 */
#ifndef masonry_brickwork_solution_krylov_h
#define masonry_brickwork_solution_krylov_h

#include <deal.II/lac/trilinos_precondition.h>

#include <memory>

#include "direct_solver.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /**
       * CG or GMRES with Trilinos ML AMG. Cracked and crushed regions can
       * make the tangent so badly conditioned that the Krylov solver stalls
       * or AztecOO reports a loss of precision. Damage does not heal, so the
       * tangents of the rest of the run are no better: the failed solve and
       * all later ones use MUMPS.
       */
      class KrylovWithFallback : public LinearSolver
      {
      public:
        /** @p cg: CG (else GMRES). */
        explicit KrylovWithFallback(const bool cg);
        ~KrylovWithFallback() override;

        void
        forget() override;

        void
        clear() override;

      protected:
        void
        do_solve(const Matrix &matrix,
                 Vector       &du,
                 const Vector &rhs,
                 const bool    initial_tangent,
                 const bool    reuse) override;

        bool
        kept_is_initial() const override;

        bool
        fallen_back() const override;

        void
        set_fallen_back() override;

      private:
        /** The direct solver a failed Krylov solver hands over to. */
        class Fallback : public DirectSolver
        {
        public:
          using DirectSolver::DirectSolver;
          void
          solve_as_fallback(const Matrix &matrix,
                            Vector       &du,
                            const Vector &rhs,
                            const bool    initial_tangent,
                            const bool    reuse);
          bool
          initial() const;
        };

        /** The AMG hierarchy of @p matrix. */
        void
        make_amg(const Matrix &matrix, const bool initial_tangent);

        bool                                                       cg;
        Fallback                                                   fallback;
        std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> amg;
        bool abandoned = false, is_initial = false;
      };
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
