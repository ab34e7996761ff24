/**
 * @file
 * LP solvers: the back-ends that solve a LinearProgram
 * (`subsection LP solver`, `set Solver = clp|glpk`).
 */
#ifndef masonry_lp_interface_h
#define masonry_lp_interface_h

#include <masonry/core/plugins.h>
#include <masonry/lp/linear_program.h>
#include <masonry/lp/solution_check.h>

#include <memory>
#include <string>
#include <vector>

namespace masonry
{
  namespace lp
  {
    /** Outcome of a solve. */
    enum class Status
    {
      /** An optimal solution was found. */
      optimal,
      /** The problem is feasible but its objective is unbounded. */
      unbounded,
      /** The problem has no feasible point. */
      infeasible,
      /**
       * The solver stopped without a proof of either (time limit, numerical
       * trouble, invalid input): the solution vectors are not meaningful.
       */
      failed
    };

    /** "optimal", "unbounded", "infeasible" or "failed". */
    std::string
    to_string(const Status status);

    /**
     * The result of LP solve.
     *
     * Dual sign convention (the same for every back-end): the dual
     * `row_duals[i]` of row i is the derivative of the optimal objective
     * value (of the sense being optimised, i.e. of @f$c^T x@f$ whether it
     * is maximised or minimised) with respect to the bound of row i that is
     * active, @f$y_i = \partial (c^T x^*) / \partial b_i@f$. Consequently,
     * with reduced costs @f$d = c - A^T y@f$:
     * - maximisation: @f$y_i \ge 0@f$ if the upper bound of row i is
     *   active, @f$y_i \le 0@f$ if the lower bound is active;
     * - minimisation: @f$y_i \le 0@f$ at an active upper bound,
     *   @f$y_i \ge 0@f$ at an active lower bound;
     * - @f$y_i = 0@f$ for a row strictly between its bounds;
     * - strong duality: @f$c^T x^* = \sum_i y_i b_i + \sum_j d_j x_j^*@f$
     *   with @f$b_i@f$ the active bound of row i (and @f$x_j^*@f$ at a bound
     *   wherever @f$d_j \neq 0@f$).
     */
    struct Solution
    {
      /** Outcome; the other members are meaningful only if optimal. */
      Status status = Status::failed;
      /** The optimal value of @f$c^T x@f$ (in the problem's sense). */
      double objective = 0;
      /** The primal solution, one value per column. */
      std::vector<double> x;
      /** The duals of the rows, one per row (sign: see above). */
      std::vector<double> row_duals;
      /** Number of simplex (or barrier plus crossover) iterations. */
      unsigned int iterations = 0;
      /** Wall-clock time of the solve, in seconds. */
      double seconds = 0;
      /** Free text from the back-end (reason of a failure, ...). */
      std::string message;
      /**
       * Infeasible, where the back-end says where: per row, its violation
       * at a point that violates the rows as little as possible in sum
       * (LP units; empty if not known).
       */
      std::vector<double> row_misfit;
      /**
       * Unbounded, where the back-end found one: a direction (one value
       * per column) in which every row and bound stays satisfied and the
       * objective improves (empty if not known).
       */
      std::vector<double> ray;
      /**
       * An optimum checked on the LP itself (check_pair() of x and
       * row_duals): bound violations, dual sign violations and the
       * duality gap. Meaningful only if @p checked.
       */
      PairCheck check;
      /**
       * Whether the back-end ran @p check on the optimum it returns (the
       * `clp` and `glpk` back-ends do, after re-solving a point that
       * fails it); a caller checks an unchecked optimum itself.
       */
      bool checked = false;
    };

    /**
     * What a back-end keeps from one solve to start the next one (a basis):
     * see Interface::solve_warm(). Back-ends derive their own data.
     */
    struct WarmStartData
    {
      virtual ~WarmStartData() = default;
    };

