/**
 * @file
 * The settlement analysis' record of where a support motion cannot be
 * followed (rigid_blocks::SupportCheck, rigid_blocks::Incompatibility) in
 * summary.json, as structured fields a report can show. Private to
 * source/analysis/.
 */
#ifndef masonry_analysis_support_motion_report_h
#define masonry_analysis_support_motion_report_h

#include <masonry/core/json.h>
#include <masonry/rigid_blocks/support_check.h>

namespace masonry
{
  namespace analysis
  {
    /**
     * @p x as an object: `kind`, `block`, `patch`, `centroid` (m),
     * `support_edge` (if any), `other_block` (a joint between blocks),
     * `position` (m), `misfit` (m), `rms_misfit` or, for kind `lp`,
     * `direction` and `total_misfit` (m), `count` and `message` (the
     * one-line description).
     */
    Json
    incompatibility_json(const rigid_blocks::Incompatibility &x);

    /**
     * The numbers of @p check into @p summary: `support_check` (largest
     * misfit and tolerance in m, whether the check is exact, the numbers
     * of supported and fixed groups of blocks) and, if it found one,
     * `incompatibility`.
     */
    void
    record_support_check(const rigid_blocks::SupportCheck &check,
                         Json                             &summary);
  } // namespace analysis
} // namespace masonry

#endif
