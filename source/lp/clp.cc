/**
 * @file
 * The `clp` LP solver back-end: COIN-OR Clp (ClpSimplex).
 */
#include <masonry/core/parameters.h>
#include <masonry/lp/interface.h>

#include <coin/ClpSimplex.hpp>
#include <coin/ClpSimplexOther.hpp>
#include <coin/ClpSolve.hpp>
#include <coin/CoinPackedMatrix.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <unordered_map>

#include "clp_barrier.h"
#include "clp_dual.h"
#include "clp_parameters.h"
#include "clp_verdict.h"

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

      /** A barrier's interior point kept without crossover. */
      struct Interior
      {
        std::vector<double> x, y;
        PairCheck           check;
        /** What ran when the point failed the check. */
        std::string then = "crossover";
      };

      /** Clp's basis (status of every column, then of every row). */
      struct ClpBasis : public WarmStartData
      {
        unsigned int               n_columns = 0, n_rows = 0;
        std::vector<unsigned char> status;
        /** WarmStart::row_keys of the LP it comes from (may be empty). */
        std::vector<long long> row_keys;
      };

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

      /**
       * `automatic`: the optimal vertex of the dual LP @p solved (@p dual,
       * or @p reduced's copy of it without singleton rows), found by
       * @p method, restored into @p model as a basis of the LP and cleaned
       * up to a vertex of the LP. Adds the pivots to @p iterations.
       * Returns whether @p model ended proven optimal.
       */
      bool
      vertex_from_dual(ClpSimplex          &model,
                       ClpSimplex          &dual,
                       const SingletonRows &reduced,
                       ClpSimplex          &solved,
                       const std::string   &method,
                       unsigned int        &iterations)
      {
        // after the barrier, a vertex optimal only for Clp's scaled dual
        // LP (secondary status) maps back to a basis the clean-up wanders
        // from (barrel corner, 24 x 32 per half: > 200 CPU s); a primal
        // pass on the unscaled dual LP and an unscaled clean-up fix it
        // (contrib/benchmarks/lp_solvers/results-2026-11-24h.md, also why
        // not after the primal simplex)
        const bool unscaled =
          method == "barrier" && solved.secondaryStatus() != 0;
        if (unscaled)
          {
            solved.scaling(0);
            solved.primal(1);
            iterations += solved.numberIterations();
            if (!solved.isProvenOptimal())
              return false;
          }
        if (reduced.model)
          expand(reduced, dual);
        static_cast<ClpSimplexOther &>(model).restoreFromDual(&dual);
        if (unscaled)
          model.scaling(0);
        // safeguard: clean-ups took at most 323 + 179 pivots (55008 rows);
        // past the cap the LP is solved directly
        model.setMaximumIterations(1000 + model.numberRows() / 20);
        // clean up from the restored basis: a vertex of the original
        // problem. The basis is the dual LP's optimal one, so dual
        // feasible; the dual simplex repairs its primal values (off by
        // the dual LP's tolerances) in a few pivots, where the primal
        // simplex wandered to a vertex up to 2e-5 too high
        // (contrib/benchmarks/lp_solvers/results-2026-11-24g.md). With
        // dual infeasibilities the primal simplex starts feasible.
        const bool dual_feasible = model.numberDualInfeasibilities() == 0;
        if (dual_feasible)
          model.dual(0);
        else
          model.primal(0);
        // if that vertex is optimal only for Clp's scaled problem
        // (secondary status), one more pass of the primal simplex on the
        // unscaled one (the barrel corner example came out 2.8e-8 high
        // without it). Tolerances of 1e-9 cost the corner example at
        // 12 x 16 blocks per half 130000 iterations; the dual simplex
        // here (on unscaled primal infeasibilities only) fell back to
        // the primal one on the Bothwell vault at 24 x 32 blocks per half
        // and had not finished after 5 CPU minutes (1.3 s by the primal).
        if (model.isProvenOptimal() && model.secondaryStatus() != 0)
          {
            iterations += model.numberIterations();
            model.scaling(0);
            model.primal(1);
          }
        iterations += model.numberIterations();
        model.setMaximumIterations(COIN_INT_MAX);
        return model.isProvenOptimal();
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

      /**
       * Solve @p lp from the basis in @p warm (simplex from that basis, no
       * presolve: the dual simplex unless `Algorithm = primal simplex'),
       * and store the optimal basis there. Without a basis of the same
       * shape, as solve().
       */
      Solution
      solve_warm(const LinearProgram &lp, WarmStart &warm) const override;

    private:
      /** Value of `Algorithm`. */
      std::string algorithm = "automatic";
      /** Value of `Presolve`. */
      bool presolve = true;
      /** Whether `Crossover = never`. */
      bool no_crossover = false;
      /** Value of `Interior point tolerance`. */
      double interior_tolerance = 1e-6;

      /**
       * solve() with an optional starting basis; on an optimal solve, the
       * final basis goes to @p basis_out.
       */
      Solution
      solve(const LinearProgram &lp,
            const ClpBasis      *basis_in,
            ClpBasis            *basis_out) const;

      /** A silent Clp model holding @p lp, with the time limit set. */
      std::unique_ptr<ClpSimplex>
      create(const LinearProgram &lp) const;

      /** Run @p method ("dual simplex", ...) on @p model. */
      void
      run(ClpSimplex        &model,
          const std::string &method,
          const bool         use_presolve) const;

      /** How solve_through_dual() ended. */
      enum class DualRoute
      {
        /** @p model holds a proven optimal vertex. */
        optimal,
        /** The barrier's interior point is the result (`Crossover`). */
        interior,
        /**
         * The simplex proved the dual LP infeasible: the LP itself has
         * no dual feasible point (it is unbounded or infeasible).
         */
        dual_infeasible,
        /** The auxiliary LPs of decide_verdict() proved the LP infeasible
         * or unbounded (see the Verdict). */
        decided,
        /** Anything else: solve the LP directly. */
        failed
      };

      /** `automatic`: Clp's explicit dual of @p model (the static problem)
       *  solved by @p method, its vertex restored into @p model, cleaned up.
       */
      DualRoute
      solve_through_dual(ClpSimplex          &model,
                         const std::string   &method,
                         unsigned int        &iterations,
                         const LinearProgram &lp,
                         Interior            *interior,
                         Verdict             &verdict) const;

      /**
       * solve_through_dual() with the barrier: the barrier on the dual LP
       * @p solved, stopped by @p diverging; with @p interior, its point is
       * the result if @p keep accepts it (which sets @p checked). A point
       * stopped or @p far_off the LP lets @p decide (the auxiliary LPs)
       * judge the LP. Adds the barrier's iterations to @p iterations.
       * Returns how the route ended, or nothing when it goes on to the
       * vertex the crossover left in @p solved.
       */
      std::optional<DualRoute>
      barrier_on_dual(ClpSimplex                                     &solved,
                      Interior                                       *interior,
                      const std::function<bool(const ClpSimplex &)>  &keep,
                      const std::function<bool(const ClpInterior &)> &diverging,
                      const std::function<bool()>                    &far_off,
                      const std::function<bool(bool)>                &decide,
                      bool                                           &checked,
                      unsigned int &iterations) const;

      /**
       * solve_through_dual() with a simplex @p method on the dual LP
       * @p solved; the primal simplex stops after @p simplex_cap pivots,
       * when @p decide (the auxiliary LPs) judges the LP, or else goes on.
       * Adds the pivots to @p iterations. Returns DualRoute::decided if the
       * auxiliary LPs decided, else nothing.
       */
      std::optional<DualRoute>
      simplex_on_dual(ClpSimplex                      &solved,
                      const std::string               &method,
                      const int                        simplex_cap,
                      const std::function<bool(bool)> &decide,
                      unsigned int                    &iterations) const;

      /**
       * solve_through_dual() after @p method ran on the dual LP @p solved:
       * how the route ends if the dual LP has no proven optimum (the
       * barrier's infeasibility confirmed by the primal simplex, the
       * primal simplex's verdicts, @p decide for an unbounded dual LP).
       * Adds the pivots to @p iterations. Nothing if @p solved is optimal.
       */
      static std::optional<DualRoute>
      dual_without_optimum(ClpSimplex                      &solved,
                           const std::string               &method,
                           const std::function<bool(bool)> &decide,
                           unsigned int                    &iterations);

      /**
       * solve() from the stored basis @p basis: a simplex without presolve
       * on @p attempt's model; the attempt is done on a verdict, else its
       * model is fresh again. Adds the pivots to @p iterations.
       */
      void
      solve_from_basis(const LinearProgram &lp,
                       const ClpBasis      &basis,
                       Attempt             &attempt,
                       unsigned int        &iterations) const;

      /**
       * solve() without a basis (or after a warm start that did not
       * decide): the barrier kept without crossover (@p use_interior with
       * `Algorithm = barrier`), the route through the dual (`automatic`),
       * then `Algorithm` on the LP itself unless @p attempt is done. Adds
       * the iterations to @p iterations.
       */
      void
      solve_cold(const LinearProgram &lp,
                 const bool           use_interior,
                 Attempt             &attempt,
                 unsigned int        &iterations) const;

      /**
       * The verdict of @p attempt's solve of the LP itself confirmed on the
       * original problem where it is not reliable: after presolve, an
       * infeasible verdict not from the primal simplex, a barrier's
       * optimum whose duals are no certificate. Adds the pivots to
       * @p iterations.
       */
      void
      confirm(const LinearProgram &lp,
              Attempt             &attempt,
              unsigned int        &iterations) const;

      /**
       * The optimal vertex in @p model into @p solution, checked (and
       * solved again unscaled if it fails the check); the message says
       * why @p interior was not kept, if it was checked. The basis goes to
       * @p basis_out if given.
       */
      void
      read_optimum(const LinearProgram &lp,
                   ClpSimplex          &model,
                   const Interior      &interior,
                   ClpBasis            *basis_out,
                   Solution            &solution) const;
    };

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

    Clp::DualRoute
    Clp::solve_through_dual(ClpSimplex          &model,
                            const std::string   &method,
                            unsigned int        &iterations,
                            const LinearProgram &lp,
                            Interior            *interior,
                            Verdict             &verdict) const
    {
      try
        {
          std::unique_ptr<ClpSimplex> dual = dual_of(model);
          if (!dual)
            return DualRoute::failed;
          dual->setLogLevel(0);
          dual->messageHandler()->setLogLevel(0);
          if (time_limit() > 0)
            dual->setMaximumSeconds(time_limit());
          // without presolve: with it, the barrier's vertex of the dual
          // maps back to a basis that is optimal only to the tolerances
          // (the limit load of the cantilever test came out 1.4e-8 low),
          // and it is slower from 6 x 8 Bothwell blocks up
          // the barrier on the dual without its singleton rows (the
          // tension cut-off and compression cap as bounds of the normal
          // forces): the same LP, a fifth fewer rows for Mohr-Coulomb
          // joints, about 20 % less time
          SingletonRows reduced;
          if (method == "barrier")
            reduced = without_singleton_rows(*dual);
          ClpSimplex &solved = reduced.model ? *reduced.model : *dual;
          // the primal simplex on the dual (no tension no sliding) without
          // Clp's scaling: the same optima, cheaper iterations
          // (contrib/benchmarks/lp_solvers/results-2026-11-25c.md)
          if (method == "primal simplex")
            solved.scaling(0);
          // an LP without an optimum: the dual LP's barrier diverges (its
          // iterates stopped by divergence_rule()), or ends at a point far
          // off the LP. Then two bounded auxiliary LPs decide whether the
          // LP is infeasible or unbounded, in about the time of an optimal
          // solve (the crossover or the simplex from such a point took
          // minutes: 53 CPU s on a thin barrel of 80 blocks, whose optimal
          // twin takes 0.08 s); if they find an optimum, the route goes on
          // as before
          const auto diverging = divergence_rule(work_scale(lp));
          const auto decide    = [&](const bool known_dual_infeasible) {
            verdict = decide_verdict(lp,
                                     model,
                                     lp.known_feasible || zero_is_feasible(lp),
                                     known_dual_infeasible,
                                     time_limit());
            iterations += verdict.iterations;
            return verdict.outcome == Verdict::Outcome::infeasible ||
                   verdict.outcome == Verdict::Outcome::unbounded;
          };
          // the primal simplex on the dual LP ends an LP with an optimum
          // within 0.99 to 1.18 times as many pivots as the dual LP has rows
          // (every no-tension LP of contrib/benchmarks/lp_verdicts below
          // 2000 rows), while proving it infeasible took 2.5 times as many,
          // each 7 times dearer (phase 1): past 1.25 times plus 20 the
          // auxiliary LPs decide (if they find an optimum, the simplex goes
          // on)
          const int simplex_cap = dual->numberRows() * 5 / 4 + 20;
          // a rejected interior point far off the LP (not a gap or a
          // residual near the tolerance)
          bool       checked = false;
          const auto far_off = [&]() {
            return checked && std::max(interior->check.primal_residual,
                                       interior->check.dual_residual) > 1e-4;
          };
          // `Crossover = never': the interior point if it checks out on
          // the LP itself
          const auto keep = [&](const ClpSimplex &point) {
            checked = true;
            interior_from_dual(model, point, reduced, interior->x, interior->y);
            interior->check = check_pair(lp, interior->x, interior->y);
            if (method == "primal simplex")
              interior->check.gap_floor =
                std::max(interior->check.gap_floor,
                         1e-2 * interior->check.work_scale);
            return interior->check.within(interior_tolerance);
          };
          if (method == "primal simplex" && interior &&
              dual->numberRows() >= 2000 && !has_dense_column(*dual))
            {
              // no tension no sliding: first the barrier, no crossover, on
              // the dual with its unbounded forces boxed at the total load
              // (Bothwell 12 x 16 blocks per half: 20 iterations against
              // 1600 pivots), with Clp's stopping tolerance 1e-8 (1e-9 to
              // 1e-12 went on past the barrier's accuracy and ended up to
              // 0.02 from the optimum); smaller LPs get the vertex, which
              // costs little there, and so do limit loads (a dense column:
              // on an arch of 400 blocks the point missed the check's gap,
              // 1.1e-6, or with larger bounds by far) (contrib/benchmarks/
              // lp_solvers/results-2026-11-29b.md)
              const auto boxed = boxed_copy(*dual, 1.);
              const bool kept =
                barrier_with_crossover(*boxed, keep, false, 1e-8);
              iterations += boxed->numberIterations();
              if (kept)
                return DualRoute::interior;
              interior->then = "primal simplex";
              // the boxed dual has no optimum (the LP has no dual
              // feasible point) or ends far off the LP (its rows cannot
              // be met: the forces end on their bounds)
              if ((!checked || far_off()) && decide(false))
                return DualRoute::decided;
            }
          if (method == "barrier")
            {
              const std::optional<DualRoute> ended =
                barrier_on_dual(solved,
                                interior,
                                keep,
                                diverging,
                                far_off,
                                decide,
                                checked,
                                iterations);
              if (ended)
                return *ended;
            }
          else if (const std::optional<DualRoute> ended = simplex_on_dual(
                     solved, method, simplex_cap, decide, iterations))
            return *ended;
          if (const std::optional<DualRoute> ended =
                dual_without_optimum(solved, method, decide, iterations))
            return *ended;
          return vertex_from_dual(
                   model, *dual, reduced, solved, method, iterations) ?
                   DualRoute::optimal :
                   DualRoute::failed;
        }
      catch (const CoinError &e)
        {
          // Clp's dualisation handles only some bound patterns: solve
          // directly
          return DualRoute::failed;
        }
    }

    std::optional<Clp::DualRoute>
    Clp::barrier_on_dual(
      ClpSimplex                                     &solved,
      Interior                                       *interior,
      const std::function<bool(const ClpSimplex &)>  &keep,
      const std::function<bool(const ClpInterior &)> &diverging,
      const std::function<bool()>                    &far_off,
      const std::function<bool(bool)>                &decide,
      bool                                           &checked,
      unsigned int                                   &iterations) const
    {
      bool stopped = false;
      bool kept    = false;
      if (interior)
        kept = barrier_with_crossover(
          solved, keep, false, 1e-12, diverging, &stopped);
      else
        barrier_with_crossover(
          solved, nullptr, true, 1e-12, diverging, &stopped);
      iterations += solved.numberIterations();
      if (kept)
        return DualRoute::interior;
      if ((stopped || far_off()) && decide(false))
        return DualRoute::decided;
      if (stopped)
        {
          // a false alarm (the LP has an optimum): the barrier
          // again as without the rule, to the same point
          checked = false;
          if (interior)
            kept = barrier_with_crossover(solved, keep);
          else
            barrier_with_crossover(solved);
          iterations += solved.numberIterations();
          if (kept)
            return DualRoute::interior;
        }
      else if (interior)
        {
          // a rejected point: the barrier again and the crossover,
          // as before
          barrier_with_crossover(solved);
          iterations += solved.numberIterations();
        }
      return std::nullopt;
    }

    std::optional<Clp::DualRoute>
    Clp::simplex_on_dual(ClpSimplex                      &solved,
                         const std::string               &method,
                         const int                        simplex_cap,
                         const std::function<bool(bool)> &decide,
                         unsigned int                    &iterations) const
    {
      if (method == "primal simplex" && solved.numberRows() >= 2000)
        {
          // from a basis of the free columns (tangential contact
          // forces; Clp replaces dependent ones by slacks when it
          // factorises): half the pivots of Clp's start, whole runs
          // x0.80-0.92 CPU from 12 x 16 Bothwell blocks per half (2304
          // rows) up; no gain at 9 x 12 (1296 rows) and 6 x 8, where
          // the LPs of the examples are
          // (contrib/benchmarks/lp_solvers/results-2026-11-28b.md)
          free_columns_basic(solved);
          solved.setMaximumIterations(simplex_cap);
          solved.primal(0);
          iterations += solved.numberIterations();
        }
      else
        {
          if (method == "primal simplex")
            solved.setMaximumIterations(simplex_cap);
          run(solved, method, false);
          iterations += solved.numberIterations();
        }
      if (method == "primal simplex" && solved.hitMaximumIterations())
        {
          // past the cap the dual LP is probably infeasible: decide by
          // the auxiliary LPs, else go on from where the simplex is
          if (decide(false))
            return DualRoute::decided;
          solved.setMaximumIterations(COIN_INT_MAX);
          solved.primal(0);
          iterations += solved.numberIterations();
        }
      return std::nullopt;
    }

    std::optional<Clp::DualRoute>
    Clp::dual_without_optimum(ClpSimplex                      &solved,
                              const std::string               &method,
                              const std::function<bool(bool)> &decide,
                              unsigned int                    &iterations)
    {
      if (method == "barrier" && solved.isProvenPrimalInfeasible())
        {
          // the barrier's infeasibility verdict is not reliable: the
          // primal simplex from its last point confirms it (or finds
          // the optimum), cheaper than solving the LP itself again
          solved.primal(1);
          iterations += solved.numberIterations();
          if (solved.isProvenPrimalInfeasible())
            return DualRoute::dual_infeasible;
        }
      if (!solved.isProvenOptimal())
        {
          // the primal simplex's infeasibility verdict on the dual LP
          // is reliable (the barrier's is not: it may stop on
          // numerical trouble; nor is the dual simplex's, which
          // `automatic' does not use here), and saves solving the LP
          // itself again
          if (method == "primal simplex" && solved.isProvenPrimalInfeasible())
            return DualRoute::dual_infeasible;
          // an unbounded dual LP: the LP is infeasible if phase 1
          // says so (else it is solved directly)
          if (method == "primal simplex" && solved.isProvenDualInfeasible() &&
              decide(false))
            return DualRoute::decided;
          return DualRoute::failed;
        }
      return std::nullopt;
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
