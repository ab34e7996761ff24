/**
 * @file
 * The linear solvers of the wallette's Newton corrections (`subsection
 * Wallette / set Linear solver = ...'): a plugin family, one file per
 * solver (source/brickwork/solution/linear_solvers/; a test defines one of
 * its own, tests/brickwork_custom_solver.cc). A solver is chosen
 * once a run and keeps what it can reuse (a symbolic analysis, the
 * factorisation of the initial tangent, a preconditioner) between solves.
 * The solvers' entries stand in `subsection Wallette' next to the
 * analysis's own.
 */
#ifndef masonry_brickwork_linear_solver_h
#define masonry_brickwork_linear_solver_h

#include <masonry/core/plugins.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <stdexcept>
#include <string>

namespace masonry
{
  namespace brickwork
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
      /** Solves with the kept factorisation of an earlier tangent (chord
       * steps of Newton). */
      unsigned int n_chord_solves = 0;
      /** Krylov solves that did not converge and were done by MUMPS. */
      unsigned int n_direct_fallbacks = 0;
      /** Wall time in solves, s. */
      double seconds = 0;
    };

    /** A linear solve that failed: a one-line message (MUMPS: its
     * INFOG(1), INFOG(2) and what they mean). Newton cuts the step back. */
    class LinearSolverFailure : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    /** Solves matrix du = rhs for the Newton corrections. */
    class LinearSolver : public plugins::InterfaceBase
    {
    public:
      using Matrix = dealii::TrilinosWrappers::SparseMatrix;
      using Vector = dealii::TrilinosWrappers::MPI::Vector;

      /** The selection `set Linear solver = ...' stands in `subsection
       * Wallette', with the solvers' own entries. */
      static constexpr const char *registry_section  = "Wallette";
      static constexpr const char *registry_entry    = "Linear solver";
      static constexpr bool        shared_subsection = true;
      /** Default selection: "direct". */
      static const char *
      default_plugin();
      /** Help text of the selection entry. */
      static std::string
      selection_documentation();
      /** `Linear solver tolerance'. */
      static void
      declare_common_parameters(dealii::ParameterHandler &prm);

      /** Read `Linear solver tolerance'. */
      void
      parse_common_parameters(dealii::ParameterHandler &prm) override;

      /** Before the first solve: the DoFs of the matrices to come (AMG's
       * rigid modes) and where notes go. */
      virtual void
      initialize(const dealii::DoFHandler<3> &dof_handler,
                 dealii::ConditionalOStream  &pcout);

      /**
       * Solve with @p matrix. @p initial_tangent: the matrix is the
       * initial (elastic) tangent, so a factorisation or preconditioner
       * made for an earlier initial tangent is kept. Throws
       * LinearSolverFailure (or another exception) when it fails.
       */
      void
      solve(const Matrix &matrix,
            Vector       &du,
            const Vector &rhs,
            const bool    initial_tangent);

      /** Whether a factorisation of an earlier tangent is kept that
       * solve_with_kept_factors() can use (none by default). */
      virtual bool
      has_kept_factors() const;

      /** du = the kept factorisation's inverse times @p rhs (a chord step
       * of Newton: the tangent is not factorised anew); only when
       * has_kept_factors(). */
      virtual void
      solve_with_kept_factors(Vector &du, const Vector &rhs);

      /** The matrix changed its structure of values for good (cells were
       * deleted): a kept factorisation or preconditioner of the initial
       * tangent is no longer that of the new initial tangent. */
      virtual void
      forget() = 0;

      /** The matrices of the run are gone: drop whatever refers to them
       * (factorisations, preconditioners). Nothing by default. */
      virtual void
      clear();

      /** Let the kept factorisation go (not the analysis of the matrix's
       * structure): the next solve factorises, as the first one after a
       * resume from a checkpoint does. Nothing by default. */
      virtual void
      drop_factors();

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
      do_solve(const Matrix &matrix,
               Vector       &du,
               const Vector &rhs,
               const bool    initial_tangent,
               const bool    reuse) = 0;
      /** Whether the kept factorisation or preconditioner is that of an
       * initial tangent. */
      virtual bool
      kept_is_initial() const = 0;
      /** Whether a Krylov solver has given up (default: never). */
      virtual bool
      fallen_back() const;
      virtual void
      set_fallen_back();

      /** `Linear solver tolerance': relative residual of iterative
       * solves. */
      double tolerance = 1e-10;
      /** The DoFs (initialize()), nullptr before. */
      const dealii::DoFHandler<3> *dof_handler = nullptr;
      /** Where notes go (initialize()), nullptr before. */
      dealii::ConditionalOStream *pcout = nullptr;
    };
  } // namespace brickwork
} // namespace masonry

/** Register a linear solver (one line in its .cc file). */
#define MASONRY_REGISTER_LINEAR_SOLVER(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::brickwork::LinearSolver,          \
                          classname,                                 \
                          name,                                      \
                          description)

#endif
