/**
 * @file
 * Clp's barrier with crossover, with a Cholesky factorisation that is
 * ordered once per sparsity pattern (see clp_barrier.h).
 */
#include "clp_barrier.h"
#include <coin/ClpCholeskyBase.hpp>
#include <coin/ClpEventHandler.hpp>
#include <coin/ClpInterior.hpp>
#include <coin/ClpSimplex.hpp>
#include <coin/CoinHelperFunctions.hpp>
#include <coin/CoinSort.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <functional>
#include <memory>
#include <vector>

namespace masonry
{
  namespace lp
  {
    namespace
    {
      /** The sparsity pattern of a Clp matrix (rows, columns, entries). */
      std::vector<int>
      pattern_of(const ClpMatrixBase &matrix, const int n_rows)
      {
        const int           n      = matrix.getNumCols();
        const CoinBigIndex *start  = matrix.getVectorStarts();
        const int          *length = matrix.getVectorLengths();
        const int          *row    = matrix.getIndices();
        std::vector<int>    p{n_rows, n};
        for (int j = 0; j < n; ++j)
          {
            p.push_back(length[j]);
            p.insert(p.end(), row + start[j], row + start[j] + length[j]);
          }
        return p;
      }

      /**
       * ClpCholeskyBase (the factorisation Clp's barrier uses by default),
       * with two changes that leave every floating-point operation as it
       * was:
       * - order() and symbolic() copy their result from an earlier solve
       *   in this thread of a matrix with the same pattern (the AMD
       *   ordering and the symbolic factorisation depend on the pattern
       *   only);
       * - factorize() forms A D A^T by a plan made once per pattern: for
       *   each row of the factor, the products that land in its lower
       *   triangle with their place in the factor, in Clp's order (Clp
       *   computes both triangles and discards the upper one, with an
       *   indirection per entry). Each entry accumulates the same terms
       *   in the same order, so the factor is bit for bit Clp's. Without
       *   a plan (dropped rows, dense columns, KKT) it is Clp's code.
       * - With @p dense_threshold 100, columns of 100 entries or more (at
       *   most 100 of them) are Clp's dense columns: left out of A D A^T
       *   and brought in by a dense low-rank correction. A limit load's
       *   dual LP has one, the load multiplier, with an entry per block,
       *   which makes A D A^T dense (Bothwell seismic, 24 x 32 blocks per
       *   half, Mohr-Coulomb joints: 20.0 -> 4.2 CPU s). Only for a point
       *   that may be kept:
       *   Clp's crossover from such a point took 270283 pivots and 288 s
       *   at 12 x 16 against 2.9 s from the point without them
       *   (contrib/benchmarks/lp_solvers/results-2026-11-29b.md). A
       *   contact force has at most 12 entries; LPs without such columns
       *   are factorised as before.
       */
      class ReusedCholesky : public ClpCholeskyBase
      {
      public:
        explicit ReusedCholesky(const int dense_threshold)
          : ClpCholeskyBase(dense_threshold)
        {}

        ReusedCholesky(const ReusedCholesky &) = default;

        ClpCholeskyBase *
        clone() const override
        {
          return new ReusedCholesky(*this);
        }

        int
        order(ClpInterior *model) override;

        int
        symbolic() override;

        int
        factorize(const CoinWorkDouble *diagonal, int *rowsDropped) override;

      private:
        /** What one pattern's order() and symbolic() produced. */
        struct Cached
        {
          std::vector<int>                pattern;
          std::unique_ptr<ReusedCholesky> cholesky;
          /** Per factor row r: plan_k[k_begin[r] .. k_begin[r+1]). */
          std::vector<int> k_begin;
          /** Per term: the entry of the row copy (k). */
          std::vector<int> plan_k;
          /** Per term: j_begin into plan_j / plan_slot. */
          std::vector<int> j_begin;
          /** Per product: the column entry j and its place in the row
           *  (0: the diagonal, 1 + i: entry i of the row in the factor). */
          std::vector<int> plan_j, plan_slot;
        };

