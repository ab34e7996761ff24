#include <masonry/core/output_file.h>
#include <masonry/lp/linear_program.h>

#include <deal.II/base/exceptions.h>

#include <coin/CoinFinite.hpp>
#include <coin/CoinMpsIO.hpp>
#include <coin/CoinPackedMatrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>

namespace masonry
{
  namespace lp
  {
    namespace
    {
      void
      check_bounds(const double       lower,
                   const double       upper,
                   const char        *what,
                   const std::string &name)
      {
        const std::string which =
          std::string(what) + (name.empty() ? "" : " '" + name + "'");
        AssertThrow(!std::isnan(lower) && !std::isnan(upper),
                    dealii::ExcMessage("LinearProgram: NaN bound of " + which +
                                       "."));
        AssertThrow(lower <= upper,
                    dealii::ExcMessage(
                      "LinearProgram: lower bound greater than upper bound "
                      "of " +
                      which + "."));
        AssertThrow(lower < infinity && upper > -infinity,
                    dealii::ExcMessage("LinearProgram: infeasible infinite "
                                       "bound of " +
                                       which + "."));
      }

      /** Valid name for fixed MPS: 1..8 printable non-blank characters. */
      bool
      valid_mps_name(const std::string &name)
      {
        if (name.empty() || name.size() > 8 || name[0] == '$' || name[0] == '*')
          return false;
        for (const char c : name)
          if (!std::isgraph(static_cast<unsigned char>(c)))
            return false;
        return true;
      }

      /**
       * The user's names if all are valid and unique (and differ from the
       * objective row's name), otherwise generated ones.
       */
      std::vector<std::string>
      mps_names(const std::vector<std::string> &given, const char prefix)
      {
        bool                  ok = true;
        std::set<std::string> seen;
        for (const auto &n : given)
          if (!valid_mps_name(n) || n == "OBJ" || !seen.insert(n).second)
            {
              ok = false;
              break;
            }
        if (ok)
          return given;
        std::vector<std::string> names(given.size());
        for (std::size_t i = 0; i < given.size(); ++i)
          {
            char buffer[32];
            std::snprintf(buffer, sizeof(buffer), "%c%07zu", prefix, i + 1);
            names[i] = buffer;
          }
        return names;
      }

    } // namespace

    unsigned int
    LinearProgram::add_column(const double       cost_value,
                              const double       lower,
                              const double       upper,
                              const std::string &name)
    {
      check_bounds(lower, upper, "column", name);
      AssertThrow(std::isfinite(cost_value),
                  dealii::ExcMessage("LinearProgram: objective coefficient "
                                     "of column '" +
                                     name + "' is not finite."));
      cost.push_back(cost_value);
      col_lower.push_back(lower);
      col_upper.push_back(upper);
      col_names.push_back(name);
      return cost.size() - 1;
    }

    void
    LinearProgram::set_cost(const unsigned int column, const double cost_value)
    {
      AssertThrow(column < cost.size() && std::isfinite(cost_value),
                  dealii::ExcMessage("LinearProgram: set_cost of a column "
                                     "that does not exist or to a value "
                                     "that is not finite."));
      cost[column] = cost_value;
    }

    unsigned int
    LinearProgram::add_row(const double       lower,
                           const double       upper,
                           const std::string &name)
    {
      check_bounds(lower, upper, "row", name);
      r_lower.push_back(lower);
      r_upper.push_back(upper);
      r_names.push_back(name);
      return r_lower.size() - 1;
    }

    void
    LinearProgram::add_entry(const unsigned int row,
                             const unsigned int column,
                             const double       value)
    {
      AssertThrow(row < n_rows(), dealii::ExcIndexRange(row, 0, n_rows()));
      AssertThrow(column < n_columns(),
                  dealii::ExcIndexRange(column, 0, n_columns()));
      AssertThrow(std::isfinite(value),
                  dealii::ExcMessage("LinearProgram: matrix entry is not "
                                     "finite."));
      if (value != 0.)
        triplets.push_back({row, column, value});
    }

    unsigned int
    LinearProgram::n_rows() const
    {
      return r_lower.size();
    }

    unsigned int
    LinearProgram::n_columns() const
    {
      return cost.size();
    }

    std::size_t
    LinearProgram::n_nonzeros() const
    {
      return triplets.size();
    }

    const std::vector<double> &
    LinearProgram::objective() const
    {
      return cost;
    }

    const std::vector<double> &
    LinearProgram::column_lower() const
    {
      return col_lower;
    }

    const std::vector<double> &
    LinearProgram::column_upper() const
    {
      return col_upper;
    }

    const std::vector<double> &
    LinearProgram::row_lower() const
    {
      return r_lower;
    }

    const std::vector<double> &
    LinearProgram::row_upper() const
    {
      return r_upper;
    }

    const std::vector<LinearProgram::Entry> &
    LinearProgram::entries() const
    {
      return triplets;
    }

    const std::vector<std::string> &
    LinearProgram::column_names() const
    {
      return col_names;
    }

