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
#include <masonry/lp/solution_check.h>

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

    /**
     * Clp's dual of @p model (ClpSimplexOther::dualOfModel), or nullptr if
     * Clp declines (some bound patterns are beyond it). That function
     * prints one line to the C stdout unconditionally; the descriptor is
     * pointed at /dev/null meanwhile (under a mutex, since GA islands
     * solve in parallel).
     */
    std::unique_ptr<ClpSimplex>
    dual_of(ClpSimplex &model);

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
