/**
 * @file
 * Clp's barrier with crossover, with a Cholesky factorisation that is
 * ordered once per sparsity pattern (see clp_barrier.h).
 */
#include "clp_barrier.h"
#include <coin/ClpEventHandler.hpp>
#include <coin/ClpInterior.hpp>
#include <coin/ClpSimplex.hpp>
#include <coin/CoinSort.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "clp_cholesky.h"

namespace masonry
{
  namespace lp
  {
    namespace
    {
      /**
       * Clp's event handler called after every barrier iteration: asks
       * the rule of barrier_with_crossover()'s @p stop whether to stop
       * (Clp copies the handler, so the flag is shared by pointer).
       */
      class StopRule : public ClpEventHandler
      {
      public:
        StopRule(const ClpInterior                              *barrier,
                 const std::function<bool(const ClpInterior &)> *rule,
                 bool                                           *stopped)
          : barrier(barrier)
          , rule(rule)
          , stopped(stopped)
        {}

        int
        event(Event which) override
        {
          if (which == endOfIteration && (*rule)(*barrier))
            {
              *stopped = true;
              return 0; // stop
            }
          return -1;
        }

        ClpEventHandler *
        clone() const override
        {
          return new StopRule(*this);
        }

      private:
        const ClpInterior                              *barrier;
        const std::function<bool(const ClpInterior &)> *rule;
        bool                                           *stopped;
      };

      /**
       * The first step of Clp's crossover: a basis from the barrier's
       * point in @p model. Rows are superbasic; columns at a bound (within
       * @p primalTolerance) sit on it, the others are superbasic, and the
       * farthest from their bounds (those with a dual value below 1e-5
       * counted 100 times farther), at most one per row, become basic.
       */
      void
      crash_basis(ClpSimplex &model, const double primalTolerance)
      {
        const int numberRows    = model.numberRows();
        const int numberColumns = model.numberColumns();

        std::vector<double> dsort(numberColumns);
        std::vector<int>    sort(numberColumns);
        int                 n           = 0;
        const double       *columnLower = model.columnLower();
        const double       *columnUpper = model.columnUpper();
        double             *primal      = model.primalColumnSolution();
        const double       *dual        = model.dualColumnSolution();
        const double        tolerance   = 10.0 * primalTolerance;
        for (int i = 0; i < numberRows; i++)
          model.setRowStatus(i, ClpSimplex::superBasic);
        for (int i = 0; i < numberColumns; i++)
          {
            double distance =
              std::min(columnUpper[i] - primal[i], primal[i] - columnLower[i]);
            if (distance > tolerance)
              {
                if (std::fabs(dual[i]) < 1.0e-5)
                  distance *= 100.0;
                dsort[n]  = -distance;
                sort[n++] = i;
                model.setStatus(i, ClpSimplex::superBasic);
              }
            else if (distance > primalTolerance)
              model.setStatus(i, ClpSimplex::superBasic);
            else if (primal[i] <= columnLower[i] + primalTolerance)
              {
                model.setStatus(i, ClpSimplex::atLowerBound);
                primal[i] = columnLower[i];
              }
            else
              {
                model.setStatus(i, ClpSimplex::atUpperBound);
                primal[i] = columnUpper[i];
              }
          }
        CoinSort_2(dsort.data(), dsort.data() + n, sort.data());
        n = std::min(numberRows, n);
        for (int i = 0; i < n; i++)
          model.setStatus(sort[i], ClpSimplex::basic);
      }

