/**
 * @file
 * The Cholesky factorisation of Clp's barrier that keeps its ordering and
 * symbolic factorisation per sparsity pattern (see clp_cholesky.h).
 */
#include "clp_cholesky.h"
#include <coin/ClpInterior.hpp>
#include <coin/CoinHelperFunctions.hpp>

#include <algorithm>
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
    } // namespace

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
    ReusedCholesky::factorize(const CoinWorkDouble *diagonal, int *rowsDropped)
    {
      bool any_dropped = numberRowsDropped_ > 0 || !current;
      for (int i = 0; i < numberRows_ && !any_dropped; ++i)
        any_dropped = rowsDropped_[i] != 0;
      if (any_dropped || doKKT_ || whichDense_)
        return ClpCholeskyBase::factorize(diagonal, rowsDropped);

      // Clp's factorize() for this case (no KKT, no dense columns, no
      // dropped row), the normal matrix formed by the plan
      const Cached         &c             = *current;
      const double         *element       = model_->clpMatrix()->getElements();
      const double         *elementByRow  = rowCopy_->getElements();
      const int            *column        = rowCopy_->getIndices();
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
          longDouble *put    = sparseFactor_ + choleskyStart_[iRow];
          const int   number = choleskyStart_[iRow + 1] - choleskyStart_[iRow];
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
      CoinWorkDouble largest             = CoinMin(largest2, CHOL_SMALL_VALUE);
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
  } // namespace lp
} // namespace masonry
