/**
 * @file
 * A sparse linear program in "row and column bounds" form, the common
 * input of every LP solver back-end (lp::Interface).
 */
#ifndef masonry_lp_linear_program_h
#define masonry_lp_linear_program_h

#include <limits>
#include <string>
#include <vector>

namespace masonry
{
  /** Linear programming: the problem, its solution, the solver plugins. */
  namespace lp
  {
    /** Shorthand for an absent bound: `-lp::infinity` or `lp::infinity`. */
    constexpr double infinity = std::numeric_limits<double>::infinity();

    /**
     * A sparse linear program
     * @f[
     *   \text{maximise (or minimise) } c^T x
     *   \quad\text{subject to}\quad
     *   r_l \le A x \le r_u,\qquad x_l \le x \le x_u .
     * @f]
     * Columns (variables) and rows (constraints) are added one at a time,
     * the matrix as (row, column, value) triplets; duplicate triplets are
     * summed when a solver builds its matrix. Absent bounds are
     * `-std::numeric_limits<double>::infinity()` and `+infinity()`
     * (lp::infinity); an equality row has equal lower and upper bounds, a
     * free variable infinite bounds on both sides.
     *
     * All data are public read-only vectors, indexed by column or row number
     * and by triplet number, so that back-ends can copy them without an
     * accessor call per entry.
     */
    class LinearProgram
    {
    public:
      /** One matrix entry A(row, column) = value. */
      struct Entry
      {
        /** Row index. */
        unsigned int row;
        /** Column index. */
        unsigned int column;
        /** Value (summed with other entries at the same position). */
        double value;
      };

      /**
       * Sense of the optimisation: true (the default) to maximise
       * @f$c^T x@f$, false to minimise it.
       */
      bool maximize = true;

      /**
       * Whether the caller knows that a point satisfies every row and
       * bound (to the solvers' tolerances), e.g. from the structure of
       * the problem: then a back-end that finds no optimum need not solve
       * a phase 1 to tell an unbounded LP from an infeasible one. False
       * by default (nothing known).
       */
      bool known_feasible = false;

      /**
       * Add a variable with objective coefficient @p cost and bounds
       * @p lower <= x <= @p upper (either may be infinite). @p name is used
       * by write_mps() when it is a valid MPS name. Returns the index of the
       * new column. Throws if a value is NaN, if lower > upper, if
       * lower = +infinity or upper = -infinity, or if @p cost is infinite.
       */
      unsigned int
      add_column(const double       cost,
                 const double       lower,
                 const double       upper,
                 const std::string &name = "");

      /** Change the objective coefficient of an existing column. */
      void
      set_cost(const unsigned int column, const double cost);

      /**
       * Add a constraint @p lower <= (A x)_row <= @p upper (either may be
       * infinite, both equal for an equality). Returns the index of the new
       * row. Throws on the same invalid bounds as add_column().
       */
      unsigned int
      add_row(const double       lower,
              const double       upper,
              const std::string &name = "");

      /**
       * Add @p value to A(@p row, @p column). The row and column must exist.
       * Zero values are kept out of the matrix.
       */
      void
      add_entry(const unsigned int row,
                const unsigned int column,
                const double       value);

      /** Number of constraints. */
      unsigned int
      n_rows() const;

      /** Number of variables. */
      unsigned int
      n_columns() const;

      /**
       * Number of stored triplets (duplicates counted separately; an upper
       * bound on the number of nonzeros of A).
       */
      std::size_t
      n_nonzeros() const;

      /** Objective coefficients c, one per column. */
      const std::vector<double> &
      objective() const;

      /** Lower bounds x_l of the columns. */
      const std::vector<double> &
      column_lower() const;

      /** Upper bounds x_u of the columns. */
      const std::vector<double> &
      column_upper() const;

      /** Lower bounds r_l of the rows. */
      const std::vector<double> &
      row_lower() const;

      /** Upper bounds r_u of the rows. */
      const std::vector<double> &
      row_upper() const;

      /** The matrix entries, in the order they were added. */
      const std::vector<Entry> &
      entries() const;

      /** Names given to the columns ("" when none was given). */
      const std::vector<std::string> &
      column_names() const;

      /** Names given to the rows ("" when none was given). */
      const std::vector<std::string> &
      row_names() const;

      /**
       * The matrix in compressed column form, duplicates summed and exact
       * zeros dropped: the entries of column j are
       * `row_index[k], value[k]` for `k` in `[start[j], start[j+1])`, with
       * increasing row indices.
       */
      struct ColumnMatrix
      {
        /** Start of each column in row_index/value; size n_columns()+1. */
        std::vector<int> start;
        /** Row index of each entry. */
        std::vector<int> row_index;
        /** Value of each entry. */
        std::vector<double> value;
      };

      /** Build the matrix in compressed column form (see ColumnMatrix). */
      ColumnMatrix
      column_matrix() const;

      /** The value of the objective @f$c^T x@f$ at @p x. */
      double
      objective_value(const std::vector<double> &x) const;

      /** The row activities @f$A x@f$ at @p x. */
      std::vector<double>
      row_activities(const std::vector<double> &x) const;

      /**
       * Write the problem to @p filename in MPS format with COIN-OR
       * CoinUtils' writer (CoinMpsIO, "extra accuracy": numbers read back
       * exactly), preceded by comment lines stating the size and the
       * sense. It is read by `clp file.mps` and `glpsol --freemps
       * file.mps`.
       *
       * Names: the user's names are used when all names of rows (or of
       * columns) are valid MPS names (1 to 8 printable characters, no
       * blanks, not starting with '$' or '*') and unique; otherwise rows are
       * called R0000001, ... and columns C0000001, ... (more digits beyond
       * 9999999). The objective row is called OBJ.
       *
       * Sense: MPS minimises. For a maximisation, the file holds the
       * negated objective (min -c^T x, stated in a comment), so every MPS
       * reader solves the same problem without relying on OBJSENSE, and
       * the optimum it reports is minus the maximum. Run `clp file.mps
       * -primals` (not `-max`) or `glpsol --freemps file.mps` (not `--max`).
       */
      void
      write_mps(const std::string &filename) const;

    private:
      std::vector<double>      cost;
      std::vector<double>      col_lower;
      std::vector<double>      col_upper;
      std::vector<double>      r_lower;
      std::vector<double>      r_upper;
      std::vector<Entry>       triplets;
      std::vector<std::string> col_names;
      std::vector<std::string> r_names;
    };
  } // namespace lp
} // namespace masonry

#endif