    const std::vector<std::string> &
    LinearProgram::row_names() const
    {
      return r_names;
    }

    LinearProgram::ColumnMatrix
    LinearProgram::column_matrix() const
    {
      // triplet indices by (column, row): a counting sort by column (linear;
      // std::sort of the index vector was 3 % of a minimum-thickness run),
      // then each column's few entries by row, duplicates in the order they
      // were added, which are then summed
      const unsigned int       n = n_columns();
      std::vector<std::size_t> first(n + 1, 0);
      for (const Entry &e : triplets)
        ++first[e.column + 1];
      for (unsigned int c = 0; c < n; ++c)
        first[c + 1] += first[c];
      std::vector<std::size_t> order(triplets.size());
      {
        std::vector<std::size_t> next(first.begin(), first.end() - 1);
        for (std::size_t k = 0; k < triplets.size(); ++k)
          order[next[triplets[k].column]++] = k;
      }
      for (unsigned int c = 0; c < n; ++c)
        std::stable_sort(order.begin() + first[c],
                         order.begin() + first[c + 1],
                         [this](const std::size_t a, const std::size_t b) {
                           return triplets[a].row < triplets[b].row;
                         });
      ColumnMatrix m;
      m.start.assign(n + 1, 0);
      m.row_index.reserve(triplets.size());
      m.value.reserve(triplets.size());
      for (unsigned int c = 0; c < n; ++c)
        {
          for (std::size_t k = first[c]; k < first[c + 1];)
            {
              const unsigned int row   = triplets[order[k]].row;
              double             value = 0;
              for (; k < first[c + 1] && triplets[order[k]].row == row; ++k)
                value += triplets[order[k]].value;
              if (value != 0.)
                {
                  m.row_index.push_back(row);
                  m.value.push_back(value);
                }
            }
          m.start[c + 1] = m.row_index.size();
        }
      return m;
    }

    double
    LinearProgram::objective_value(const std::vector<double> &x) const
    {
      AssertDimension(x.size(), n_columns());
      double v = 0;
      for (unsigned int j = 0; j < n_columns(); ++j)
        v += cost[j] * x[j];
      return v;
    }

    std::vector<double>
    LinearProgram::row_activities(const std::vector<double> &x) const
    {
      AssertDimension(x.size(), n_columns());
      std::vector<double> ax(n_rows(), 0.);
      for (const Entry &e : triplets)
        ax[e.row] += e.value * x[e.column];
      return ax;
    }

    void
    LinearProgram::write_mps(const std::string &filename) const
    {
      const unsigned int        n = n_columns(), m = n_rows();
      const double              sign = maximize ? -1. : 1.;
      const ColumnMatrix        a    = column_matrix();
      std::vector<CoinBigIndex> start(a.start.begin(), a.start.end());
      std::vector<int>          length(n);
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
      const auto             coin = [](const double bound) {
        return bound == infinity  ? COIN_DBL_MAX :
                           bound == -infinity ? -COIN_DBL_MAX :
                                                bound;
      };
      std::vector<double> lower(n), upper(n), c(n), row_lo(m), row_up(m);
      for (unsigned int j = 0; j < n; ++j)
        {
          lower[j] = coin(col_lower[j]);
          upper[j] = coin(col_upper[j]);
          c[j]     = sign * cost[j] + 0.;
        }
      for (unsigned int i = 0; i < m; ++i)
        {
          row_lo[i] = coin(r_lower[i]);
          row_up[i] = coin(r_upper[i]);
        }
      CoinMpsIO mps;
      mps.messageHandler()->setLogLevel(0);
      mps.setMpsData(matrix,
                     COIN_DBL_MAX,
                     lower.data(),
                     upper.data(),
                     c.data(),
                     nullptr,
                     row_lo.data(),
                     row_up.data(),
                     mps_names(col_names, 'C'),
                     mps_names(r_names, 'R'));
      mps.setProblemName("MASONRY");
      mps.setObjectiveName("OBJ");
      // CoinMpsIO writes the body to a temporary file (removed on leaving);
      // the file appears under its name only with its header, whole.
      // Extra accuracy: numbers are written so that they read back exactly
      StagedFile body_file(filename + ".body");
      AssertThrow(mps.writeMps(body_file.temporary_name().c_str(), 0, 1) == 0,
                  dealii::ExcMessage("Cannot write '" + filename + "'."));

      // CoinMpsIO writes no comments: put the sense first
      std::ifstream in(body_file.temporary_name());
      std::string   body((std::istreambuf_iterator<char>(in)),
                       std::istreambuf_iterator<char>());
      in.close();
      OutputFile out(filename);
      out << "* masonry linear program: " << m << " rows, " << n << " columns, "
          << n_nonzeros() << " entries\n";
      if (maximize)
        out << "* The problem MAXIMISES c^T x; this file states the "
               "equivalent\n"
               "* MINIMISE (-c)^T x: the optimum reported by an MPS reader "
               "is\n"
               "* minus the maximum (do not pass -max/--max).\n";
      out << body;
      out.close();
    }
  } // namespace lp
} // namespace masonry
