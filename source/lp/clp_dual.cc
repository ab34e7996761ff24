/**
 * @file
 * The `clp` back-end's route through Clp's explicit dual LP: singleton rows
 * as bounds, and the barrier's interior point mapped back (clp_dual.h).
 */
#include "clp_dual.h"
#include <coin/ClpSimplex.hpp>
#include <coin/ClpSimplexOther.hpp>
#include <coin/CoinPackedMatrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fcntl.h>
#include <mutex>
#include <unistd.h>

namespace masonry
{
  namespace lp
  {
    SingletonRows::SingletonRows()                          = default;
    SingletonRows::SingletonRows(SingletonRows &&) noexcept = default;
    SingletonRows &
    SingletonRows::operator=(SingletonRows &&) noexcept = default;
    SingletonRows::~SingletonRows()                     = default;

    SingletonRows
    without_singleton_rows(const ClpSimplex &dual)
    {
      SingletonRows    s;
      CoinPackedMatrix by_row;
      by_row.reverseOrderedCopyOf(*dual.matrix());
      const int           m     = dual.numberRows();
      const CoinBigIndex *start = by_row.getVectorStarts();
      const int          *len   = by_row.getVectorLengths();
      std::vector<double> lower(dual.columnLower(),
                                dual.columnLower() + dual.numberColumns());
      std::vector<double> upper(dual.columnUpper(),
                                dual.columnUpper() + dual.numberColumns());
      for (int i = 0; i < m; ++i)
        {
          if (len[i] != 1)
            continue;
          const int    j  = by_row.getIndices()[start[i]];
          const double a  = by_row.getElements()[start[i]];
          const double lo = dual.rowLower()[i], up = dual.rowUpper()[i];
          // only a free column, bounded on each side by one row at
          // most (so that the row's dual is the column's reduced cost)
          if (a == 0 || dual.columnLower()[j] > -COIN_DBL_MAX ||
              dual.columnUpper()[j] < COIN_DBL_MAX)
            continue;
          const double l = a > 0 ? lo : up, u = a > 0 ? up : lo;
          const double bl = std::abs(l) < 1e30 ? l / a : -COIN_DBL_MAX;
          const double bu = std::abs(u) < 1e30 ? u / a : COIN_DBL_MAX;
          if ((bl > -COIN_DBL_MAX && bu < COIN_DBL_MAX) ||
              (bl > -COIN_DBL_MAX && lower[j] > -COIN_DBL_MAX) ||
              (bu < COIN_DBL_MAX && upper[j] < COIN_DBL_MAX))
            continue;
          if (bl > -COIN_DBL_MAX)
            lower[j] = bl;
          if (bu < COIN_DBL_MAX)
            upper[j] = bu;
          s.rows.push_back(i);
          s.columns.push_back(j);
          s.values.push_back(a);
          s.gives_lower.push_back(bl > -COIN_DBL_MAX);
        }
      if (s.rows.empty())
        return s;
      s.model = std::make_unique<ClpSimplex>(dual);
      for (int j = 0; j < dual.numberColumns(); ++j)
        {
          s.model->setColumnLower(j, lower[j]);
          s.model->setColumnUpper(j, upper[j]);
        }
      s.model->deleteRows(s.rows.size(), s.rows.data());
      return s;
    }