        /** The patterns of this thread, the newest first (at most 2). */
        static std::deque<std::shared_ptr<Cached>> &
        cache()
        {
          thread_local std::deque<std::shared_ptr<Cached>> c;
          return c;
        }

        /** Copy the factorisation structure of @p c into this object. */
        void
        restore(const ReusedCholesky &c);

        /** Make the plan of factorize() for the current structure. */
        void
        make_plan(Cached &c) const;

        /** The pattern and plan in use (nullptr: Clp's factorize). */
        std::shared_ptr<Cached> current;
        /** Whether order() restored a cached structure. */
        bool restored = false;
        /** The pattern of the model passed to order(). */
        std::vector<int> pattern;
      };

      template <typename T>
      T *
      copy_of(const T *a, const long n)
      {
        if (!a)
          return nullptr;
        T *b = new T[n];
        std::copy(a, a + n, b);
        return b;
      }

      void
      ReusedCholesky::restore(const ReusedCholesky &c)
      {
        // as ClpCholeskyBase::operator=, without its leak of choleskyRow_
        delete[] rowsDropped_;
        delete[] permuteInverse_;
        delete[] permute_;
        delete[] sparseFactor_;
        delete[] choleskyStart_;
        delete[] choleskyRow_;
        delete[] indexStart_;
        delete[] diagonal_;
        delete[] workDouble_;
        delete[] link_;
        delete[] workInteger_;
        delete[] clique_;
        delete rowCopy_;
        type_              = c.type_;
        doKKT_             = c.doKKT_;
        goDense_           = c.goDense_;
        choleskyCondition_ = c.choleskyCondition_;
        numberTrials_      = c.numberTrials_;
        numberRows_        = c.numberRows_;
        status_            = c.status_;
        numberRowsDropped_ = c.numberRowsDropped_;
        rowsDropped_       = copy_of(c.rowsDropped_, numberRows_);
        permuteInverse_    = copy_of(c.permuteInverse_, numberRows_);
        permute_           = copy_of(c.permute_, numberRows_);
        sizeFactor_        = c.sizeFactor_;
        sizeIndex_         = c.sizeIndex_;
        firstDense_        = c.firstDense_;
        sparseFactor_      = copy_of(c.sparseFactor_, sizeFactor_);
        choleskyStart_     = copy_of(c.choleskyStart_, numberRows_ + 1);
        indexStart_        = copy_of(c.indexStart_, numberRows_);
        choleskyRow_       = copy_of(c.choleskyRow_, sizeIndex_);
        diagonal_          = copy_of(c.diagonal_, numberRows_);
        workDouble_        = copy_of(c.workDouble_, numberRows_);
        link_              = copy_of(c.link_, numberRows_);
        workInteger_       = copy_of(c.workInteger_, numberRows_);
        clique_            = copy_of(c.clique_, numberRows_);
        std::copy(c.integerParameters_,
                  c.integerParameters_ + 64,
                  integerParameters_);
        std::copy(c.doubleParameters_,
                  c.doubleParameters_ + 64,
                  doubleParameters_);
        // the values of this model's matrix, by rows
        rowCopy_        = model_->clpMatrix()->reverseOrderedCopy();
        denseThreshold_ = c.denseThreshold_;
      }

      int
      ReusedCholesky::order(ClpInterior *model)
      {
        model_   = model;
        restored = false;
        current.reset();
        pattern = pattern_of(*model->clpMatrix(), model->numberRows());
        auto &c = cache();
        for (auto i = c.begin(); i != c.end(); ++i)
          if ((*i)->pattern == pattern)
            {
              current = *i;
              c.erase(i);
              c.push_front(current);
              restore(*current->cholesky);
              restored = true;
              if (current->k_begin.empty())
                current.reset(); // no plan for this structure
              return 0;
            }
        return ClpCholeskyBase::order(model);
      }