      /**
       * Clp's primal values pass from the barrier's point (after
       * crash_basis()), then the reduced costs cleaned and the variables
       * flagged as Clp does it. Afterwards @p rowPrimal and @p columnPrimal
       * hold the pass's primal values and @p model the barrier's dual
       * values (@p rowDual, @p columnDual). @p dualTolerance and
       * @p direction are the model's, read before the crossover. Returns
       * whether the pass ended optimal.
       */
      bool
      primal_values_pass(ClpSimplex                &model,
                         const double               dualTolerance,
                         const double               direction,
                         std::vector<double>       &rowPrimal,
                         const std::vector<double> &rowDual,
                         std::vector<double>       &columnPrimal,
                         const std::vector<double> &columnDual)
      {
        const int numberRows    = model.numberRows();
        const int numberColumns = model.numberColumns();

        // just primal values pass
        const double saveScale = model.objectiveScale();
        model.setObjectiveScale(1.0e-3);
        model.primal(2);
        model.setObjectiveScale(saveScale);
        // (nothing below changes the basis or the primal values)
        const bool optimal = model.isProvenOptimal();
        // save primal solution and copy back dual
        std::copy(model.primalRowSolution(),
                  model.primalRowSolution() + numberRows,
                  rowPrimal.begin());
        std::copy(rowDual.begin(), rowDual.end(), model.dualRowSolution());
        std::copy(model.primalColumnSolution(),
                  model.primalColumnSolution() + numberColumns,
                  columnPrimal.begin());
        std::copy(columnDual.begin(),
                  columnDual.end(),
                  model.dualColumnSolution());
        // clean up reduced costs and flag variables
        double             *dj    = model.dualColumnSolution();
        double             *cost  = model.objective();
        double             *lower = model.columnLower();
        double             *upper = model.columnUpper();
        std::vector<double> saveCost(cost, cost + numberColumns);
        std::vector<double> saveL(lower, lower + numberColumns);
        std::vector<double> saveU(upper, upper + numberColumns);
        const double        tolerance = 10.0 * dualTolerance;
        for (int i = 0; i < numberColumns; i++)
          {
            if (model.getStatus(i) == ClpSimplex::basic)
              dj[i] = 0.0;
            else if (model.getStatus(i) == ClpSimplex::atLowerBound)
              {
                if (direction * dj[i] < tolerance)
                  {
                    if (direction * dj[i] < 0.0)
                      {
                        cost[i] -= dj[i];
                        dj[i] = 0.0;
                      }
                  }
                else
                  upper[i] = lower[i];
              }
            else if (model.getStatus(i) == ClpSimplex::atUpperBound)
              {
                if (direction * dj[i] > tolerance)
                  {
                    if (direction * dj[i] > 0.0)
                      {
                        cost[i] -= dj[i];
                        dj[i] = 0.0;
                      }
                  }
                else
                  lower[i] = upper[i];
              }
          }
        // Clp runs a dual values pass here when the barrier's
        // complementarity gap is exactly 0. Not here: on the
        // Bothwell settlement with Mohr-Coulomb joints at 24 x 32
        // blocks per half (gap 0) it had not ended after 13 CPU
        // minutes, while the primal passes below finish the LP in 46 s;
        // at 6 x 8 (gap 0 too) it made one pivot. The primal values
        // pass and the primal simplex alone reach the optimum (every
        // rigid example within 2e-12 of before,
        // contrib/benchmarks/lp_solvers/results-2026-11-27.md)
        std::copy(saveCost.begin(), saveCost.end(), cost);
        std::copy(saveL.begin(), saveL.end(), lower);
        std::copy(saveU.begin(), saveU.end(), upper);
        return optimal;
      }

      /**
       * Clp's crossover (ClpSimplex::initialSolve() after its barrier)
       * from the barrier's point in @p model to a vertex: a basis from the
       * point, a primal values pass when the barrier's complementarity
       * gap @p gap is small, and the primal simplex. @p rowPrimal,
       * @p rowDual, @p columnPrimal and @p columnDual are the barrier's
       * values; @p restore_fixed_bounds puts back the bounds that
       * fixFixed() moved, if it did.
       */
      void
      crossover(ClpSimplex                  &model,
                const double                 gap,
                std::vector<double>         &rowPrimal,
                const std::vector<double>   &rowDual,
                std::vector<double>         &columnPrimal,
                const std::vector<double>   &columnDual,
                const std::function<void()> &restore_fixed_bounds)
      {
        const int numberRows    = model.numberRows();
        const int numberColumns = model.numberColumns();

        bool optimal_values_pass = false;
        // crossover
        model.createStatus();
        model.setPerturbation(100);
        if (model.factorizationFrequency() == 200)
          model.defaultFactorizationFrequency();
        const double primalTolerance = model.primalTolerance();
        const double dualTolerance   = model.dualTolerance();
        const double direction       = model.optimizationDirection();
        // throw some into basis
        {
          crash_basis(model, primalTolerance);
          if (gap < 1.0e-3 * static_cast<double>(numberRows + numberColumns))
            {
              restore_fixed_bounds();
              optimal_values_pass = primal_values_pass(model,
                                                       dualTolerance,
                                                       direction,
                                                       rowPrimal,
                                                       rowDual,
                                                       columnPrimal,
                                                       columnDual);
            }
          // and finish
          std::copy(rowPrimal.begin(),
                    rowPrimal.end(),
                    model.primalRowSolution());
          std::copy(columnPrimal.begin(),
                    columnPrimal.end(),
                    model.primalColumnSolution());
        }
        // Clp repeats the values pass here; after an optimal one it
        // starts from that pass's optimal basis and values and does
        // nothing but refactorise (0 pivots in all 158 LPs of the
        // Bothwell genetic-algorithm benchmark), about 2 % of an LP's
        // time (contrib/benchmarks/lp_solvers/results-2026-11-25d.md)
        if (!optimal_values_pass)
          {
            const double saveScale = model.objectiveScale();
            model.setObjectiveScale(1.0e-3);
            model.primal(2);
            model.setObjectiveScale(saveScale);
          }
        model.primal(1);
      }
    } // namespace

