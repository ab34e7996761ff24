#include <masonry/core/parameters.h>
#include <masonry/geometry/interface.h>
#include <masonry/geometry/patch_occt.h>

namespace masonry
{
  namespace geometry
  {
    /**
     * A flat rectangular panel (a wall or a slab) as one bilinear patch: the
     * simplest block geometry, for checks against the statics of a single
     * block or a cantilever.
     */
    class Panel : public Interface
    {
    public:
      /** Declare `Orientation`, `Length`, `Width`. */
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Orientation",
                          "vertical",
                          dealii::Patterns::Selection("vertical|horizontal"),
                          "`vertical': a wall, middle surface in the plane "
                          "y = 0, x from 0 to Length, z from 0 to Width "
                          "(the height), thickness along y. `horizontal': a "
                          "slab, middle surface in the plane z = 0, x from 0 "
                          "to Length, y from 0 to Width, thickness along z.");
        prm.declare_entry("Length",
                          "1",
                          dealii::Patterns::Double(),
                          "Size along x (m), > 0 (u runs along it).");
        prm.declare_entry("Width",
                          "1",
                          dealii::Patterns::Double(),
                          "Size along z for a vertical panel (its height) or "
                          "along y for a horizontal one (m), > 0 (v runs "
                          "along it).");
      }

      /** Read the entries and build the patch. */
      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        const double length   = prm.get_double("Length");
        const double width    = prm.get_double("Width");
        const bool   vertical = prm.get("Orientation") == "vertical";
        AssertThrow(length > 0,
                    ExcParameter("Length", "must be positive (m)."));
        AssertThrow(width > 0, ExcParameter("Width", "must be positive (m)."));
        std::vector<std::vector<dealii::Point<3>>> points(2);
        std::vector<std::vector<double>>           weights(2, {1., 1.});
        for (unsigned int i = 0; i < 2; ++i)
          for (const double w : {0., width})
            points[i].push_back(vertical ? dealii::Point<3>(i * length, 0, w) :
                                           dealii::Point<3>(i * length, w, 0));
        const auto surface =
          make_bspline_surface(points, weights, 1, 1, {0, 1}, 1, {0, 1}, 1);
        // vertical: (d/du × d/dv) = x × z = −y, so the extrados (+y) is the
        // reversed normal; horizontal: x × y = +z
        set_patches({make_patch(
          surface,
          "panel",
          vertical ?
            std::array<std::string, 4>{{"left", "right", "base", "top"}} :
            std::array<std::string, 4>{{"left", "right", "front", "back"}},
          vertical ? NormalOrientation::reversed :
                     NormalOrientation::as_parametrised)});
      }
    };
  } // namespace geometry
} // namespace masonry

MASONRY_REGISTER_GEOMETRY_MODEL(
  masonry::geometry::Panel,
  "panel",
  "A flat rectangular wall or slab of given Length and Width (m) as one "
  "bilinear patch; u along x (0 to Length), v along z (vertical: 0 to "
  "Width, the height) or y (horizontal: 0 to Width). The normal towards "
  "the extrados is +y (vertical) or +z (horizontal). Edge labels (u=0, "
  "u=1, v=0, v=1): `left', `right', `base', `top' (vertical) or `left', "
  "`right', `front', `back' (horizontal). For checks against the statics "
  "of single blocks and cantilevers.")
