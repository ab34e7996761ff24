/**
 * @file
 * The bond interface and the bonds `stack`, `stretcher` and `english`.
 */
#include <masonry/brickwork/bond.h>
#include <masonry/core/parameters.h>

#include <cmath>
#include <sstream>

namespace masonry
{
  namespace brickwork
  {
    const char *
    Bond::default_plugin()
    {
      return "stretcher";
    }

    std::string
    Bond::selection_documentation()
    {
      return "The bond pattern of the wallette: how the enlarged bricks "
             "(brick plus half a joint on every side) are laid. x runs along "
             "the wall, y across it, z up; the wallette stands on z = 0.";
    }

    void
    Bond::declare_common_parameters(dealii::ParameterHandler &)
    {}

    void
    Bond::parse_common_parameters(dealii::ParameterHandler &)
    {}

    void
    Bond::parse_parameters(dealii::ParameterHandler &)
    {}

    namespace
    {
      /** A box from its corner and its extents. */
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

      /** A row of stretchers along x, optionally starting and ending with
       * half bats (half a brick offset). */
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

      /** A row of headers (length across the wall, from y to y + length)
       * with a queen closer (half the width) at both ends. */
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
    } // namespace

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

MASONRY_REGISTER_BOND(masonry::brickwork::StackBond,
                      "stack",
                      "Stack bond: every course is a row of whole "
                      "stretchers, so head joints run through the height "
                      "(single thickness; for checks against closed-form "
                      "results).")
MASONRY_REGISTER_BOND(masonry::brickwork::StretcherBond,
                      "stretcher",
                      "Stretcher (running) bond, single thickness (one "
                      "brick width): every other course starts and ends "
                      "with a half bat, so head joints are offset by half "
                      "a brick. Needs an even number of elements along the "
                      "brick length.")
MASONRY_REGISTER_BOND(masonry::brickwork::EnglishBond,
                      "english",
                      "English bond, double or triple thickness: courses of "
                      "headers and stretchers with queen closers (see "
                      "Thickness). Needs a number of elements along the "
                      "brick length that is a multiple of 4.")