    bool
    barrier_with_crossover(
      ClpSimplex                                     &model,
      const std::function<bool(const ClpSimplex &)>  &accept,
      const bool                                      cross_if_rejected,
      const double                                    accept_tolerance,
      const std::function<bool(const ClpInterior &)> &stop,
      bool                                           *stopped)
    {
      // ClpSimplex::initialSolve(), ClpSolve::useBarrier, presolve off,
      // special options 0 (ClpSolve.cpp of Clp 1.17), with ReusedCholesky
      const int   numberRows       = model.numberRows();
      const int   numberColumns    = model.numberColumns();
      const int   savePerturbation = model.perturbation();
      const int   saveScaling      = model.scalingFlag();
      ClpInterior barrier;
      barrier.borrowModel(model);
      bool was_stopped = false;
      if (stop)
        {
          const StopRule rule(&barrier, &stop, &was_stopped);
          barrier.passInEventHandler(&rule);
        }
      barrier.eventHandler()->setSimplex(nullptr);
      if (numberRows + numberColumns > 10000)
        barrier.setMaximumBarrierIterations(1000);
      // dense columns only for a point that may be kept (see
      // ReusedCholesky)
      ReusedCholesky *cholesky = new ReusedCholesky(accept ? 100 : -1);
      cholesky->setIntegerParameter(0, 0);
      barrier.setCholesky(cholesky);
      barrier.scaling(0);
      const double saveDualTolerance = model.dualTolerance();
      if (accept)
        // Clp's barrier stops when its primal and dual objectives differ
        // by less than the dual tolerance (absolute: 1e-7, 1e-6 of a
        // mechanism LP's scaled optimum); for an interior point that is
        // kept, by less than this
        barrier.setDualTolerance(accept_tolerance);
      barrier.primalDual();
      barrier.setDualTolerance(saveDualTolerance);
      if (stopped)
        *stopped = was_stopped;
      const int    maxIts        = barrier.maximumBarrierIterations();
      const int    barrierStatus = barrier.status();
      const double gap           = barrier.complementarityGap();
      const int    numberFixed   = barrier.numberFixed();
      if (accept)
        {
          // the barrier's point, before fixFixed() below moves the values
          // within the primal tolerance of a bound onto it (the arrays are
          // the model's, borrowed)
          const bool kept  = barrierStatus == 0 && accept(model);
          const int  first = barrier.numberIterations();
          barrier.returnModel(model);
          model.setPerturbation(savePerturbation);
          model.scaling(saveScaling);
          if (kept)
            {
              model.setNumberIterations(first);
              return true;
            }
          if (!cross_if_rejected || was_stopped)
            {
              model.setNumberIterations(first);
              return false;
            }
          // else the barrier with crossover as without @p accept (from
          // the barrier's point of the tighter tolerance, the crossover
          // ended at a vertex 2.8e-7 above the optimum on the barrel
          // corner settlement)
          barrier_with_crossover(model);
          model.setNumberIterations(model.numberIterations() + first);
          return false;
        }
      // the bounds of columns then rows, saved and put back
      std::vector<double> saveLower, saveUpper;
      const auto save = [&](const double *columns, const double *rows) {
        std::vector<double> v(columns, columns + numberColumns);
        v.insert(v.end(), rows, rows + numberRows);
        return v;
      };
      const auto put =
        [&](const std::vector<double> &v, double *columns, double *rows) {
          std::copy(v.begin(), v.begin() + numberColumns, columns);
          std::copy(v.begin() + numberColumns, v.end(), rows);
        };
      if (numberFixed)
        {
          saveLower = save(barrier.columnLower(), barrier.rowLower());
          saveUpper = save(barrier.columnUpper(), barrier.rowUpper());
          barrier.fixFixed(false);
        }
      const auto restore_bounds = [&]() {
        put(saveLower, model.columnLower(), model.rowLower());
        put(saveUpper, model.columnUpper(), model.rowUpper());
        saveLower.clear();
        saveUpper.clear();
      };
      const int saveNumberIterations = barrier.numberIterations();
      barrier.returnModel(model);
      std::vector<double>       rowPrimal(model.primalRowSolution(),
                                    model.primalRowSolution() + numberRows);
      const std::vector<double> rowDual(model.dualRowSolution(),
                                        model.dualRowSolution() + numberRows);
      std::vector<double>       columnPrimal(model.primalColumnSolution(),
                                       model.primalColumnSolution() +
                                         numberColumns);
      const std::vector<double> columnDual(model.dualColumnSolution(),
                                           model.dualColumnSolution() +
                                             numberColumns);
      if (maxIts && barrierStatus < 4 && !was_stopped)
        {
          crossover(
            model, gap, rowPrimal, rowDual, columnPrimal, columnDual, [&]() {
              if (!saveUpper.empty())
                restore_bounds();
            });
        }
      else if (barrierStatus == 4)
        {
          // memory problems
          model.setPerturbation(savePerturbation);
          model.createStatus();
          model.dual();
        }
      model.setNumberIterations(model.numberIterations() +
                                saveNumberIterations);
      if (!saveUpper.empty())
        {
          restore_bounds();
          model.primal(1);
        }
      model.setPerturbation(savePerturbation);
      model.scaling(saveScaling);
      return false;
    }
  } // namespace lp
} // namespace masonry
