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
#include <unordered_map>

#include "clp.h"
#include "clp_barrier.h"
#include "clp_parameters.h"
#include "clp_verdict.h"

namespace masonry
{
  namespace lp
  {
    /** Clp's basis (status of every column, then of every row). */
    struct ClpBasis : public WarmStartData
    {
      unsigned int               n_columns = 0, n_rows = 0;
      std::vector<unsigned char> status;
      /** WarmStart::row_keys of the LP it comes from (may be empty). */
      std::vector<long long> row_keys;
    };

    /**
     * What one solve() has done so far, passed from each of its stages
     * to the next.
     */
    struct Attempt
    {
      /** The Clp model of the LP that the stages solve. */
      std::unique_ptr<ClpSimplex> model;
      /** The method that solves @p model ("dual simplex", ...). */
      std::string method;
      /** Whether the result is settled (nothing more to solve). */
      bool done = false;
      /** Whether a simplex ran from a stored basis. */
      bool warm = false;
      /**
       * Whether the route through the dual proved the LP without a dual
       * feasible point (DualRoute::dual_infeasible).
       */
      bool dual_infeasible = false;
      /** Whether the barrier's interior point is the result. */
      bool kept_interior = false;
      /** Whether the barrier with crossover already ran on @p model. */
      bool barrier_ran = false;
      /** The barrier's interior point, if one was checked. */
      Interior interior;
      /** What the auxiliary LPs of decide_verdict() found, if they ran. */
      Verdict verdict;
    };

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

      /**
       * Whether the optimal solution of @p model is a valid optimality
       * certificate for @p lp: finite primal values, and every nonzero row
       * dual or reduced cost d = c - A^T y has the sign of a finite bound.
       */
      bool
      certificate_ok(const LinearProgram &lp, const ClpSimplex &model)
      {
        const unsigned int n = lp.n_columns(), m = lp.n_rows();
        const double       sense = lp.maximize ? 1. : -1.;
        const double      *x     = model.primalColumnSolution();
        const double      *y     = model.dualRowSolution();
        for (unsigned int j = 0; j < n; ++j)
          if (!(std::abs(x[j]) < 1e20))
            return false;
        std::vector<double> d = lp.objective();
        for (const auto &e : lp.entries())
          d[e.column] -= e.value * y[e.row];
        // a positive sense*dual means the upper bound is active
        const auto allowed =
          [sense](const double dual, const double lower, const double upper) {
            const double tolerance = 1e-7;
            if (sense * dual > tolerance)
              return upper < infinity;
            if (sense * dual < -tolerance)
              return lower > -infinity;
            return true;
          };
        for (unsigned int i = 0; i < m; ++i)
          if (!allowed(y[i], lp.row_lower()[i], lp.row_upper()[i]))
            return false;
        for (unsigned int j = 0; j < n; ++j)
          if (!allowed(d[j], lp.column_lower()[j], lp.column_upper()[j]))
            return false;
        return true;
      }

      /**
       * @p stored mapped to an LP with the same columns and the rows
       * identified by @p keys: a row takes the status of the stored row
       * with its key, a new row's slack is basic. Clp repairs a basis with
       * the wrong number of basic variables when it factorises it.
       */
      ClpBasis
      remap(const ClpBasis &stored, const std::vector<long long> &keys)
      {
        ClpBasis basis;
        basis.n_columns = stored.n_columns;
        basis.n_rows    = keys.size();
        basis.row_keys  = keys;
        basis.status.assign(stored.status.begin(),
                            stored.status.begin() + stored.n_columns);
        std::unordered_map<long long, unsigned int> row_of;
        row_of.reserve(stored.row_keys.size());
        for (unsigned int i = 0; i < stored.row_keys.size(); ++i)
          row_of.emplace(stored.row_keys[i], i);
        for (const long long key : keys)
          {
            const auto i = row_of.find(key);
            basis.status.push_back(
              i != row_of.end() ?
                stored.status[stored.n_columns + i->second] :
                static_cast<unsigned char>(ClpSimplex::basic));
          }
        return basis;
      }

