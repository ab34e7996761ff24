/**
 * @file
 * The `clp` LP solver back-end: COIN-OR Clp (ClpSimplex).
 */
#include <masonry/core/parameters.h>
#include <masonry/lp/interface.h>

#include <coin/ClpSimplex.hpp>
#include <coin/ClpSolve.hpp>
#include <coin/CoinPackedMatrix.hpp>

#include <chrono>
#include <cmath>
#include <memory>

namespace masonry
{
  namespace lp
  {
    namespace
    {
      /** Clp's representation of an infinite bound. */
      double
      to_clp(const double bound)
      {
        if (bound == infinity)
          return COIN_DBL_MAX;
        if (bound == -infinity)
          return -COIN_DBL_MAX;
        return bound;
      }
    } // namespace

    /**
     * LP solver back-end on COIN-OR Clp: dual simplex, primal simplex or
     * barrier (interior point) followed by crossover to a vertex, with or
     * without Clp's presolve.
     */
    class Clp : public Interface
    {
    public:
      /** Declare `Algorithm` and `Presolve` in `subsection Clp`. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Read `subsection Clp`. */
      void
      parse_parameters(dealii::ParameterHandler &prm) override;

      /** Solve @p lp with Clp. */
      Solution
      solve(const LinearProgram &lp) const override;

    private:
      /** Value of `Algorithm`. */
      std::string algorithm = "dual simplex";
      /** Value of `Presolve`. */
      bool presolve = true;

      /** A silent Clp model holding @p lp, with the time limit set. */
      std::unique_ptr<ClpSimplex>
      create(const LinearProgram &lp) const;

      /** Run the chosen algorithm on @p model. */
      void
      run(ClpSimplex &model, const bool use_presolve) const;
    };


