/**
 * @file
 * Bond `english': headers and stretchers, double or triple thickness.
 */
#include <masonry/brickwork/bond.h>
#include <masonry/core/parameters.h>

#include <cmath>
#include <sstream>

#include "rows.h"

namespace masonry
{
  namespace brickwork
  {
    using rows::header_row;
    using rows::stretcher_row;

    /** English bond, double or triple thickness. */
    class EnglishBond : public Bond
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        prm.declare_entry(
          "Thickness",
          "double",
          dealii::Patterns::Selection("double|triple"),
          "`double': one brick length thick (two brick widths plus a "
          "joint, 215 mm for 215 x 102.5 mm bricks): courses of two "
          "wythes of stretchers (with a longitudinal collar joint) "
          "alternate with courses of headers. `triple': one and a half "
          "bricks thick (327.5 mm): every course has a wythe of stretchers "
          "and a wythe of headers, on the front face in one course and on "
          "the back face in the next. Header wythes end with a queen "
          "closer (a brick halved along its length) at both ends of the "
          "wallette. The bond needs brick length + joint = 2 x (brick "
          "width + joint).");
      }

      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        triple = prm.get("Thickness") == "triple";
      }

      std::vector<Box>
      layout(const WalletteSize &s) const override
      {
        // headers lie across the wall: a header (length + joint) must
        // match two stretcher widths (width + joint). The error names the
        // first of the three entries that the file sets (the bricks are
        // laid while `subsection Wallette' is parsed, so with its line).
        if (std::abs(s.length - 2 * s.width) > 1e-9 * s.length)
          {
            std::string blame = "Brick width";
            for (const char *e :
                 {"Brick width", "Brick length", "Joint thickness"})
              if (parameter_is_set("Wallette/" + std::string(e)))
                {
                  blame = e;
                  break;
                }
            std::ostringstream m;
            m << "the english bond needs brick length + joint = 2 x (brick "
                 "width + joint); got "
              << s.length << " m and 2 x " << s.width
              << " m (set Brick length, Brick width and Joint thickness to "
                 "match)";
            throw ExcParameter(blame, m.str());
          }
        std::vector<Box> boxes;
        for (unsigned int c = 0; c < s.courses; ++c)
          {
            const double z = c * s.height;
            if (!triple)
              {
                if (c % 2 == 0)
                  {
                    stretcher_row(boxes, s, 0, z, false);
                    stretcher_row(boxes, s, s.width, z, false);
                  }
                else
                  header_row(boxes, s, 0, z);
              }
            else
              {
                if (c % 2 == 0)
                  {
                    stretcher_row(boxes, s, 0, z, false);
                    header_row(boxes, s, s.width, z);
                  }
                else
                  {
                    header_row(boxes, s, 0, z);
                    stretcher_row(boxes, s, s.length, z, false);
                  }
              }
          }
        return boxes;
      }

    private:
      bool triple = false;
    };
  } // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_BOND(masonry::brickwork::EnglishBond,
                      "english",
                      "English bond, double or triple thickness: courses of "
                      "headers and stretchers with queen closers (see "
                      "Thickness). The simplified model needs a number of "
                      "elements along the brick length that is a multiple "
                      "of 4.")