      /**
       * The optimal vertex in @p model, read into @p solution, failed the
       * check at @p tolerance: the primal simplex from its basis on the
       * unscaled problem, its vertex kept if it checks out better, and
       * the message says how it ended.
       */
      void
      resolve_unscaled(const LinearProgram &lp,
                       ClpSimplex          &model,
                       const double         tolerance,
                       Solution            &solution)
      {
        const unsigned int n = lp.n_columns(), m = lp.n_rows();
        // a vertex optimal only within Clp's tolerances on its scaled
        // problem: the primal simplex from its basis on the unscaled
        // one, kept if it checks out better
        const std::string first = solution.check.describe();
        model.scaling(0);
        model.primal(1);
        solution.iterations += model.numberIterations();
        if (model.isProvenOptimal())
          {
            std::vector<double> x(model.primalColumnSolution(),
                                  model.primalColumnSolution() + n),
              y(model.dualRowSolution(), model.dualRowSolution() + m);
            const PairCheck again = check_pair(lp, x, y);
            const auto      worst = [](const PairCheck &c) {
              return std::max(
                {c.primal_residual, c.dual_residual, c.relative_gap()});
            };
            if (worst(again) < worst(solution.check))
              {
                solution.x         = std::move(x);
                solution.row_duals = std::move(y);
                solution.objective = lp.objective_value(solution.x);
                solution.check     = again;
              }
          }
        solution.message +=
          " (failed the check, " + first +
          (solution.check.within(tolerance) ?
             std::string("; solved again by the primal simplex on the "
                         "unscaled problem)") :
             "; still failing after a re-solve: " + solution.check.describe() +
               ")");
      }

      /**
       * The status and message of @p solution for an LP without a dual
       * feasible point, from @p phase_1 (verdict_when_dual_infeasible()):
       * unbounded, infeasible, or undecided.
       */
      void
      report_dual_infeasible(Verdict &&phase_1, Solution &solution)
      {
        if (phase_1.outcome == Verdict::Outcome::unbounded)
          {
            solution.status = Status::unbounded;
            solution.message =
              "Clp: unbounded (dual infeasible" +
              (phase_1.description.empty() ? std::string() :
                                             ", " + phase_1.description) +
              ")";
          }
        else if (phase_1.outcome == Verdict::Outcome::infeasible)
          {
            solution.status = Status::infeasible;
            solution.message =
              "Clp: primal and dual infeasible" +
              (phase_1.description.empty() ? std::string() :
                                             " (" + phase_1.description + ")");
            solution.row_misfit = std::move(phase_1.row_misfit);
          }
        else
          solution.message = "Clp: dual infeasible, primal feasibility "
                             "undecided";
      }
    } // namespace

    void
    Clp::declare_parameters(dealii::ParameterHandler &prm)
    {
      declare_clp_parameters(prm);
    }

