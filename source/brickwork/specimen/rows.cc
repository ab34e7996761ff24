/**
 * @file
 * The rows the bonds are laid from.
 */
#include "rows.h"

namespace masonry
{
  namespace brickwork
  {
    namespace rows
    {
      Box
      box(const double       x,
          const double       y,
          const double       z,
          const double       dx,
          const double       dy,
          const double       dz,
          const std::string &kind)
      {
        return {{{x, y, z}}, {{x + dx, y + dy, z + dz}}, kind};
      }

      void
      stretcher_row(std::vector<Box>   &boxes,
                    const WalletteSize &s,
                    const double        y,
                    const double        z,
                    const bool          offset)
      {
        double x = 0;
        if (offset)
          {
            boxes.push_back(
              box(x, y, z, s.length / 2, s.width, s.height, "half bat"));
            x += s.length / 2;
          }
        const unsigned int n = offset ? s.bricks_long - 1 : s.bricks_long;
        for (unsigned int i = 0; i < n; ++i, x += s.length)
          boxes.push_back(
            box(x, y, z, s.length, s.width, s.height, "stretcher"));
        if (offset)
          boxes.push_back(
            box(x, y, z, s.length / 2, s.width, s.height, "half bat"));
      }

      void
      header_row(std::vector<Box>   &boxes,
                 const WalletteSize &s,
                 const double        y,
                 const double        z)
      {
        double x = 0;
        boxes.push_back(
          box(x, y, z, s.width / 2, s.length, s.height, "closer"));
        x += s.width / 2;
        for (unsigned int i = 0; i + 1 < 2 * s.bricks_long; ++i, x += s.width)
          boxes.push_back(box(x, y, z, s.width, s.length, s.height, "header"));
        boxes.push_back(
          box(x, y, z, s.width / 2, s.length, s.height, "closer"));
      }
    } // namespace rows
  }   // namespace brickwork
} // namespace masonry
