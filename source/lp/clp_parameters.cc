/**
 * @file
 * The entries of the `clp` LP solver back-end (see clp_parameters.h).
 */
#include <deal.II/base/parameter_handler.h>

#include "clp_parameters.h"

namespace masonry
{
  namespace lp
  {
    void
    declare_clp_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        "Algorithm",
        "automatic",
        dealii::Patterns::Selection(
          "automatic|dual simplex|primal simplex|barrier"),
        "Algorithm of Clp: `dual simplex', `primal simplex', `barrier' "
        "(primal-dual interior point, kept as it is or followed by the "
        "crossover to a vertex: see `Crossover'), or `automatic': Clp solves "
        "the explicit dual of the LP (for a mechanism LP, the static problem "
        "in the contact forces) without presolve, by the barrier when the LP "
        "has at least as many columns as rows (Mohr-Coulomb joints: the "
        "plastic multipliers), else (no tension no sliding) by the primal "
        "simplex without scaling (from 2000 rows of the dual LP up, from a "
        "basis of its free columns, the tangential forces), except that with "
        "`Crossover = never' a dual LP of 2000 rows or more without a column "
        "of 100 entries (a limit load's multiplier) is first solved by the "
        "barrier with its unbounded forces bounded (see `Crossover'). "
        "The barrier's factorisation treats columns of 100 entries or more "
        "(a limit load's multiplier) as dense. After the "
        "barrier, with `Crossover = never' (the default), its interior point "
        "is mapped back and checked (see there); otherwise, or if that check "
        "fails, and after the primal simplex, the vertex is mapped back and "
        "confirmed "
        "with the dual simplex (the primal simplex if the mapped basis is not "
        "dual feasible; both without scaling, after a pass of the primal "
        "simplex on the unscaled dual LP, when the barrier's vertex is optimal "
        "only for Clp's scaled dual LP; the LP is solved directly if this "
        "clean-up does not end within 1000 + rows / 20 iterations). An LP "
        "without an optimum is decided by two bounded auxiliary LPs solved by "
        "the barrier (phase 1: the least sum of row violations, > 1e-5 of the "
        "largest bound: infeasible; the ray LP: a direction of positive "
        "objective with the free columns within [-1, 1]: unbounded; "
        "doc/rigid-blocks.md, Statuses) when the barrier on the dual LP "
        "diverges (three iterations with its dual objective above its primal "
        "one by more than the LP's objective scale, or its primal objective "
        "below -100 times it), ends far off the LP (a residual above 1e-4), "
        "or the simplex proves the dual LP unbounded or needs more than "
        "1.25 times as many pivots as the dual LP has rows (plus 20); a dual "
        "LP that the "
        "simplex proves infeasible (after the barrier: the primal simplex "
        "from the barrier's last point) makes the LP unbounded or infeasible "
        "(unbounded if x = 0 satisfies every bound, else phase 1 decides). "
        "If they do not decide, a feasibility solve does, and anything else "
        "not proven optimal is solved directly by the same method. The "
        "choice comes from the measurements in contrib/benchmarks/lp_solvers "
        "and contrib/benchmarks/lp_verdicts. Unitless choice.");
      prm.declare_entry(
        "Crossover",
        "never",
        dealii::Patterns::Selection("always|never"),
        "Whether Clp's barrier (`Algorithm = barrier', and the routes of "
        "`automatic' that use it) is followed by the crossover to a vertex "
        "(`always') or, with `never' (the default), stops at its interior "
        "point when Clp's barrier ends optimal and the point checks out on the "
        "LP itself: the LP's primal values (for `automatic', read off the "
        "duals of the explicit dual LP) violate no bound, the duals no sign "
        "condition, by more than `Interior point tolerance' (in the LP's "
        "scaled units), and the pair's duality gap is at most that tolerance "
        "relative to the objective (see there); otherwise the barrier runs "
        "again and the crossover follows, as with `always'. On the "
        "no-tension route of `automatic' (see `Algorithm') the barrier solves "
        "the dual LP with every contact force that has no bound bounded by the "
        "total load (the 1-norm of the LP's objective: the force set of joints "
        "without a strength limit is unbounded, by self-stress, and the "
        "barrier does not converge on it), with Clp's stopping tolerance 1e-8; "
        "a point that fails the check is dropped and the primal simplex runs "
        "as with `always'; such forces are a centre of the optimal force set "
        "cut off at that bound (a vertex's are one extreme). With `never' the "
        "solution is not "
        "a vertex (velocities and contact forces are a centre of the optimal "
        "face; where several mechanisms or force states are optimal, `always' "
        "gives one extreme one), the optimum is exact to that tolerance "
        "(Mohr-Coulomb: within 6.4e-9 of the vertex's on every example and the "
        "Bothwell settlement up to 24 x 32 blocks per half, in 0.22 to 0.70 of "
        "the solve time; contrib/benchmarks/lp_solvers/README.md), "
        "`Algorithm = barrier' runs without presolve, and no basis is kept, so "
        "warm-started callers (minimum thickness) always cross over; the "
        "genetic algorithm's cold evaluations do not. Unitless choice.");
      prm.declare_entry(
        "Interior point tolerance",
        "1e-6",
        dealii::Patterns::Double(1e-12, 1e-3),
        "With `Crossover = never': the largest relative duality gap, bound "
        "violation and dual sign violation of the barrier's point that is kept "
        "as the optimum (else the crossover runs; on the no-tension route of "
        "`automatic' the primal simplex). The gap is relative to the "
        "objective (at least 1e-6), on the no-tension route of `automatic' to "
        "the larger of the objective and 1 % of the LP's own scale (the "
        "1-norm of its objective times its largest finite bound: the loads' "
        "work at the largest prescribed velocity), so that an optimum of 0 (a "
        "settlement that moves no block) is judged on that scale. The "
        "pair's contact forces "
        "are less accurate than its velocities: from 12 x 16 Bothwell blocks "
        "per half up its gap is 9e-8 to 2.7e-7 while the objective is within "
        "6.1e-9 of the vertex's "
        "(contrib/benchmarks/lp_solvers/README.md). "
        "Dimensionless.");
      prm.declare_entry("Presolve",
                        "true",
                        dealii::Patterns::Bool(),
                        "Whether Clp simplifies the problem before solving "
                        "it (removing fixed variables, singleton rows, ...). "
                        "An infeasible or unbounded problem is always "
                        "confirmed without presolve. Unitless flag.");
    }
  } // namespace lp
} // namespace masonry
