/**
 * @file
 * Bond `stretcher': single thickness, courses offset by half a brick.
 */
#include <masonry/brickwork/bond.h>

#include "rows.h"

namespace masonry
{
  namespace brickwork
  {
    using rows::stretcher_row;

    /** Single thickness, courses offset by half a brick. */
    class StretcherBond : public Bond
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
          stretcher_row(boxes, s, 0, c * s.height, c % 2 == 1);
        return boxes;
      }
    };
  } // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_BOND(masonry::brickwork::StretcherBond,
                      "stretcher",
                      "Stretcher (running) bond, single thickness (one "
                      "brick width): every other course starts and ends "
                      "with a half bat, so head joints are offset by half "
                      "a brick. The simplified model needs an even number "
                      "of elements along the brick length.")