      int
      ReusedCholesky::symbolic()
      {
        if (restored)
          return 0;
        const int status = ClpCholeskyBase::symbolic();
        if (status != 0 || doKKT_ || whichDense_ || numberRowsDropped_ > 0)
          return status;
        auto c      = std::make_shared<Cached>();
        c->pattern  = std::move(pattern);
        c->cholesky = std::make_unique<ReusedCholesky>(*this);
        make_plan(*c);
        auto &cached = cache();
        cached.push_front(c);
        if (cached.size() > 2)
          cached.pop_back();
        if (!c->k_begin.empty())
          current = c;
        return 0;
      }

      void
      ReusedCholesky::make_plan(Cached &c) const
      {
        const ClpMatrixBase &a         = *model_->clpMatrix();
        const CoinBigIndex  *col_start = a.getVectorStarts();
        const int           *col_len   = a.getVectorLengths();
        const int           *row       = a.getIndices();
        const CoinBigIndex  *row_start = rowCopy_->getVectorStarts();
        const int           *row_len   = rowCopy_->getVectorLengths();
        const int           *column    = rowCopy_->getIndices();
        // the plan has about half the products Clp's loop makes: give up
        // (Clp's factorize) where it would be large
        long n_products = 0;
        for (int j = 0; j < a.getNumCols(); ++j)
          n_products += static_cast<long>(col_len[j]) * col_len[j];
        if (n_products > 50000000L)
          return;
        std::vector<int> slot_of(numberRows_, -2);
        c.k_begin.reserve(numberRows_ + 1);
        c.plan_slot.reserve(n_products / 2 + numberRows_);
        c.plan_j.reserve(n_products / 2 + numberRows_);
        for (int r = 0; r < numberRows_; ++r)
          {
            c.k_begin.push_back(c.plan_k.size());
            const int  original = permute_[r];
            const int  number   = choleskyStart_[r + 1] - choleskyStart_[r];
            const int *which    = choleskyRow_ + indexStart_[r];
            if (row_len[original] == 0)
              {
                // Clp drops such a row: no plan
                c.k_begin.clear();
                return;
              }
            for (int i = 0; i < number; ++i)
              slot_of[which[i]] = 1 + i;
            slot_of[r] = 0;
            for (CoinBigIndex k = row_start[original];
                 k < row_start[original] + row_len[original];
                 ++k)
              {
                const int col = column[k];
                c.plan_k.push_back(k);
                c.j_begin.push_back(c.plan_j.size());
                for (CoinBigIndex j = col_start[col];
                     j < col_start[col] + col_len[col];
                     ++j)
                  {
                    const int target = permuteInverse_[row[j]];
                    if (target < r)
                      continue;
                    if (slot_of[target] == -2)
                      {
                        // not in the factor's pattern: cannot happen
                        c.k_begin.clear();
                        return;
                      }
                    c.plan_j.push_back(j);
                    c.plan_slot.push_back(slot_of[target]);
                  }
              }
            slot_of[r] = -2;
            for (int i = 0; i < number; ++i)
              slot_of[which[i]] = -2;
          }
        c.k_begin.push_back(c.plan_k.size());
        c.j_begin.push_back(c.plan_j.size());
      }

