/**
 * @file
 * What every linear solver shares: the tolerance, the counters.
 */
#include <masonry/brickwork/linear_solver.h>
#include <masonry/core/parameters.h>

#include <chrono>

namespace masonry
{
  namespace brickwork
  {
    using Clock = std::chrono::steady_clock;

    const char *
    LinearSolver::default_plugin()
    {
      return "direct";
    }

    std::string
    LinearSolver::selection_documentation()
    {
      return "The solver of the Newton corrections. A Krylov solve that "
             "fails (1000 iterations, or AztecOO's loss of precision on a "
             "cracked tangent) is redone by MUMPS, and MUMPS solves the rest "
             "of the run (damage does not heal); summary.json: "
             "direct_solver_fallbacks.";
    }

    void
    LinearSolver::declare_common_parameters(dealii::ParameterHandler &prm)
    {
      declare_ranged_entry(prm,
                           "Linear solver tolerance",
                           "1e-10",
                           {1e-16, 0.1, "(dimensionless)"},
                           "Relative residual tolerance of the iterative "
                           "linear solvers (dimensionless).");
    }

    void
    LinearSolver::parse_common_parameters(dealii::ParameterHandler &prm)
    {
      tolerance = positive_entry(prm, "Linear solver tolerance");
    }


    void
    LinearSolver::initialize(const dealii::DoFHandler<3> &dofs,
                             dealii::ConditionalOStream  &out)
    {
      dof_handler = &dofs;
      pcout       = &out;
    }

    void
    LinearSolver::solve(const Matrix &matrix,
                        Vector       &du,
                        const Vector &rhs,
                        const bool    initial_tangent)
    {
      const auto start = Clock::now();
      ++statistics.n_solves;
      // the factorisation (or AMG hierarchy) of the initial tangent is
      // kept while the tangent stays the initial one: every step of a
      // linear model, the elastic steps of a nonlinear one
      const bool reuse = initial_tangent && kept_is_initial();
      if (reuse)
        ++statistics.n_factorisations_reused;
      do_solve(matrix, du, rhs, initial_tangent, reuse);
      statistics.seconds +=
        std::chrono::duration<double>(Clock::now() - start).count();
    }

    bool
    LinearSolver::has_kept_factors() const
    {
      return false;
    }

    void
    LinearSolver::solve_with_kept_factors(Vector &, const Vector &)
    {
      AssertThrow(false, dealii::ExcInternalError());
    }

    void
    LinearSolver::clear()
    {}

    void
    LinearSolver::drop_factors()
    {}

    bool
    LinearSolver::fallen_back() const
    {
      return false;
    }

    void
    LinearSolver::set_fallen_back()
    {}
  } // namespace brickwork
} // namespace masonry