    void
    expand(const SingletonRows &s, ClpSimplex &dual)
    {
      const ClpSimplex &r = *s.model;
      const int         n = dual.numberColumns(), m = dual.numberRows();
      std::vector<int>  kept_index(m, 0);
      std::vector<bool> removed(m, false);
      for (const int i : s.rows)
        removed[i] = true;
      for (int i = 0, k = 0; i < m; ++i)
        kept_index[i] = removed[i] ? -1 : k++;
      double *x  = dual.primalColumnSolution();
      double *dj = dual.dualColumnSolution();
      double *y  = dual.dualRowSolution();
      for (int j = 0; j < n; ++j)
        {
          x[j]  = r.primalColumnSolution()[j];
          dj[j] = r.dualColumnSolution()[j];
          dual.setColumnStatus(j, r.getColumnStatus(j));
        }
      for (int i = 0; i < m; ++i)
        if (kept_index[i] >= 0)
          {
            y[i] = r.dualRowSolution()[kept_index[i]];
            dual.setRowStatus(i, r.getRowStatus(kept_index[i]));
          }
      for (unsigned int k = 0; k < s.rows.size(); ++k)
        {
          const int    i = s.rows[k], j = s.columns[k];
          const double a = s.values[k];
          y[i]           = 0;
          dual.setRowStatus(i, ClpSimplex::basic);
          const ClpSimplex::Status status = r.getColumnStatus(j);
          const bool at_lower = status == ClpSimplex::atLowerBound &&
                                r.columnLower()[j] > -COIN_DBL_MAX;
          const bool at_upper = status == ClpSimplex::atUpperBound &&
                                r.columnUpper()[j] < COIN_DBL_MAX;
          // is the bound at which the column sits this row's?
          const double lo = dual.rowLower()[i], up = dual.rowUpper()[i];
          const double row_l = a > 0 ? lo : up, row_u = a > 0 ? up : lo;
          const bool   mine = (at_lower && std::abs(row_l) < 1e30) ||
                            (at_upper && std::abs(row_u) < 1e30);
          if (!mine)
            continue;
          y[i]  = dj[j] / a;
          dj[j] = 0;
          dual.setColumnStatus(j, ClpSimplex::basic);
          dual.setRowStatus(i,
                            (at_upper) == (a > 0) ? ClpSimplex::atUpperBound :
                                                    ClpSimplex::atLowerBound);
        }
      double *activity = dual.primalRowSolution();
      std::fill(activity, activity + m, 0.);
      dual.matrix()->times(x, activity);
      dual.setObjectiveValue(r.objectiveValue());
      dual.setProblemStatus(r.problemStatus());
    }

    void
    interior_from_dual(const ClpSimplex    &primal,
                       const ClpSimplex    &solved,
                       const SingletonRows &s,
                       std::vector<double> &x,
                       std::vector<double> &y)
    {
      constexpr double big = 1e27; // Clp's SMALL_INFINITY
      const int        n = primal.numberColumns(), m = primal.numberRows();
      // the duals of the first n rows of the dual LP (one per column of
      // the LP), those of removed singleton rows from the reduced costs
      std::vector<double> dual_row(n, 0.);
      {
        std::vector<char> removed(n, 0);
        for (const int i : s.rows)
          removed[i] = 1;
        const double *ys = solved.dualRowSolution();
        for (int i = 0, k = 0; i < n; ++i)
          if (!removed[i])
            dual_row[i] = ys[k++];
        const double    *dj = solved.dualColumnSolution();
        std::vector<int> n_rows_of(solved.numberColumns(), 0);
        for (const int j : s.columns)
          ++n_rows_of[j];
        for (unsigned int k = 0; k < s.rows.size(); ++k)
          {
            const int j = s.columns[k];
            // a column bounded by one row: its dual takes the whole
            // reduced cost (the column is free in the dual LP); by two:
            // the row on the side the reduced cost's sign selects
            // (minimisation: positive at the lower bound)
            if (n_rows_of[j] == 1 || (dj[j] > 0) == (s.gives_lower[k] != 0))
              dual_row[s.rows[k]] = dj[j] / s.values[k];
          }
      }
      x.assign(n, 0.);
      const double *lower = primal.columnLower();
      const double *upper = primal.columnUpper();
      for (int j = 0; j < n; ++j)
        {
          double offset = 0;
          if (lower[j] > -big && upper[j] < big)
            offset =
              std::abs(lower[j]) < std::abs(upper[j]) ? lower[j] : upper[j];
          else if (lower[j] > -big)
            offset = lower[j];
          else if (upper[j] < big)
            offset = upper[j];
          x[j] = offset - dual_row[j];
        }
      // columns of the dual LP: one per row, one per boxed column, then
      // the second column of every range row
      int n_boxed = 0;
      for (int j = 0; j < n; ++j)
        n_boxed += lower[j] > -big && upper[j] < big;
      const double *value = solved.primalColumnSolution();
      const double  sign  = primal.optimizationDirection() < 0 ? -1. : 1.;
      y.assign(m, 0.);
      for (int i = 0, extra = m + n_boxed; i < m; ++i)
        {
          y[i]            = value[i];
          const double lo = primal.rowLower()[i], up = primal.rowUpper()[i];
          if (lo > -big && up < big && lo != up)
            y[i] += value[extra++];
          y[i] *= sign;
        }
    }

