/**
 * @file
 * The `clp` back-end's verdicts on an LP without an optimum (clp_verdict.h).
 */
#include "clp_verdict.h"
#include <coin/ClpInterior.hpp>
#include <coin/ClpSimplex.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "clp_barrier.h"
#include "clp_dual.h"

namespace masonry
{
  namespace lp
  {
    namespace
    {
      constexpr double big = 1e27; // Clp's SMALL_INFINITY

      /**
       * Solve @p model by the barrier without crossover and return the
       * objective of its interior point (NaN if the barrier did not end
       * optimal); its primal and dual values stay in @p model. Only
       * whether |value| exceeds @p prove or stays below @p refute matters:
       * the barrier stops as soon as its two objectives, at primal and
       * dual feasible iterates, bracket the optimum below @p refute, or
       * (with @p stop_when_proven) beyond @p prove (the value is then the
       * end of the bracket nearer to 0). Without @p stop_when_proven a
       * value beyond @p prove is solved to the end, for its point (phase
       * 1: where the rows cannot be met).
       */
      double
      barrier_value(ClpSimplex   &model,
                    unsigned int &iterations,
                    const double  prove,
                    const double  refute,
                    const bool    stop_when_proven)
      {
        double     value = std::nan("");
        const auto keep  = [&](const ClpSimplex &point) {
          const double *x = point.primalColumnSolution();
          const double *c = point.objective();
          value           = 0;
          for (int j = 0; j < point.numberColumns(); ++j)
            value += c[j] * x[j];
          return true;
        };
        const std::function<bool(const ClpInterior &)> decided =
          [&](const ClpInterior &b) {
            if (b.sumPrimalInfeasibilities() > 1e-9 ||
                b.sumDualInfeasibilities() > 1e-9)
              return false;
            const double p = b.primalObjective(), d = b.dualObjective();
            const double low = std::min(p, d), high = std::max(p, d);
            if (stop_when_proven && low > prove)
              value = low;
            else if (stop_when_proven && high < -prove)
              value = high;
            else if (low > -refute && high < refute)
              value = 0.5 * (low + high);
            else
              return false;
            return true;
          };
        bool stopped = false;
        barrier_with_crossover(model, keep, false, 1e-9, decided, &stopped);
        iterations += model.numberIterations();
        return value;
      }

      /** Largest violation of a row bound of @p lp by @p x, per row. */
      std::vector<double>
      row_violations(const LinearProgram &lp, const std::vector<double> &x)
      {
        const auto          activity = lp.row_activities(x);
        std::vector<double> v(lp.n_rows(), 0.);
        for (unsigned int i = 0; i < lp.n_rows(); ++i)
          v[i] = std::max({0.,
                           lp.row_lower()[i] - activity[i],
                           activity[i] - lp.row_upper()[i]});
        return v;
      }

      std::string
      number(const double x)
      {
        char text[32];
        std::snprintf(text, sizeof(text), "%.3g", x);
        return text;
      }

      /**
       * Phase 1 of decide_verdict(): D (@p dual, Clp's explicit dual of
       * @p lp, which @p model holds) with its right-hand side set to 0 and
       * its columns boxed, solved by the barrier. Its value, judged on
       * @p scale (the LP's largest finite bound), sets Verdict::misfit of
       * @p v, and the outcome, row misfits and description when it proves
       * the LP infeasible or is undecided. Returns whether that ends the
       * verdict.
       */
      bool
      decide_by_phase_1(const LinearProgram &lp,
                        ClpSimplex          &model,
                        const ClpSimplex    &dual,
                        const double         scale,
                        Verdict             &v)
      {
        SingletonRows none;
        // phase 1: the rows of D (the LP's columns) homogeneous, its
        // columns (the multipliers of the LP's rows) boxed
        ClpSimplex farkas(dual);
        for (int i = 0; i < farkas.numberRows(); ++i)
          {
            if (farkas.rowLower()[i] > -big)
              farkas.setRowLower(i, 0.);
            if (farkas.rowUpper()[i] < big)
              farkas.setRowUpper(i, 0.);
          }
        for (int j = 0; j < farkas.numberColumns(); ++j)
          {
            if (farkas.columnLower()[j] < -big)
              farkas.setColumnLower(j, -1.);
            if (farkas.columnUpper()[j] > big)
              farkas.setColumnUpper(j, 1.);
          }
        const double value = barrier_value(
          farkas, v.iterations, 1e-5 * scale, 1e-6 * scale, false);
        if (std::isnan(value))
          {
            v.description = "phase 1 did not converge";
            return true;
          }
        v.misfit = std::abs(value);
        if (v.misfit > 1e-5 * scale)
          {
            v.outcome = Verdict::Outcome::infeasible;
            // the point of least total violation: the duals of D's rows
            std::vector<double> x, y;
            interior_from_dual(model, farkas, none, x, y);
            v.row_misfit  = row_violations(lp, x);
            v.description = "phase 1: the rows cannot be met, least sum of "
                            "violations " +
                            number(v.misfit);
            return true;
          }
        if (v.misfit > 1e-6 * scale)
          {
            v.description = "phase 1 undecided (least sum of violations " +
                            number(v.misfit) + ")";
            return true;
          }
        return false;
      }

