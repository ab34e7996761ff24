/**
 * @file
 * The Cholesky factorisation of Clp's barrier in barrier_with_crossover()
 * (clp_barrier.h): ordered once per sparsity pattern, the normal matrix
 * formed from a precomputed plan. Private to the `clp` back-end.
 */
#ifndef masonry_lp_clp_cholesky_h
#define masonry_lp_clp_cholesky_h

#include <coin/ClpCholeskyBase.hpp>

#include <deque>
#include <memory>
#include <vector>

namespace masonry
{
  namespace lp
  {
    /**
     * ClpCholeskyBase (the factorisation Clp's barrier uses by default),
     * with two changes that leave every floating-point operation as it
     * was:
     * - order() and symbolic() copy their result from an earlier solve
     *   in this thread of a matrix with the same pattern (the AMD
     *   ordering and the symbolic factorisation depend on the pattern
     *   only);
     * - factorize() forms A D A^T by a plan made once per pattern: for
     *   each row of the factor, the products that land in its lower
     *   triangle with their place in the factor, in Clp's order (Clp
     *   computes both triangles and discards the upper one, with an
     *   indirection per entry). Each entry accumulates the same terms
     *   in the same order, so the factor is bit for bit Clp's. Without
     *   a plan (dropped rows, dense columns, KKT) it is Clp's code.
     * - With @p dense_threshold 100, columns of 100 entries or more (at
     *   most 100 of them) are Clp's dense columns: left out of A D A^T
     *   and brought in by a dense low-rank correction. A limit load's
     *   dual LP has one, the load multiplier, with an entry per block,
     *   which makes A D A^T dense (Bothwell seismic, 24 x 32 blocks per
     *   half, Mohr-Coulomb joints: 20.0 -> 4.2 CPU s). Only for a point
     *   that may be kept:
     *   Clp's crossover from such a point took 270283 pivots and 288 s
     *   at 12 x 16 against 2.9 s from the point without them
     *   (contrib/benchmarks/lp_solvers/results-2026-11-29b.md). A
     *   contact force has at most 12 entries; LPs without such columns
     *   are factorised as before.
     */
    class ReusedCholesky : public ClpCholeskyBase
    {
    public:
      explicit ReusedCholesky(const int dense_threshold)
        : ClpCholeskyBase(dense_threshold)
      {}

      ReusedCholesky(const ReusedCholesky &) = default;

      ClpCholeskyBase *
      clone() const override
      {
        return new ReusedCholesky(*this);
      }

      int
      order(ClpInterior *model) override;

      int
      symbolic() override;

      int
      factorize(const CoinWorkDouble *diagonal, int *rowsDropped) override;

    private:
      /** What one pattern's order() and symbolic() produced. */
      struct Cached
      {
        std::vector<int>                pattern;
        std::unique_ptr<ReusedCholesky> cholesky;
        /** Per factor row r: plan_k[k_begin[r] .. k_begin[r+1]). */
        std::vector<int> k_begin;
        /** Per term: the entry of the row copy (k). */
        std::vector<int> plan_k;
        /** Per term: j_begin into plan_j / plan_slot. */
        std::vector<int> j_begin;
        /** Per product: the column entry j and its place in the row
         *  (0: the diagonal, 1 + i: entry i of the row in the factor). */
        std::vector<int> plan_j, plan_slot;
      };

      /** The patterns of this thread, the newest first (at most 2). */
      static std::deque<std::shared_ptr<Cached>> &
      cache()
      {
        thread_local std::deque<std::shared_ptr<Cached>> c;
        return c;
      }

      /** Copy the factorisation structure of @p c into this object. */
      void
      restore(const ReusedCholesky &c);

      /** Make the plan of factorize() for the current structure. */
      void
      make_plan(Cached &c) const;

      /** The pattern and plan in use (nullptr: Clp's factorize). */
      std::shared_ptr<Cached> current;
      /** Whether order() restored a cached structure. */
      bool restored = false;
      /** The pattern of the model passed to order(). */
      std::vector<int> pattern;
    };
  } // namespace lp
} // namespace masonry

#endif