    std::unique_ptr<ClpSimplex>
    dual_of(ClpSimplex &model)
    {
      static std::mutex           mutex;
      std::lock_guard<std::mutex> lock(mutex);
      std::fflush(stdout);
      const int saved = ::dup(STDOUT_FILENO);
      const int null  = ::open("/dev/null", O_WRONLY);
      if (saved >= 0 && null >= 0)
        ::dup2(null, STDOUT_FILENO);
      std::unique_ptr<ClpSimplex> dual;
      try
        {
          dual.reset(static_cast<ClpSimplexOther &>(model).dualOfModel());
        }
      catch (const CoinError &)
        {
          // some bound patterns are beyond it: no dual
        }
      std::fflush(stdout);
      if (saved >= 0 && null >= 0)
        ::dup2(saved, STDOUT_FILENO);
      if (null >= 0)
        ::close(null);
      if (saved >= 0)
        ::close(saved);
      return dual;
    }

    void
    free_columns_basic(ClpSimplex &model)
    {
      const auto at_bound = [](const double lower, const double upper) {
        if (lower == upper)
          return ClpSimplex::isFixed;
        if (lower > -1e30)
          return ClpSimplex::atLowerBound;
        if (upper < 1e30)
          return ClpSimplex::atUpperBound;
        return ClpSimplex::basic;
      };
      for (int j = 0; j < model.numberColumns(); ++j)
        model.setColumnStatus(j,
                              at_bound(model.columnLower()[j],
                                       model.columnUpper()[j]));
      for (int i = 0; i < model.numberRows(); ++i)
        {
          const auto s = at_bound(model.rowLower()[i], model.rowUpper()[i]);
          // a free row's slack stays basic, as in Clp's slack basis
          model.setRowStatus(i, s);
        }
    }

    std::unique_ptr<ClpSimplex>
    boxed_copy(const ClpSimplex &dual, const double factor)
    {
      constexpr double big   = 1e27; // Clp's SMALL_INFINITY
      double           scale = 0;
      for (int i = 0; i < dual.numberRows(); ++i)
        {
          const double lo = dual.rowLower()[i], up = dual.rowUpper()[i];
          scale += std::max(lo > -big ? std::abs(lo) : 0.,
                            up < big ? std::abs(up) : 0.);
        }
      const double bound = factor * (scale > 0 ? scale : 1.);
      auto         boxed = std::make_unique<ClpSimplex>(dual);
      for (int j = 0; j < boxed->numberColumns(); ++j)
        {
          if (boxed->columnLower()[j] < -big)
            boxed->setColumnLower(j, -bound);
          if (boxed->columnUpper()[j] > big)
            boxed->setColumnUpper(j, bound);
        }
      return boxed;
    }

    bool
    has_dense_column(const ClpSimplex &model)
    {
      const int *length = model.matrix()->getVectorLengths();
      for (int j = 0; j < model.numberColumns(); ++j)
        if (length[j] >= 100)
          return true;
      return false;
    }
  } // namespace lp
} // namespace masonry
