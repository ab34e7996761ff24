/**
 * @file
 * Helpers of the `clp` back-end's route through Clp's explicit dual LP
 * (`Algorithm = automatic`): the dual's singleton rows as bounds, and the
 * barrier's interior point mapped back without a crossover
 * (`Crossover = never`). Private to the `clp` back-end.
 */
#ifndef masonry_lp_clp_dual_h
#define masonry_lp_clp_dual_h

#include <masonry/lp/linear_program.h>

#include <memory>
#include <string>
#include <vector>

class ClpSimplex;

namespace masonry
{
  namespace lp
  {
    /**
     * The rows of a dual LP with a single nonzero (in Clp's explicit dual
     * of a mechanism LP: the tension cut-off and the compression cap,
     * each a multiplier with one entry in the normal row of its point),
     * turned into bounds of their column and removed: the same feasible
     * set with fewer rows, which is what the barrier's factorisations
     * grow with. expand() maps a solution back.
     */
    struct SingletonRows
    {
      /** The removed rows, their column and coefficient. */
      std::vector<int>    rows, columns;
      std::vector<double> values;
      /** Per removed row: whether it bounds its column from below. */
      std::vector<char> gives_lower;
      /** The reduced model (nullptr if there was no singleton row). */
      std::unique_ptr<ClpSimplex> model;

      SingletonRows();
      SingletonRows(SingletonRows &&) noexcept;
      SingletonRows &
      operator=(SingletonRows &&) noexcept;
      ~SingletonRows();
    };

    /** The singleton rows of @p dual removed (see SingletonRows). */
    SingletonRows
    without_singleton_rows(const ClpSimplex &dual);

    /**
     * The solution and basis of the reduced model of @p s mapped to
     * @p dual, the model it was made from: a column at a bound that came
     * from a removed row is basic, that row at its bound with the
     * column's reduced cost as its dual; the other removed rows are
     * basic with dual 0.
     */
    void
    expand(const SingletonRows &s, ClpSimplex &dual);

    /**
     * The primal and dual values of @p primal (a model that @p dual was
     * made from by ClpSimplexOther::dualOfModel) read off the barrier's
     * interior point of @p solved (@p dual itself, or the reduced model of
     * @p s), by the same linear maps as ClpSimplexOther::restoreFromDual
     * but without statuses: column j of the LP is the bound that stayed on
     * it in the dual (0 if free) minus the dual of row j of @p dual; the
     * dual of row i is the value of column i of @p dual (plus that of its
     * second column if the row is a range), negated when maximising (a
     * removed singleton row's dual is its column's reduced cost over the
     * coefficient). Results in @p x and @p y (the Solution convention).
     */
    void
    interior_from_dual(const ClpSimplex    &primal,
                       const ClpSimplex    &solved,
                       const SingletonRows &s,
                       std::vector<double> &x,
                       std::vector<double> &y);

    /** Residuals and weak-duality bracket of a primal-dual pair. */
    struct PairCheck
    {
      /** Largest violation of a row or column bound by x (LP units). */
      double primal_residual = 0;
      /**
       * Largest part of a row dual or reduced cost d = c - A^T y whose
       * sign asks for a bound that is infinite (LP units).
       */
      double dual_residual = 0;
      /** c^T x. */
      double primal_objective = 0;
      /**
       * The Lagrangian bound of the pair: sum of y_i times the bound of
       * row i its sign selects plus the same for d_j and the column
       * bounds (the parts against infinite bounds left out). If x and y
       * are feasible, the optimum lies between primal_objective and it.
       */
      double dual_objective = 0;
      /**
       * The LP's own scale of its objective: the 1-norm of the objective
       * times the largest finite bound of a row or column (in a mechanism
       * LP, the loads' work at the largest prescribed velocity).
       */
      double work_scale = 0;
      /**
       * The smallest denominator of relative_gap(): 1e-6, or on the
       * no-tension route of `automatic` 1 % of work_scale (there the only
       * finite bounds are the prescribed velocities), so that an optimum
       * of 0 (a settlement that moves no block) is judged on that scale.
       * Mohr-Coulomb LPs have larger finite bounds (work_scale 462 on the
       * Bothwell example, whose optimum is 0.06), so not there.
       */
      double gap_floor = 1e-6;
      /**
       * |dual_objective - primal_objective| over the largest of their
       * absolute values and gap_floor.
       */
      double
      relative_gap() const;
      /**
       * Whether relative_gap(), primal_residual and dual_residual are all
       * at most @p tolerance (`Interior point tolerance`).
       */
      bool
      within(const double tolerance) const;
      /** The numbers, for Solution::message. */
      std::string
      describe() const;
    };

    /** Check the pair (@p x, @p y) on @p lp (Solution's sign convention). */
    PairCheck
    check_pair(const LinearProgram       &lp,
               const std::vector<double> &x,
               const std::vector<double> &y);

    /**
     * A starting basis for @p model: its free columns basic, every other
     * column and every row slack at a finite bound (at the lower one if it
     * has one). Usually singular or short of basic variables; Clp
     * completes it with slacks when it factorises it.
     */
    void
    free_columns_basic(ClpSimplex &model);

    /**
     * A copy of the dual LP @p dual whose column bounds that are infinite
     * are @p factor times the 1-norm of its right-hand side instead (the
     * LP's objective: in a mechanism LP the loads, so a contact force may
     * reach @p factor times the total load). The force set of a mechanism
     * LP with joints of unbounded strength (no tension no sliding) is
     * unbounded (self-stress within an interface), so that the barrier's
     * iterates grow without end; on the boxed copy they converge. An
     * interior point of the copy whose mapped pair passes check_pair() on
     * the LP is optimal for the LP itself: the boxes only allow the LP's
     * rows to be violated, and the check would see that.
     */
    std::unique_ptr<ClpSimplex>
    boxed_copy(const ClpSimplex &dual, double factor);

    /**
     * Whether a column of @p model has 100 entries or more (a contact
     * force of a mechanism LP's dual has at most 12; the load multiplier of
     * a limit load LP one per block).
     */
    bool
    has_dense_column(const ClpSimplex &model);
  } // namespace lp
} // namespace masonry

#endif
