/**
 * @file
 * A direct solver through Trilinos Amesos (MUMPS or KLU): the symbolic
 * analysis once a run, a numeric factorisation per new tangent, the
 * factorisation of the initial tangent kept while the tangent stays the
 * initial one, and (`Factorisation reuse iterations') GMRES with the last
 * factorisation before a new one. The plugins `direct' and `direct klu'
 * (direct.cc, direct_klu.cc) are this class; the Krylov solvers fall back
 * to it.
 */
#ifndef masonry_brickwork_solution_direct_solver_h
#define masonry_brickwork_solution_direct_solver_h

#include <masonry/brickwork/linear_solver.h>

#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <memory>
#include <string>

class Amesos_Mumps;

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** See the file's description. */
      class DirectSolver : public LinearSolver
      {
      public:
        /** @p name: Amesos_Mumps or Amesos_Klu. */
        explicit DirectSolver(const std::string &name);
        ~DirectSolver() override;

        /** Factorise @p matrix and solve. */
        void
        factorise_and_solve(const Matrix &matrix,
                            Vector       &du,
                            const Vector &rhs,
                            const bool    initial_tangent);

        void
        forget() override;

        void
        clear() override;

        void
        drop_factors() override;

        bool
        has_kept_factors() const override;

        void
        solve_with_kept_factors(Vector &du, const Vector &rhs) override;

      protected:
        void
        do_solve(const Matrix &matrix,
                 Vector       &du,
                 const Vector &rhs,
                 const bool    initial_tangent,
                 const bool    reuse) override;

        bool
        kept_is_initial() const override;

        /** GMRES with the last factorisation before a new one, up to this
         * many iterations (0: never; `Factorisation reuse iterations'). */
        unsigned int reuse_iterations = 0;

      private:
        /** The last factorisation as a preconditioner. */
        struct OldFactors
        {
          DirectSolver *direct;
          void
          vmult(Vector &dst, const Vector &src) const;
        };

        /** dst = the kept factors' inverse times src. */
        void
        apply_factors(Vector &dst, const Vector &src);

        /**
         * GMRES (right-preconditioned: the true residual) on @p matrix with
         * the last factorisation as the preconditioner, to the relative
         * `tolerance'; false (du zeroed) when it needs more than
         * `reuse_iterations' or fails.
         */
        bool
        solve_with_old_factors(const Matrix &matrix,
                               Vector       &du,
                               const Vector &rhs);

        /** The solver of @p matrix and its symbolic analysis. */
        void
        make(const Matrix &matrix);

        /**
         * MUMPS's fill-reducing ordering (ICNTL(7)): of AMF, PORD and
         * QAMD the one whose analysis predicts the fewest flops of a
         * factorisation (RINFOG(1)), rank 0's choice on every rank. The
         * analysis is done once a run and the factorisation once a Newton
         * iteration, so the trial costs nothing against what it saves.
         * MUMPS's own choice (ICNTL(7) = 7) takes AMF for the single
         * cyclic example: 2.37e8 flops, where QAMD needs 1.63e8 (9 % of
         * the CPU time of its first 300 steps); PORD, its choice for the
         * double and triple ones, is the best there (triple: 4.4e9, AMF
         * 5.2e9, QAMD 5.5e9).
         * METIS and SCOTCH are not in Debian's sequential analysis
         * (contrib/benchmarks/wallette_cyclic/results-2026-11-25c.md).
         */
        void
        choose_ordering(Amesos_Mumps &mumps, const MPI_Comm comm);

        /** Solve, factorising first when @p factorise. */
        void
        solve_with(Vector       &du,
                   const Vector &rhs,
                   const bool    factorise,
                   const bool    initial_tangent);

        /** Whether MUMPS reported an error (INFOG(1) < 0). */
        bool
        failed();

        /** A one-line error of the solver, with MUMPS's INFOG. */
        [[noreturn]] void
        fail(const std::string &what);

        std::string                        name;
        Epetra_LinearProblem               problem;
        std::unique_ptr<Amesos_BaseSolver> direct;
        bool                               is_initial = false;
        /** A numeric factorisation (of some earlier tangent) exists. */
        bool factorised = false;
      };
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