      int
      ReusedCholesky::factorize(const CoinWorkDouble *diagonal,
                                int                  *rowsDropped)
      {
        bool any_dropped = numberRowsDropped_ > 0 || !current;
        for (int i = 0; i < numberRows_ && !any_dropped; ++i)
          any_dropped = rowsDropped_[i] != 0;
        if (any_dropped || doKKT_ || whichDense_)
          return ClpCholeskyBase::factorize(diagonal, rowsDropped);

        // Clp's factorize() for this case (no KKT, no dense columns, no
        // dropped row), the normal matrix formed by the plan
        const Cached         &c            = *current;
        const double         *element      = model_->clpMatrix()->getElements();
        const double         *elementByRow = rowCopy_->getElements();
        const int            *column       = rowCopy_->getIndices();
        const int             numberColumns = model_->clpMatrix()->getNumCols();
        const CoinWorkDouble *diagonalSlack = diagonal + numberColumns;
        CoinWorkDouble        perturbation =
          model_->diagonalPerturbation() * model_->diagonalNorm();
        if (perturbation > 1.0)
          perturbation = 1.0;
        CoinWorkDouble delta2 = model_->delta();
        delta2 *= delta2;
        std::fill(workDouble_, workDouble_ + numberRows_, 0.0);
        CoinWorkDouble              largest2 = 1.0e-20;
        std::vector<CoinWorkDouble> row_values;
        for (int iRow = 0; iRow < numberRows_; iRow++)
          {
            longDouble *put  = sparseFactor_ + choleskyStart_[iRow];
            const int number = choleskyStart_[iRow + 1] - choleskyStart_[iRow];
            row_values.assign(number + 1, 0.0);
            CoinWorkDouble *values = row_values.data();
            values[0]              = diagonalSlack[permute_[iRow]] + delta2;
            for (int t = c.k_begin[iRow]; t < c.k_begin[iRow + 1]; ++t)
              {
                const int            k = c.plan_k[t];
                const CoinWorkDouble multiplier =
                  diagonal[column[k]] * elementByRow[k];
                for (int p = c.j_begin[t]; p < c.j_begin[t + 1]; ++p)
                  values[c.plan_slot[p]] += element[c.plan_j[p]] * multiplier;
              }
            diagonal_[iRow] = values[0];
            for (int j = 0; j <= number; j++)
              largest2 = CoinMax(largest2, CoinAbs(values[j]));
            std::copy(values + 1, values + 1 + number, put);
          }
        largest2 *= 1.0e-20;
        CoinWorkDouble largest = CoinMin(largest2, CHOL_SMALL_VALUE);
        int            numberDroppedBefore = 0;
        for (int iRow = 0; iRow < numberRows_; iRow++)
          {
            const int dropped = rowsDropped_[iRow];
            rowsDropped[iRow] = dropped;
            if (!dropped)
              {
                const CoinWorkDouble value = diagonal_[iRow];
                diagonal_[iRow]            = value + perturbation;
                if (!(value > largest2))
                  {
                    rowsDropped[iRow] = 2;
                    numberDroppedBefore++;
                  }
              }
          }
        doubleParameters_[10]  = CoinMax(1.0e-20, largest);
        integerParameters_[20] = 0;
        doubleParameters_[3]   = 0.0;
        doubleParameters_[4]   = COIN_DBL_MAX;
        integerParameters_[34] = 0;
        factorizePart2(rowsDropped);
        int newDropped     = integerParameters_[20] + numberDroppedBefore;
        largest            = doubleParameters_[3];
        const double small = doubleParameters_[4];
        choleskyCondition_ = largest / small;
        if (model_->numberIterations() < 2000)
          {
            if (newDropped || numberRowsDropped_)
              {
                newDropped = 0;
                for (int i = 0; i < numberRows_; i++)
                  {
                    const char dropped = static_cast<char>(rowsDropped[i]);
                    rowsDropped_[i]    = 0;
                    if (dropped == 2)
                      rowsDropped[newDropped++] = i;
                  }
                numberRowsDropped_ = newDropped;
                newDropped         = -(2 + newDropped);
              }
          }
        else if (newDropped)
          {
            newDropped = 0;
            for (int i = 0; i < numberRows_; i++)
              {
                const char dropped = static_cast<char>(rowsDropped[i]);
                rowsDropped_[i]    = dropped;
                if (dropped == 2)
                  {
                    rowsDropped[newDropped++] = i;
                    rowsDropped_[i]           = 1;
                  }
              }
            numberRowsDropped_ += newDropped;
          }
        status_ = 0;
        return newDropped;
      }
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
