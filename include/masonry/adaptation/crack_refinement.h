/**
 * @file
 * `set Optimiser = crack refinement`: refine the block mesh where the
 * mechanism of the current mesh cracks, instead of moving its lines.
 */
#ifndef masonry_adaptation_crack_refinement_h
#define masonry_adaptation_crack_refinement_h

#include <masonry/adaptation/optimiser.h>

#include <vector>

namespace masonry
{
  namespace adaptation
  {
    /**
     * Crack-guided refinement of the parameter lines (no genes): the
     * analysis solves its mesh, measures the crack activity (the
     * area-weighted jumps of the mechanism) of the interfaces on lines u =
     * const and v = const, and splits the most active strips between
     * neighbouring lines u = const (per patch) and v = const (shared by
     * the patches) next to them at their middle;
     * then solves again (`Stages` times). The meshes are nested, so the
     * objective of a settlement never decreases from one stage to the
     * next. The analysis does the work (analysis::RigidBlockAnalysis);
     * this class holds the settings and the marking rule.
     */
    class CrackRefinement : public Optimiser
    {
    public:
      /** Stages, Split, Marked fraction, Marking, Largest number of
       * blocks. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      void
      parse_parameters(dealii::ParameterHandler &prm) override;

      /** Not a gene optimiser: throws. */
      Result
      optimise(const MPI_Comm,
               const std::vector<Fitness> &,
               const std::vector<double> &,
               const std::function<void(const Generation &)> &) override;

      /**
       * The strips to split, by Dörfler marking: the strips of largest
       * @p indicator (≥ 0) whose sum first reaches `Marked fraction` of the
       * total (at least one), and at least @p at_least of them (the
       * largest ones). Strips with no activity (below 1e-9 of the total)
       * or not above @p floor are never marked unless @p at_least asks
       * for them.
       */
      std::vector<bool>
      mark(const std::vector<double> &indicator,
           const unsigned int         at_least = 0,
           const double               floor    = 0) const;

      /** Refinement stages (solves before the final analysis). */
      unsigned int stages = 3;
      /** Fraction of the total crack activity whose strips are split. */
      double marked_fraction = 0.5;
      /** `Marking = per direction`: one marking per direction. */
      bool per_direction = false;
      /** `Split = blocks`: split the blocks next to cracks into four
       * (local, non-conforming refinement) instead of whole strips. */
      bool split_blocks = false;
      /** No stage refines a mesh with this many blocks or more. */
      unsigned int max_blocks = 100000;
    };
  } // namespace adaptation
} // namespace masonry

#endif
