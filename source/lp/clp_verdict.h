/**
 * @file
 * The `clp` back-end's verdicts on an LP without an optimum: two bounded
 * auxiliary LPs, each solved by the barrier on Clp's explicit dual, tell
 * an infeasible from an unbounded LP in about the time of an optimal
 * solve; the verdict on an LP without a dual feasible point; and a rule
 * that stops a barrier whose iterates diverge. Private to the `clp`
 * back-end.
 */
#ifndef masonry_lp_clp_verdict_h
#define masonry_lp_clp_verdict_h

#include <masonry/lp/linear_program.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

class ClpInterior;
class ClpSimplex;

namespace masonry
{
  namespace lp
  {
    /** What the auxiliary LPs of decide_verdict() proved. */
    struct Verdict
    {
      enum class Outcome
      {
        /** No point satisfies every row and bound. */
        infeasible,
        /** Feasible, with a ray of positive objective. */
        unbounded,
        /** Feasible without such a ray: the LP has an optimum. */
        bounded,
        /** The auxiliary LPs' values fell between the thresholds, or a
         * barrier failed. */
        undecided
      };
      Outcome outcome = Outcome::undecided;
      /**
       * The least sum of the violations of the rows (phase 1), in the
       * LP's units; -1 if not computed.
       */
      double misfit = -1;
      /**
       * The largest objective of a direction of the LP's recession cone
       * with every column within [-1, 1] (the ray LP); -1 if not
       * computed.
       */
      double ray_value = -1;
      /**
       * Infeasible: the violation of every row at the point of least
       * total violation (where the rows cannot be met).
       */
      std::vector<double> row_misfit;
      /** Unbounded: the ray (one value per column). */
      std::vector<double> ray;
      /** Barrier iterations of the auxiliary LPs. */
      unsigned int iterations = 0;
      /** What was solved and found, for Solution::message. */
      std::string description;
    };

    /**
     * Decide whether @p lp (loaded into @p model, a Clp model of it
     * without a solve, as the `clp` back-end creates it) is infeasible,
     * unbounded or has an optimum, by two bounded LPs built from Clp's
     * explicit dual D of the LP (rows: one per column of the LP):
     *
     * - phase 1, unless @p known_feasible: D with its right-hand side set
     *   to 0 and every column (a multiplier of a row of the LP) within
     *   [-1, 1]. Its optimum is 0 if the LP is feasible and minus the
     *   least sum of row violations otherwise (Farkas).
     * - the ray LP, unless the LP is infeasible or @p known_dual_infeasible
     *   (a simplex proved D infeasible): D with a zero objective
     *   and a slack of cost 1 on every row, the dual of "maximise c^T r
     *   over the recession cone of the LP with every column within
     *   [-1, 1]". Its optimum is positive exactly when D is infeasible,
     *   i.e. when a feasible LP is unbounded. Where no column bounded on
     *   one side lets the objective grow (plastic multipliers cost
     *   dissipation), only the free columns are boxed: the rows of the
     *   others get no slack, and those with a single entry become bounds
     *   (SingletonRows), which makes it about 15 % faster.
     *
     * Both are feasible and bounded, so the barrier converges on them (in
     * about as many iterations as on an LP with an optimum). A value above
     * 1e-6 of the LP's scale (the largest finite bound for phase 1, the
     * largest objective coefficient for the ray LP) proves it, one below
     * 1e-8 of it refutes it, anything between is `undecided`.
     */
    Verdict
    decide_verdict(const LinearProgram &lp,
                   ClpSimplex          &model,
                   const bool           known_feasible,
                   const bool           known_dual_infeasible,
                   const double         time_limit);

    /**
     * A rule for barrier_with_crossover()'s @p stop on Clp's explicit dual
     * D of an LP whose objective scale is @p scale (check_pair()'s
     * work_scale): stop after three consecutive iterations in which D's
     * dual objective exceeds its primal one by more than @p scale (D
     * infeasible: its dual values, the LP's columns, grow along a ray of
     * the LP) or D's primal objective is below -100 @p scale (D
     * unbounded: the LP is infeasible), in D's minimisation sense. A
     * barrier on an LP with an optimum keeps its dual objective below its
     * primal one and both near the optimum, whose size the scale bounds.
     */
    std::function<bool(const ClpInterior &)>
    divergence_rule(const double scale);

    /** Whether x = 0 satisfies every row and column bound of @p lp. */
    bool
    zero_is_feasible(const LinearProgram &lp);

    /**
     * The verdict on @p lp once it is known to have no dual feasible point
     * (it is unbounded if it is feasible, else infeasible): unbounded if
     * x = 0 is feasible; else phase 1 of decide_verdict() on a model from
     * @p create (a fresh Clp model of @p lp), and if that is undecided, a
     * primal simplex with zero objective on another. Verdict::iterations
     * counts the iterations of all these solves; the outcome stays
     * `undecided` if none decided.
     */
    Verdict
    verdict_when_dual_infeasible(
      const LinearProgram                                &lp,
      const std::function<std::unique_ptr<ClpSimplex>()> &create,
      const double                                        time_limit);
  } // namespace lp
} // namespace masonry

#endif
