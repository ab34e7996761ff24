/**
 * @file
 * Bond `stack': every course the same.
 */
#include <masonry/brickwork/bond.h>

#include "rows.h"

namespace masonry
{
  namespace brickwork
  {
    using rows::stretcher_row;

    /** Every course the same: continuous head joints (for checks). */
    class StackBond : public Bond
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &)
      {}

      std::vector<Box>
      layout(const WalletteSize &s) const override
      {
        std::vector<Box> boxes;
        for (unsigned int c = 0; c < s.courses; ++c)
          stretcher_row(boxes, s, 0, c * s.height, false);
        return boxes;
      }
    };
  } // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_BOND(masonry::brickwork::StackBond,
                      "stack",
                      "Stack bond: every course is a row of whole "
                      "stretchers, so head joints run through the height "
                      "(single thickness; for checks against closed-form "
                      "results).")
