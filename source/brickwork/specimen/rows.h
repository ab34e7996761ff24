/**
 * @file
 * The rows the bonds are laid from (the built-in bonds' own helpers).
 */
#ifndef masonry_brickwork_specimen_rows_h
#define masonry_brickwork_specimen_rows_h

#include <masonry/brickwork/bond.h>

#include <string>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    namespace rows
    {
      /** A box from its corner and its extents. */
      Box
      box(const double       x,
          const double       y,
          const double       z,
          const double       dx,
          const double       dy,
          const double       dz,
          const std::string &kind);

      /** A row of stretchers along x, optionally starting and ending with
       * half bats (half a brick offset). */
      void
      stretcher_row(std::vector<Box>   &boxes,
                    const WalletteSize &s,
                    const double        y,
                    const double        z,
                    const bool          offset);

      /** A row of headers (length across the wall, from y to y + length)
       * with a queen closer (half the width) at both ends. */
      void
      header_row(std::vector<Box>   &boxes,
                 const WalletteSize &s,
                 const double        y,
                 const double        z);
    } // namespace rows
  }   // namespace brickwork
} // namespace masonry

#endif