    /**
     * The warm-start state of a sequence of LPs of the same shape (number
     * of rows and columns): empty at first, filled by every optimal solve
     * of Interface::solve_warm(). One object per sequence (and per thread).
     */
    struct WarmStart
    {
      /** The back-end's data; nullptr before the first optimal solve. */
      std::unique_ptr<WarmStartData> data;
      /**
       * Optional identity of every row of the LP passed to the next
       * solve_warm() (e.g. contact point and component), set by the
       * caller: then an LP with the same columns but another set of rows
       * starts from the stored basis too, each row taking the status of
       * the stored row with the same key (a new row's slack is basic).
       * Empty: only an LP of the same shape starts warm, rows matched by
       * position.
       */
      std::vector<long long> row_keys;
      /** Number of solves that started from a stored basis. */
      unsigned int n_warm = 0;
    };

    /**
     * Base class of LP solver back-ends. Create one with
     * `plugins::Registry<lp::Interface>::create(prm)` after the registry's
     * declare_parameters(); it reads the shared entries of
     * `subsection LP solver` and its own subsection
     * (`subsection LP solver/Clp`, ...).
     */
    class Interface : public plugins::InterfaceBase
    {
    public:
      /** Parameters live in `subsection LP solver`. */
      static constexpr const char *registry_section = "LP solver";
      /** The selection entry: `set Solver = ...`. */
      static constexpr const char *registry_entry = "Solver";
      /** Default selection: "clp". */
      static const char *
      default_plugin();
      /** Help text of the selection entry. */
      static std::string
      selection_documentation();

      /**
       * Entries shared by all back-ends: `Export MPS file` (Bool), `Time
       * limit` (Double, seconds), `Warm starts` (Bool) and `Optimality
       * check tolerance` (Double).
       */
      static void
      declare_common_parameters(dealii::ParameterHandler &prm);

      /** Read the shared entries. */
      void
      parse_common_parameters(dealii::ParameterHandler &prm) override;


      /**
       * Solve @p lp. Never throws for infeasible or unbounded problems (see
       * Solution::status); a back-end failure gives Status::failed with a
       * message.
       */
      virtual Solution
      solve(const LinearProgram &lp) const = 0;

      /**
       * Solve @p lp starting from what @p warm holds from an earlier solve
       * of an LP with the same numbers of rows and columns (coefficients
       * and bounds may differ; with WarmStart::row_keys, the same columns
       * and rows matched by key), and store the final state in @p warm. Same
       * optimum and status as solve() (to the solver's tolerances). The
       * default ignores @p warm and calls solve().
       */
      virtual Solution
      solve_warm(const LinearProgram &lp, WarmStart &warm) const;

      /**
       * Whether the caller should write the LP to `lp.mps` in the output
       * directory (entry `Export MPS file`).
       */
      bool
      export_mps() const;

      /**
       * Time limit of a solve in seconds (CPU time for Clp, wall-clock time
       * for GLPK); 0 means none (`Time limit`).
       */
      double
      time_limit() const;

      /**
       * Whether a caller with a sequence of LPs with the same columns (rows
       * may differ, see WarmStart::row_keys) should call solve_warm()
       * (entry `Warm starts`); false: solve() every time.
       */
      bool
      warm_starts() const;

      /**
       * The largest bound violation, dual sign violation and relative
       * duality gap of an optimum that passes the check on the LP (entry
       * `Optimality check tolerance`).
       */
      double
      check_tolerance() const;

    protected:
      /** Value of `Export MPS file`. */
      bool export_mps_file = false;
      /** Value of `Time limit`, in seconds (0: no limit). */
      double time_limit_seconds = 0;
      /** Value of `Warm starts`. */
      bool warm_starts_enabled = true;
      /** Value of `Optimality check tolerance`. */
      double check_tolerance_value = 1e-6;
    };
  } // namespace lp
} // namespace masonry

/** Register an LP solver back-end (one line in the back-end's .cc file). */
#define MASONRY_REGISTER_LP_SOLVER(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::lp::Interface, classname, name, description)

#endif
