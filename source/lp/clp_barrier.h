/**
 * @file
 * Clp's barrier with crossover, as ClpSolve runs it without presolve, but
 * with a Cholesky factorisation that keeps its ordering and symbolic
 * factorisation between LPs of the same sparsity (the evaluations of one
 * block topology in an adaptation) and forms the normal matrix from a
 * precomputed plan. Private to the `clp` back-end.
 */
#ifndef masonry_lp_clp_barrier_h
#define masonry_lp_clp_barrier_h

#include <functional>

class ClpSimplex;
class ClpInterior;

namespace masonry
{
  namespace lp
  {
    /**
     * Solve @p model (loaded, no presolve) by Clp's primal-dual barrier
     * followed by Clp's crossover to a vertex: the same steps and the same
     * arithmetic as ClpSimplex::initialSolve() with ClpSolve::useBarrier
     * and presolve off (the optimum, vertex and iterations are
     * identical), except that the ordering and symbolic factorisation of
     * the normal matrix A D A^T are reused from an earlier solve (in this
     * thread) of an LP with the same sparsity pattern, that A D A^T is
     * assembled only in its lower triangle, that the crossover's second
     * primal values pass is skipped when the first one ended optimal (it
     * would start from that optimal basis and values), and that Clp's dual
     * values pass, run when the barrier's complementarity gap is exactly 0,
     * is left out (it had not ended after 13 CPU minutes on a 24 x 32 Bothwell
     * LP that the primal passes finish in about 46 s).
     *
     * If @p accept is given, the barrier runs with a dual tolerance of
     * @p accept_tolerance
     * (Clp stops when its primal and dual objectives differ by less than
     * the dual tolerance); if it ends optimal (by Clp's criteria) @p accept
     * is called with @p model holding the barrier's interior
     * point (unscaled primal values, row duals and reduced costs); if it
     * returns true the crossover is skipped and this function returns true
     * (@p model then has no basis and no optimal status). Otherwise the
     * barrier runs again as without @p accept, followed by the crossover
     * (the same result as without @p accept), and this function returns
     * false; with @p cross_if_rejected false it returns false at once
     * (@p model then holds the barrier's last point, with no basis).
     *
     * If @p stop is given, it is called after every barrier iteration with
     * the barrier; when it returns true the barrier stops there, no
     * crossover runs (also not with @p cross_if_rejected), @p model holds
     * the barrier's last point without a basis, *@p stopped is set and
     * this function returns false.
     */
    bool
    barrier_with_crossover(
      ClpSimplex                                     &model,
      const std::function<bool(const ClpSimplex &)>  &accept = nullptr,
      bool                                            cross_if_rejected = true,
      double                                          accept_tolerance  = 1e-12,
      const std::function<bool(const ClpInterior &)> &stop    = nullptr,
      bool                                           *stopped = nullptr);
  } // namespace lp
} // namespace masonry

#endif