    void
    Clp::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        "Algorithm",
        "dual simplex",
        dealii::Patterns::Selection("dual simplex|primal simplex|barrier"),
        "Algorithm of Clp: `dual simplex', `primal simplex', or `barrier' "
        "(primal-dual interior point followed by crossover, so that the "
        "solution is a vertex as with the simplex methods). Unitless "
        "choice.");
      prm.declare_entry("Presolve",
                        "true",
                        dealii::Patterns::Bool(),
                        "Whether Clp simplifies the problem before solving "
                        "it (removing fixed variables, singleton rows, ...). "
                        "An infeasible or unbounded problem is always "
                        "confirmed without presolve. Unitless flag.");
    }

    void
    Clp::parse_parameters(dealii::ParameterHandler &prm)
    {
      algorithm = prm.get("Algorithm");
      presolve  = prm.get_bool("Presolve");
    }

    std::unique_ptr<ClpSimplex>
    Clp::create(const LinearProgram &lp) const
    {
      auto model = std::make_unique<ClpSimplex>();
      model->setLogLevel(0);
      model->messageHandler()->setLogLevel(0);
      if (time_limit() > 0)
        model->setMaximumSeconds(time_limit());
      const unsigned int                n = lp.n_columns(), m = lp.n_rows();
      const LinearProgram::ColumnMatrix a = lp.column_matrix();
      std::vector<CoinBigIndex>         start(a.start.begin(), a.start.end());
      std::vector<int>                  length(n);
      for (unsigned int j = 0; j < n; ++j)
        length[j] = a.start[j + 1] - a.start[j];
      const CoinPackedMatrix matrix(true,
                                    m,
                                    n,
                                    start[n],
                                    a.value.data(),
                                    a.row_index.data(),
                                    start.data(),
                                    length.data());

      std::vector<double> col_lower(n), col_upper(n), row_lower(m),
        row_upper(m);
      for (unsigned int j = 0; j < n; ++j)
        {
          col_lower[j] = to_clp(lp.column_lower()[j]);
          col_upper[j] = to_clp(lp.column_upper()[j]);
        }
      for (unsigned int i = 0; i < m; ++i)
        {
          row_lower[i] = to_clp(lp.row_lower()[i]);
          row_upper[i] = to_clp(lp.row_upper()[i]);
        }
      model->loadProblem(matrix,
                         col_lower.data(),
                         col_upper.data(),
                         lp.objective().data(),
                         row_lower.data(),
                         row_upper.data());
      model->setOptimizationDirection(lp.maximize ? -1. : 1.);
      return model;
    }

    void
    Clp::run(ClpSimplex &model, const bool use_presolve) const
    {
      ClpSolve options;
      if (algorithm == "primal simplex")
        options.setSolveType(ClpSolve::usePrimal);
      else if (algorithm == "barrier")
        options.setSolveType(ClpSolve::useBarrier); // with crossover
      else
        options.setSolveType(ClpSolve::useDual);
      options.setPresolveType(use_presolve ? ClpSolve::presolveOn :
                                             ClpSolve::presolveOff);
      model.initialSolve(options);
    }

    Solution
    Clp::solve(const LinearProgram &lp) const
    {
      const auto start_time = std::chrono::steady_clock::now();
      Solution   solution;

      std::unique_ptr<ClpSimplex> model = create(lp);
      run(*model, presolve);
      solution.iterations = model->numberIterations();
      if (!model->isProvenOptimal() && presolve &&
          !model->hitMaximumIterations())
        {
          // confirm infeasibility/unboundedness (or recover from a failure)
          // on the original problem: presolve's verdicts are less reliable
          model = create(lp);
          run(*model, false);
          solution.iterations += model->numberIterations();
        }

      if (model->isProvenOptimal())
        {
          const unsigned int n = lp.n_columns(), m = lp.n_rows();
          solution.status = Status::optimal;
          solution.x.assign(model->primalColumnSolution(),
                            model->primalColumnSolution() + n);
          // Clp's duals are d(objective)/d(bound) for the minimisation of
          // direction * c^T x: multiply by the direction to get our
          // convention (derivative of c^T x itself).
          const double direction = model->optimizationDirection();
          solution.row_duals.resize(m);
          for (unsigned int i = 0; i < m; ++i)
            solution.row_duals[i] = direction * model->dualRowSolution()[i];
          solution.objective = lp.objective_value(solution.x);
          solution.message   = "Clp: optimal";
        }
      else if (model->isProvenPrimalInfeasible())
        {
          solution.status  = Status::infeasible;
          solution.message = "Clp: primal infeasible";
        }
      else if (model->isProvenDualInfeasible())
        {
          // dual infeasible: unbounded if primal feasible, which a solve
          // with zero objective decides
          std::unique_ptr<ClpSimplex> feasibility = create(lp);
          for (unsigned int j = 0; j < lp.n_columns(); ++j)
            feasibility->setObjectiveCoefficient(j, 0.);
          feasibility->primal();
          solution.iterations += feasibility->numberIterations();
          if (feasibility->isProvenOptimal())
            {
              solution.status  = Status::unbounded;
              solution.message = "Clp: unbounded (dual infeasible)";
            }
          else if (feasibility->isProvenPrimalInfeasible())
            {
              solution.status  = Status::infeasible;
              solution.message = "Clp: primal and dual infeasible";
            }
          else
            solution.message = "Clp: dual infeasible, primal feasibility "
                               "undecided";
        }
      else if (model->hitMaximumIterations())
        solution.message = "Clp: stopped on the time or iteration limit";
      else
        solution.message =
          "Clp: failed with status " + std::to_string(model->status()) +
          ", secondary status " + std::to_string(model->secondaryStatus());

      solution.seconds = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start_time)
                           .count();
      return solution;
    }
  } // namespace lp
} // namespace masonry

MASONRY_REGISTER_LP_SOLVER(masonry::lp::Clp,
                           "clp",
                           "COIN-OR Clp: dual or primal simplex, or barrier "
                           "with crossover.")