    void
    Clp::parse_parameters(dealii::ParameterHandler &prm)
    {
      algorithm          = prm.get("Algorithm");
      presolve           = prm.get_bool("Presolve");
      no_crossover       = prm.get("Crossover") == "never";
      interior_tolerance = prm.get_double("Interior point tolerance");
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
    Clp::run(ClpSimplex        &model,
             const std::string &method,
             const bool         use_presolve) const
    {
      if (method == "barrier" && !use_presolve)
        {
          barrier_with_crossover(model); // ClpSolve's steps, faster
          return;
        }
      ClpSolve options;
      if (method == "primal simplex")
        options.setSolveType(ClpSolve::usePrimal);
      else if (method == "barrier")
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
      return solve(lp, nullptr, nullptr);
    }

    Solution
    Clp::solve_warm(const LinearProgram &lp, WarmStart &warm) const
    {
      const ClpBasis *in    = dynamic_cast<const ClpBasis *>(warm.data.get());
      const bool      keyed = warm.row_keys.size() == lp.n_rows() && in &&
                         in->row_keys.size() == in->n_rows &&
                         in->n_columns == lp.n_columns();
      ClpBasis mapped;
      if (keyed && warm.row_keys != in->row_keys)
        {
          mapped = remap(*in, warm.row_keys);
          in     = &mapped;
        }
      else if (in && !keyed &&
               (in->n_columns != lp.n_columns() || in->n_rows != lp.n_rows()))
        in = nullptr;
      auto out = std::make_unique<ClpBasis>();
      if (warm.row_keys.size() == lp.n_rows())
        out->row_keys = warm.row_keys;
      Solution solution = solve(lp, in, out.get());
      if (in)
        ++warm.n_warm;
      if (solution.status == Status::optimal)
        warm.data = std::move(out);
      return solution;
    }

    void
    Clp::solve_from_basis(const LinearProgram &lp,
                          const ClpBasis      &basis,
                          Attempt             &attempt,
                          unsigned int        &iterations) const
    {
      std::unique_ptr<ClpSimplex> &model = attempt.model;
      // a simplex from the stored basis, without presolve (which would
      // drop it); its verdict is then handled as a cold one's
      model->copyinStatus(basis.status.data());
      if (algorithm == "primal simplex")
        model->primal(0);
      else
        model->dual(0);
      iterations += model->numberIterations();
      attempt.method =
        algorithm == "primal simplex" ? "primal simplex" : "dual simplex";
      attempt.warm = true;
      attempt.done = model->isProvenOptimal() ||
                     model->isProvenPrimalInfeasible() ||
                     model->isProvenDualInfeasible();
      if (!attempt.done)
        model = create(lp);
    }

    void
    Clp::solve_cold(const LinearProgram &lp,
                    const bool           use_interior,
                    Attempt             &attempt,
                    unsigned int        &iterations) const
    {
      std::unique_ptr<ClpSimplex> &model    = attempt.model;
      Interior                    &interior = attempt.interior;
      if (!attempt.warm && algorithm == "barrier" && use_interior)
        {
          // the LP itself by the barrier, without presolve
          const auto keep = [&](const ClpSimplex &point) {
            interior.x.assign(point.primalColumnSolution(),
                              point.primalColumnSolution() + lp.n_columns());
            interior.y.assign(point.dualRowSolution(),
                              point.dualRowSolution() + lp.n_rows());
            interior.check = check_pair(lp, interior.x, interior.y);
            return interior.check.within(interior_tolerance);
          };
          attempt.kept_interior = barrier_with_crossover(*model, keep);
          // otherwise the crossover ran: as run() without presolve
          attempt.done        = attempt.kept_interior;
          attempt.barrier_ran = !attempt.kept_interior;
          if (attempt.kept_interior)
            iterations += model->numberIterations();
        }
      if (!attempt.warm && algorithm == "automatic")
        {
          // measured (contrib/benchmarks/lp_solvers): the explicit dual LP,
          // with more columns than rows (Mohr-Coulomb) by the barrier,
          // otherwise (no tension no sliding: many rows, few columns) by
          // the primal simplex; the LP itself by the same method if that
          // fails
          attempt.method =
            lp.n_columns() >= lp.n_rows() ? "barrier" : "primal simplex";
          const DualRoute route =
            solve_through_dual(*model,
                               attempt.method,
                               iterations,
                               lp,
                               use_interior ? &interior : nullptr,
                               attempt.verdict);
          attempt.kept_interior = route == DualRoute::interior;
          attempt.done = route == DualRoute::optimal || attempt.kept_interior ||
                         route == DualRoute::decided;
          attempt.dual_infeasible = route == DualRoute::dual_infeasible;
          if (!attempt.done && !attempt.dual_infeasible)
            model = create(lp);
        }
      if (!attempt.done && !attempt.dual_infeasible)
        {
          if (!attempt.barrier_ran)
            run(*model, attempt.method, presolve);
          iterations += model->numberIterations();
        }
    }

    void
    Clp::confirm(const LinearProgram &lp,
                 Attempt             &attempt,
                 unsigned int        &iterations) const
    {
      std::unique_ptr<ClpSimplex> &model  = attempt.model;
      std::string                 &method = attempt.method;
      if (attempt.done || attempt.dual_infeasible)
        return;
      if (!model->isProvenOptimal() && presolve &&
          !model->hitMaximumIterations())
        {
          // confirm infeasibility/unboundedness (or recover from a failure)
          // on the original problem: presolve's verdicts are less reliable
          model = create(lp);
          run(*model, method, false);
          iterations += model->numberIterations();
        }
      if (model->isProvenPrimalInfeasible() && method != "primal simplex")
        {
          // the dual simplex (or the barrier) misjudges some feasible LPs
          // with thin feasible sets as infeasible (the normalised collapse
          // LP of a minimum-thickness arch just below the minimum): an
          // infeasible verdict is confirmed by the primal simplex on the
          // original problem
          model = create(lp);
          run(*model, "primal simplex", false);
          iterations += model->numberIterations();
          method = "primal simplex";
        }
      if (model->isProvenOptimal() && method == "barrier" &&
          !certificate_ok(lp, *model))
        {
          // the barrier maps infinite bounds to huge finite ones, so that an
          // unbounded problem comes back "optimal" at a huge vertex: the
          // duals then have a sign that only a finite bound allows. Decide
          // with the primal simplex on the original problem. Not after a
          // simplex: its verdict is reliable, and on large LPs (the
          // settlement benchmark at 2048 blocks) its unscaled duals miss the
          // sign test by round-off (4e-6), which made every solve run twice
          // and end at a less accurate vertex of the unpresolved problem.
          model = create(lp);
          ClpSolve options;
          options.setSolveType(ClpSolve::usePrimal);
          options.setPresolveType(ClpSolve::presolveOff);
          model->initialSolve(options);
          iterations += model->numberIterations();
        }
    }

    void
    Clp::read_optimum(const LinearProgram &lp,
                      ClpSimplex          &model,
                      const Interior      &interior,
                      ClpBasis            *basis_out,
                      Solution            &solution) const
    {
      const unsigned int n = lp.n_columns(), m = lp.n_rows();
      solution.status = Status::optimal;
      solution.x.assign(model.primalColumnSolution(),
                        model.primalColumnSolution() + n);
      // Clp's row duals are d(c^T x)/d(row bound) for either sense
      // (with the objective as given, not as minimised internally): our
      // convention already
      solution.row_duals.assign(model.dualRowSolution(),
                                model.dualRowSolution() + m);
      solution.objective = lp.objective_value(solution.x);
      solution.message   = "Clp: optimal";
      if (!interior.x.empty())
        solution.message += " (the barrier's point failed the check, " +
                            interior.check.describe() + ": " + interior.then +
                            ")";
      solution.check   = check_pair(lp, solution.x, solution.row_duals);
      solution.checked = true;
      if (!solution.check.within(check_tolerance()))
        resolve_unscaled(lp, model, check_tolerance(), solution);
      if (basis_out)
        {
          basis_out->n_columns = n;
          basis_out->n_rows    = m;
          basis_out->status.assign(model.statusArray(),
                                   model.statusArray() + n + m);
        }
    }

    Solution
    Clp::solve(const LinearProgram &lp,
               const ClpBasis      *basis_in,
               ClpBasis            *basis_out) const
    {
      const auto start_time = std::chrono::steady_clock::now();
      Solution   solution;

      Attempt attempt;
      attempt.model  = create(lp);
      attempt.method = algorithm;
      if (basis_in)
        solve_from_basis(lp, *basis_in, attempt, solution.iterations);
      // `Crossover = never': not for a caller that keeps the basis (warm
      // starts: minimum thickness)
      const bool use_interior = no_crossover && !basis_out;
      solve_cold(lp, use_interior, attempt, solution.iterations);
      confirm(lp, attempt, solution.iterations);

      const std::unique_ptr<ClpSimplex> &model = attempt.model;
      const bool dual_infeasible               = attempt.dual_infeasible;
      Verdict   &verdict                       = attempt.verdict;
      Interior  &interior                      = attempt.interior;
      if (verdict.outcome == Verdict::Outcome::infeasible)
        {
          solution.status     = Status::infeasible;
          solution.message    = "Clp: infeasible (" + verdict.description + ")";
          solution.row_misfit = std::move(verdict.row_misfit);
        }
      else if (verdict.outcome == Verdict::Outcome::unbounded)
        {
          solution.status  = Status::unbounded;
          solution.message = "Clp: unbounded (" + verdict.description + ")";
          solution.ray     = std::move(verdict.ray);
        }
      else if (attempt.kept_interior)
        {
          const PairCheck &c = interior.check;
          solution.status    = Status::optimal;
          solution.x         = std::move(interior.x);
          solution.row_duals = std::move(interior.y);
          solution.objective = c.primal_objective;
          solution.message   = "Clp: optimal (barrier, no crossover: " +
                             interior.check.describe() + ")";
          solution.check   = c;
          solution.checked = true;
        }
      else if (!dual_infeasible && model->isProvenOptimal())
        read_optimum(lp, *model, interior, basis_out, solution);
      else if (!dual_infeasible && model->isProvenPrimalInfeasible())
        {
          solution.status  = Status::infeasible;
          solution.message = "Clp: primal infeasible";
        }
      else if (dual_infeasible || model->isProvenDualInfeasible())
        {
          Verdict phase_1 = verdict_when_dual_infeasible(
            lp, [&]() { return create(lp); }, time_limit());
          solution.iterations += phase_1.iterations;
          report_dual_infeasible(std::move(phase_1), solution);
        }
      else if (model->hitMaximumIterations())
        solution.message = "Clp: stopped on the time or iteration limit";
      else
        solution.message =
          "Clp: failed with status " + std::to_string(model->status()) +
          ", secondary status " + std::to_string(model->secondaryStatus());

      // auxiliary LPs that ran without deciding (a false alarm, or values
      // between the thresholds) are said, since they cost time
      if (!verdict.description.empty() &&
          (verdict.outcome == Verdict::Outcome::bounded ||
           verdict.outcome == Verdict::Outcome::undecided))
        solution.message += " (auxiliary LPs: " + verdict.description + ")";
      solution.seconds = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start_time)
                           .count();
      return solution;
    }
  } // namespace lp
} // namespace masonry

MASONRY_REGISTER_LP_SOLVER(masonry::lp::Clp,
                           "clp",
                           "COIN-OR Clp: dual or primal simplex, barrier "
                           "with crossover, or automatic (the explicit dual "
                           "problem by barrier or primal simplex).")
