/**
 * @file
 * The `clp` LP solver back-end's class, shared by clp.cc (the solve and its
 * stages) and clp_dual_route.cc (the route through Clp's explicit dual LP).
 * Private to the `clp` back-end.
 */
#ifndef masonry_lp_clp_h
#define masonry_lp_clp_h

#include <masonry/lp/interface.h>
#include <masonry/lp/solution_check.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class ClpInterior;
class ClpSimplex;

namespace masonry
{
  namespace lp
  {
    struct Attempt;
    struct ClpBasis;
    struct Verdict;

    /** A barrier's interior point kept without crossover. */
    struct Interior
    {
      std::vector<double> x, y;
      PairCheck           check;
      /** What ran when the point failed the check. */
      std::string then = "crossover";
    };

    /**
     * LP solver back-end on COIN-OR Clp: dual simplex, primal simplex or
     * barrier (interior point) followed by crossover to a vertex, with or
     * without Clp's presolve.
     */
    class Clp : public Interface
    {
    public:
      /** Declare `Algorithm` and `Presolve` in `subsection Clp`. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Read `subsection Clp`. */
      void
      parse_parameters(dealii::ParameterHandler &prm) override;

      /** Solve @p lp with Clp. */
      Solution
      solve(const LinearProgram &lp) const override;

      /**
       * Solve @p lp from the basis in @p warm (simplex from that basis, no
       * presolve: the dual simplex unless `Algorithm = primal simplex'),
       * and store the optimal basis there. Without a basis of the same
       * shape, as solve().
       */
      Solution
      solve_warm(const LinearProgram &lp, WarmStart &warm) const override;

    private:
      /** Value of `Algorithm`. */
      std::string algorithm = "automatic";
      /** Value of `Presolve`. */
      bool presolve = true;
      /** Whether `Crossover = never`. */
      bool no_crossover = false;
      /** Value of `Interior point tolerance`. */
      double interior_tolerance = 1e-6;

      /**
       * solve() with an optional starting basis; on an optimal solve, the
       * final basis goes to @p basis_out.
       */
      Solution
      solve(const LinearProgram &lp,
            const ClpBasis      *basis_in,
            ClpBasis            *basis_out) const;

      /** A silent Clp model holding @p lp, with the time limit set. */
      std::unique_ptr<ClpSimplex>
      create(const LinearProgram &lp) const;

      /** Run @p method ("dual simplex", ...) on @p model. */
      void
      run(ClpSimplex        &model,
          const std::string &method,
          const bool         use_presolve) const;

      /** How solve_through_dual() ended. */
      enum class DualRoute
      {
        /** @p model holds a proven optimal vertex. */
        optimal,
        /** The barrier's interior point is the result (`Crossover`). */
        interior,
        /**
         * The simplex proved the dual LP infeasible: the LP itself has
         * no dual feasible point (it is unbounded or infeasible).
         */
        dual_infeasible,
        /** The auxiliary LPs of decide_verdict() proved the LP infeasible
         * or unbounded (see the Verdict). */
        decided,
        /** Anything else: solve the LP directly. */
        failed
      };

      /** `automatic`: Clp's explicit dual of @p model (the static problem)
       *  solved by @p method, its vertex restored into @p model, cleaned up.
       */
      DualRoute
      solve_through_dual(ClpSimplex          &model,
                         const std::string   &method,
                         unsigned int        &iterations,
                         const LinearProgram &lp,
                         Interior            *interior,
                         Verdict             &verdict) const;

      /**
       * solve_through_dual() with the barrier: the barrier on the dual LP
       * @p solved, stopped by @p diverging; with @p interior, its point is
       * the result if @p keep accepts it (which sets @p checked). A point
       * stopped or @p far_off the LP lets @p decide (the auxiliary LPs)
       * judge the LP. Adds the barrier's iterations to @p iterations.
       * Returns how the route ended, or nothing when it goes on to the
       * vertex the crossover left in @p solved.
       */
      std::optional<DualRoute>
      barrier_on_dual(ClpSimplex                                     &solved,
                      Interior                                       *interior,
                      const std::function<bool(const ClpSimplex &)>  &keep,
                      const std::function<bool(const ClpInterior &)> &diverging,
                      const std::function<bool()>                    &far_off,
                      const std::function<bool(bool)>                &decide,
                      bool                                           &checked,
                      unsigned int &iterations) const;

      /**
       * solve_through_dual() with a simplex @p method on the dual LP
       * @p solved; the primal simplex stops after @p simplex_cap pivots,
       * when @p decide (the auxiliary LPs) judges the LP, or else goes on.
       * Adds the pivots to @p iterations. Returns DualRoute::decided if the
       * auxiliary LPs decided, else nothing.
       */
      std::optional<DualRoute>
      simplex_on_dual(ClpSimplex                      &solved,
                      const std::string               &method,
                      const int                        simplex_cap,
                      const std::function<bool(bool)> &decide,
                      unsigned int                    &iterations) const;

      /**
       * solve_through_dual() after @p method ran on the dual LP @p solved:
       * how the route ends if the dual LP has no proven optimum (the
       * barrier's infeasibility confirmed by the primal simplex, the
       * primal simplex's verdicts, @p decide for an unbounded dual LP).
       * Adds the pivots to @p iterations. Nothing if @p solved is optimal.
       */
      static std::optional<DualRoute>
      dual_without_optimum(ClpSimplex                      &solved,
                           const std::string               &method,
                           const std::function<bool(bool)> &decide,
                           unsigned int                    &iterations);

      /**
       * solve() from the stored basis @p basis: a simplex without presolve
       * on @p attempt's model; the attempt is done on a verdict, else its
       * model is fresh again. Adds the pivots to @p iterations.
       */
      void
      solve_from_basis(const LinearProgram &lp,
                       const ClpBasis      &basis,
                       Attempt             &attempt,
                       unsigned int        &iterations) const;

      /**
       * solve() without a basis (or after a warm start that did not
       * decide): the barrier kept without crossover (@p use_interior with
       * `Algorithm = barrier`), the route through the dual (`automatic`),
       * then `Algorithm` on the LP itself unless @p attempt is done. Adds
       * the iterations to @p iterations.
       */
      void
      solve_cold(const LinearProgram &lp,
                 const bool           use_interior,
                 Attempt             &attempt,
                 unsigned int        &iterations) const;

      /**
       * The verdict of @p attempt's solve of the LP itself confirmed on the
       * original problem where it is not reliable: after presolve, an
       * infeasible verdict not from the primal simplex, a barrier's
       * optimum whose duals are no certificate. Adds the pivots to
       * @p iterations.
       */
      void
      confirm(const LinearProgram &lp,
              Attempt             &attempt,
              unsigned int        &iterations) const;

      /**
       * The optimal vertex in @p model into @p solution, checked (and
       * solved again unscaled if it fails the check); the message says
       * why @p interior was not kept, if it was checked. The basis goes to
       * @p basis_out if given.
       */
      void
      read_optimum(const LinearProgram &lp,
                   ClpSimplex          &model,
                   const Interior      &interior,
                   ClpBasis            *basis_out,
                   Solution            &solution) const;
    };
  } // namespace lp
} // namespace masonry

#endif
