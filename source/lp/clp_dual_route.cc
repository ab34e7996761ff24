/**
 * @file
 * The `clp` back-end's route through Clp's explicit dual LP
 * (`Algorithm = automatic`): the dual LP solved by the barrier or the
 * primal simplex, its verdicts, and its vertex restored into the LP
 * (clp.h).
 */
#include <masonry/lp/solution_check.h>

#include <coin/ClpSimplex.hpp>
#include <coin/ClpSimplexOther.hpp>

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "clp.h"
#include "clp_barrier.h"
#include "clp_dual.h"
#include "clp_verdict.h"

namespace masonry
{
  namespace lp
  {
    namespace
    {
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
  } // namespace lp
} // namespace masonry
