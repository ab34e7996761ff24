/**
 * @file
 * The direct check of a prescribed support motion before the linear
 * program: whether the blocks can follow it at all, and if not, where not.
 */
#ifndef masonry_rigid_blocks_support_check_h
#define masonry_rigid_blocks_support_check_h

#include <masonry/rigid_blocks/block_model.h>
#include <masonry/rigid_blocks/mechanism.h>

#include <deal.II/base/point.h>

#include <string>

namespace masonry
{
  namespace rigid_blocks
  {
    class InterfaceModel;

    /**
     * Where a prescribed support motion cannot be followed by rigid blocks.
     *
     * Two kinds:
     * - `support`: the motion that the supports of one block (or of a group
     *   of blocks tied by joints that cannot open) prescribe exactly (all
     *   three components at a bonded support, those that the joints cannot
     *   open or slide in at a unilateral one) is no rigid motion. The
     *   misfit is the largest distance, at a support point, between the
     *   prescribed motion and the rigid motion of the block that fits it
     *   best (least squares).
     * - `lp`: found by the LP, not by the direct check (locate_row_misfit()):
     *   the contact row with the largest violation at the point that
     *   violates the rows least in sum (phase 1).
     * - `joint`: the supports fix the motions of the blocks on both sides
     *   of a joint (or of a block and the ground at a unilateral support),
     *   and the jump between them is not one the joint admits (it would
     *   have to close, or slide where it cannot). The misfit is the
     *   distance of that jump from the admissible jumps.
     */
    struct Incompatibility
    {
      /** `support`, `joint` or `lp` (see above). */
      std::string kind;
      /** The block. */
      unsigned int block = 0;
      /** The block on the other side of a `joint` (Interface::support for
       * the ground). */
      unsigned int other_block = Interface::support;
      /** Label of the support edge (empty for a joint between blocks). */
      std::string support_label;
      /** Name of the block's patch. */
      std::string patch;
      /** Centroid of the block, m. */
      dealii::Point<3> centroid;
      /** The contact point with the largest misfit, m. */
      dealii::Point<3> position;
      /** Largest misfit at a contact point, m. */
      double misfit = 0;
      /** Root mean square of the misfits at the block's points, m. */
      double rms_misfit = 0;
      /** Number of blocks (kind `support`), joints (`joint`) or contact
       * rows (`lp`) whose misfit exceeds the tolerance. */
      unsigned int n_found = 0;
      /** Kind `lp`: the direction of the row (`normal', `across' or
       * `along' the joint). */
      std::string direction;
      /** Kind `lp`: the sum of the misfits of all rows, m. */
      double total_misfit = 0;

      /** One line naming the edge, the block, its position and the misfit. */
      std::string
      describe() const;
    };

    /** The outcome of check_support_motion(). */
    struct SupportCheck
    {
      /** Whether a misfit exceeds the tolerance (then see @p worst). */
      bool incompatible = false;
      /** The largest misfit found (kind `support` first: see there). */
      Incompatibility worst;
      /** The tolerance used, m. */
      double tolerance = 0;
      /** Largest misfit of a supported block's fit, also when compatible
       * (m). */
      double largest_misfit = 0;
      /** Number of supported groups of blocks whose motion the supports
       * fix completely. */
      unsigned int n_fixed_groups = 0;
      /** Number of supported groups of blocks. */
      unsigned int n_supported_groups = 0;
      /**
       * Whether the check is exact for this model: every joint admits any
       * jump (a bounded strength domain), so that the LP is feasible
       * whenever no misfit is found.
       */
      bool exact = false;
    };

    /**
     * Check whether the support motion @p u0 (m; nullptr: fixed supports)
     * can be followed by the blocks of @p model with joints @p joints and
     * bonded (@p bonded) or unilateral supports, before any LP is built:
     *
     * 1. The joints of @p joints admit the jumps of the cone K spanned by
     *    the normals of its yield planes; a component orthogonal to K's
     *    span is fixed (no tension no sliding: both tangential components;
     *    Mohr-Coulomb with a compression cap: none). Blocks joined by an
     *    interface whose fixed components at its points determine the
     *    relative motion (rigid joints) form one group.
     * 2. Per group, the support components that are prescribed exactly (at
     *    bonded supports all three, at unilateral ones the fixed
     *    components) are fitted by one rigid motion (least squares); a
     *    misfit above @p tolerance is an Incompatibility of kind
     *    `support`.
     * 3. Where the fit fixes a group's motion completely, the jumps of the
     *    joints between two fixed groups, and at unilateral supports of a
     *    fixed group, must lie in K; a distance from K above
     *    @p tolerance is an Incompatibility of kind `joint`.
     *
     * What this cannot see: jumps that blocks of undetermined motion
     * would have to take (a chain of blocks between two supports); those
     * remain for the LP.
     */
    SupportCheck
    check_support_motion(const BlockModel     &model,
                         const InterfaceModel &joints,
                         const SupportMotion  &u0,
                         const bool            bonded,
                         const double          tolerance);

    /**
     * Where the infeasible LP of @p problem (built for @p model) cannot be
     * met: given @p row_misfit, every row's violation at a point of least
     * total violation (lp::Solution::row_misfit, LP units), the row with
     * the largest one as an Incompatibility of kind `lp`: its joint (the
     * blocks, or the block and the support edge), contact point,
     * direction and misfit in m (LP units times @p velocity_scale, the
     * settlement that the LP's unit stands for); n_found counts the rows
     * above @p tolerance (m). Kind empty if no row is violated.
     */
    Incompatibility
    locate_row_misfit(const BlockModel          &model,
                      const MechanismProblem    &problem,
                      const std::vector<double> &row_misfit,
                      const double               velocity_scale,
                      const double               tolerance);
  } // namespace rigid_blocks
} // namespace masonry

#endif