      /**
       * Whether the ray LP of decide_verdict() boxes every column of
       * @p lp: when @p dual (Clp's explicit dual of @p lp) does not have a
       * row per column, or a column bounded on one side lets the
       * objective grow along it. Otherwise only the free columns are boxed.
       */
      bool
      boxes_every_column(const LinearProgram &lp, const ClpSimplex &dual)
      {
        const double sense   = lp.maximize ? 1. : -1.;
        bool         box_all = dual.numberRows() != int(lp.n_columns());
        for (unsigned int j = 0; j < lp.n_columns() && !box_all; ++j)
          {
            const bool   lower = std::isfinite(lp.column_lower()[j]);
            const bool   upper = std::isfinite(lp.column_upper()[j]);
            const double c     = sense * lp.objective()[j];
            box_all = (lower && !upper && c > 0) || (!lower && upper && c < 0);
          }
        return box_all;
      }

      /**
       * The ray LP's dual from @p ray, a copy of D (Clp's explicit dual of
       * @p lp): no cost but a slack of cost 1 on each bounded side of a row
       * (of every row if @p box_all, else of the rows of the LP's free
       * columns), minimised.
       */
      void
      add_ray_slacks(ClpSimplex          &ray,
                     const LinearProgram &lp,
                     const bool           box_all)
      {
        std::vector<int>    start{0}, rows;
        std::vector<double> values, lower, upper, cost;
        for (int i = 0; i < ray.numberRows(); ++i)
          for (const double sign : {1., -1.})
            if ((sign > 0 ? ray.rowLower()[i] > -big :
                            ray.rowUpper()[i] < big) &&
                (box_all || (!std::isfinite(lp.column_lower()[i]) &&
                             !std::isfinite(lp.column_upper()[i]))))
              {
                rows.push_back(i);
                values.push_back(sign);
                start.push_back(rows.size());
                lower.push_back(0.);
                upper.push_back(COIN_DBL_MAX);
                cost.push_back(1.);
              }
        for (int j = 0; j < ray.numberColumns(); ++j)
          ray.setObjectiveCoefficient(j, 0.);
        ray.addColumns(lower.size(),
                       lower.data(),
                       upper.data(),
                       cost.data(),
                       start.data(),
                       rows.data(),
                       values.data());
        ray.setOptimizationDirection(1.);
      }
    } // namespace

