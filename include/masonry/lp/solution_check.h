/**
 * @file
 * The check of an LP solver's answer on the LP itself: bound violations of
 * the primal point, sign violations of the duals and the gap between the
 * two objectives. Every back-end's optimum goes through it
 * (lp::Solution::check).
 */
#ifndef masonry_lp_solution_check_h
#define masonry_lp_solution_check_h

#include <string>
#include <vector>

namespace masonry
{
  namespace lp
  {
    class LinearProgram;

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
       * no-tension route of Clp's `automatic` 1 % of work_scale (there the
       * only finite bounds are the prescribed velocities), so that an
       * optimum of 0 (a settlement that moves no block) is judged on that
       * scale. Mohr-Coulomb LPs have larger finite bounds (work_scale 462
       * on the Bothwell example, whose optimum is 0.06), so not there.
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
       * at most @p tolerance (`Optimality check tolerance`; Clp's
       * `Interior point tolerance` for a barrier's point kept without
       * crossover).
       */
      bool
      within(const double tolerance) const;
      /** The numbers, for Solution::message. */
      std::string
      describe() const;
    };

    /**
     * The scale of the objective of @p lp: the 1-norm of the objective
     * times the largest finite bound of a row or column (PairCheck's
     * work_scale).
     */
    double
    work_scale(const LinearProgram &lp);

    /** Check the pair (@p x, @p y) on @p lp (Solution's sign convention). */
    PairCheck
    check_pair(const LinearProgram       &lp,
               const std::vector<double> &x,
               const std::vector<double> &y);
  } // namespace lp
} // namespace masonry

#endif
