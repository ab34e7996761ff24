#include <masonry/lp/linear_program.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
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

      /** Shortest decimal representation that reads back exactly. */
      std::string
      number(const double value)
      {
        char buffer[40];
        for (int digits = 1; digits <= 17; ++digits)
          {
            std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
            if (std::strtod(buffer, nullptr) == value)
              break;
          }
        return buffer;
      }

      /** A fixed-MPS data line: fields at columns 5, 15, 25, 40, 50. */
      std::string
      data_line(const std::string &indicator,
                const std::string &name,
                const std::string &name1,
                const std::string &value1,
                const std::string &name2  = "",
                const std::string &value2 = "")
      {
        std::string line = " " + indicator;
        auto        pad  = [&line](const std::size_t column) {
          // column is 1-based; keep at least one blank between fields
          if (line.size() < column - 1)
            line.resize(column - 1, ' ');
          else
            line += ' ';
        };
        pad(5);
        line += name;
        pad(15);
        line += name1;
        if (!value1.empty())
          {
            pad(25);
            line += value1;
          }
        if (!name2.empty())
          {
            pad(40);
            line += name2;
            pad(50);
            line += value2;
          }
        return line + "\n";
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
      // sort triplet indices by (column, row), then merge duplicates
      std::vector<std::size_t> order(triplets.size());
      for (std::size_t k = 0; k < order.size(); ++k)
        order[k] = k;
      std::sort(order.begin(),
                order.end(),
                [this](const std::size_t a, const std::size_t b) {
                  const Entry &ea = triplets[a], &eb = triplets[b];
                  return ea.column != eb.column ? ea.column < eb.column :
                                                  ea.row < eb.row;
                });
      ColumnMatrix m;
      m.start.assign(n_columns() + 1, 0);
      m.row_index.reserve(triplets.size());
      m.value.reserve(triplets.size());
      std::vector<unsigned int> column_of;
      column_of.reserve(triplets.size());
      for (std::size_t k = 0; k < order.size();)
        {
          const Entry &e     = triplets[order[k]];
          double       value = 0;
          for (; k < order.size() && triplets[order[k]].column == e.column &&
                 triplets[order[k]].row == e.row;
               ++k)
            value += triplets[order[k]].value;
          if (value != 0.)
            {
              m.row_index.push_back(e.row);
              m.value.push_back(value);
              column_of.push_back(e.column);
            }
        }
      for (const unsigned int c : column_of)
        ++m.start[c + 1];
      for (unsigned int c = 0; c < n_columns(); ++c)
        m.start[c + 1] += m.start[c];
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
      std::ofstream out(filename);
      AssertThrow(out, dealii::ExcMessage("Cannot write '" + filename + "'."));

      const std::vector<std::string> rows = mps_names(r_names, 'R');
      const std::vector<std::string> cols = mps_names(col_names, 'C');
      const double                   sign = maximize ? -1. : 1.;

      out << "* masonry linear program: " << n_rows() << " rows, "
          << n_columns() << " columns, " << n_nonzeros() << " entries\n";
      if (maximize)
        out << "* The problem MAXIMISES c^T x; this file states the "
               "equivalent\n"
               "* MINIMISE (-c)^T x: the optimum reported by an MPS reader "
               "is\n"
               "* minus the maximum (do not pass -max/--max).\n";
      out << "NAME          MASONRY\n";
      out << "ROWS\n";
      out << " N  OBJ\n";
      std::vector<std::string> type(n_rows());
      for (unsigned int i = 0; i < n_rows(); ++i)
        {
          const bool has_lower = r_lower[i] > -infinity;
          const bool has_upper = r_upper[i] < infinity;
          if (has_lower && has_upper && r_lower[i] == r_upper[i])
            type[i] = "E";
          else if (has_lower)
            type[i] = "G"; // a finite upper bound too: RANGES below
          else if (has_upper)
            type[i] = "L";
          else
            type[i] = "N"; // free row
          out << " " << type[i] << "  " << rows[i] << "\n";
        }

      out << "COLUMNS\n";
      const ColumnMatrix m = column_matrix();
      for (unsigned int j = 0; j < n_columns(); ++j)
        {
          // the objective entry, then the matrix entries; a column without
          // any entry gets an explicit zero cost so that it is declared
          if (cost[j] != 0. || m.start[j] == m.start[j + 1])
            out << data_line("", cols[j], "OBJ", number(sign * cost[j] + 0.));
          for (int k = m.start[j]; k < m.start[j + 1]; ++k)
            out << data_line("",
                             cols[j],
                             rows[m.row_index[k]],
                             number(m.value[k]));
        }

      out << "RHS\n";
      for (unsigned int i = 0; i < n_rows(); ++i)
        {
          double rhs = 0;
          if (type[i] == "E" || type[i] == "G")
            rhs = r_lower[i];
          else if (type[i] == "L")
            rhs = r_upper[i];
          if (rhs != 0.)
            out << data_line("", "RHS", rows[i], number(rhs));
        }

      bool ranges_header = false;
      for (unsigned int i = 0; i < n_rows(); ++i)
        if (type[i] == "G" && r_upper[i] < infinity)
          {
            if (!ranges_header)
              out << "RANGES\n";
            ranges_header = true;
            // for a G row, the range R gives lower <= a x <= lower + |R|
            out << data_line("",
                             "RNG",
                             rows[i],
                             number(r_upper[i] - r_lower[i]));
          }

      out << "BOUNDS\n";
      for (unsigned int j = 0; j < n_columns(); ++j)
        {
          const double l = col_lower[j], u = col_upper[j];
          const bool   has_l = l > -infinity, has_u = u < infinity;
          if (has_l && has_u && l == u)
            out << data_line("FX", "BND", cols[j], number(l));
          else if (!has_l && !has_u)
            out << data_line("FR", "BND", cols[j], "");
          else
            {
              // MPS default is 0 <= x < infinity
              if (!has_l)
                out << data_line("MI", "BND", cols[j], "");
              else if (l != 0.)
                out << data_line("LO", "BND", cols[j], number(l));
              if (has_u)
                out << data_line("UP", "BND", cols[j], number(u));
            }
        }
      out << "ENDATA\n";
      AssertThrow(out, dealii::ExcMessage("Error writing '" + filename + "'."));
    }
  } // namespace lp
} // namespace masonry