    Verdict
    decide_verdict(const LinearProgram &lp,
                   ClpSimplex          &model,
                   const bool           known_feasible,
                   const bool           known_dual_infeasible,
                   const double         time_limit)
    {
      Verdict                     v;
      std::unique_ptr<ClpSimplex> dual = dual_of(model);
      if (!dual)
        {
          v.description = "no explicit dual";
          return v;
        }
      dual->setLogLevel(0);
      if (time_limit > 0)
        dual->setMaximumSeconds(time_limit);
      // the scales the values are judged on
      double largest_bound = 0, largest_cost = 0;
      for (const auto *b : {&lp.row_lower(),
                            &lp.row_upper(),
                            &lp.column_lower(),
                            &lp.column_upper()})
        for (const double x : *b)
          if (std::isfinite(x))
            largest_bound = std::max(largest_bound, std::abs(x));
      for (const double c : lp.objective())
        largest_cost = std::max(largest_cost, std::abs(c));
      const double phase_1_scale = std::max(largest_bound, 1e-300);
      const double ray_scale     = std::max(largest_cost, 1e-300);

      if (!known_feasible &&
          decide_by_phase_1(lp, model, *dual, phase_1_scale, v))
        return v;

      if (known_dual_infeasible)
        {
          v.outcome = Verdict::Outcome::unbounded;
          v.description =
            "feasible (phase 1: " + number(std::max(v.misfit, 0.)) +
            "), no dual feasible point";
          return v;
        }
      // the ray LP's dual: D with slacks of cost 1 on its rows, no other
      // cost, minimised. D's row i is the LP's column i; a column bounded
      // on one side along which the objective cannot grow (a plastic
      // multiplier costs dissipation) needs no box in the ray LP, so its
      // row gets no slack and a row with a single entry stays one, which
      // then becomes a bound (SingletonRows: a fifth fewer rows with
      // Mohr-Coulomb joints)
      const bool box_all = boxes_every_column(lp, *dual);
      ClpSimplex ray(*dual);
      add_ray_slacks(ray, lp, box_all);
      SingletonRows reduced = without_singleton_rows(ray);
      ClpSimplex   &solved  = reduced.model ? *reduced.model : ray;
      const double  value   = barrier_value(
        solved, v.iterations, 1e-5 * ray_scale, 1e-6 * ray_scale, true);
      if (std::isnan(value))
        {
          v.description += "ray LP did not converge";
          return v;
        }
      v.ray_value = value;
      if (value > 1e-5 * ray_scale)
        {
          v.outcome = Verdict::Outcome::unbounded;
          std::vector<double> y;
          interior_from_dual(model, solved, reduced, v.ray, y);
          v.description = "a ray of objective " + number(value) + " with " +
                          (box_all ? "every column" : "its free columns") +
                          " within [-1, 1]";
        }
      else if (value < 1e-6 * ray_scale)
        {
          v.outcome     = Verdict::Outcome::bounded;
          v.description = "feasible and bounded (ray LP " + number(value) + ")";
        }
      else
        v.description = "ray LP undecided (" + number(value) + ")";
      if (!known_feasible)
        v.description =
          "phase 1 feasible (" + number(v.misfit) + "), " + v.description;
      return v;
    }

    std::function<bool(const ClpInterior &)>
    divergence_rule(const double scale)
    {
      auto count = std::make_shared<int>(0);
      return [scale, count](const ClpInterior &barrier) {
        const double primal    = barrier.primalObjective();
        const double dual      = barrier.dualObjective();
        const bool   diverging = dual - primal > scale || primal < -100 * scale;
        *count                 = diverging ? *count + 1 : 0;
        return *count >= 3;
      };
    }

    bool
    zero_is_feasible(const LinearProgram &lp)
    {
      for (unsigned int j = 0; j < lp.n_columns(); ++j)
        if (lp.column_lower()[j] > 0 || lp.column_upper()[j] < 0)
          return false;
      for (unsigned int i = 0; i < lp.n_rows(); ++i)
        if (lp.row_lower()[i] > 0 || lp.row_upper()[i] < 0)
          return false;
      return true;
    }

    Verdict
    verdict_when_dual_infeasible(
      const LinearProgram                                &lp,
      const std::function<std::unique_ptr<ClpSimplex>()> &create,
      const double                                        time_limit)
    {
      // dual infeasible: unbounded if primal feasible, which x = 0
      // shows when every bound allows it (a mechanism LP with fixed
      // supports), else phase 1 by the barrier (decide_verdict()) or,
      // if that is undecided, a solve with zero objective decides
      Verdict phase_1;
      if (zero_is_feasible(lp))
        phase_1.outcome = Verdict::Outcome::unbounded;
      else
        {
          auto pristine = create();
          phase_1 = decide_verdict(lp, *pristine, false, true, time_limit);
        }
      if (phase_1.outcome == Verdict::Outcome::undecided)
        {
          auto feasibility = create();
          for (unsigned int j = 0; j < lp.n_columns(); ++j)
            feasibility->setObjectiveCoefficient(j, 0.);
          feasibility->primal();
          phase_1.iterations += feasibility->numberIterations();
          if (feasibility->isProvenOptimal())
            phase_1.outcome = Verdict::Outcome::unbounded;
          else if (feasibility->isProvenPrimalInfeasible())
            phase_1.outcome = Verdict::Outcome::infeasible;
        }
      return phase_1;
    }
  } // namespace lp
} // namespace masonry
