#include <masonry/core/parameters.h>
#include <masonry/geometry/arch_profile.h>
#include <masonry/geometry/interface.h>

#include <cmath>

namespace masonry
{
  namespace geometry
  {
    /**
     * A barrel vault: the circular or pointed profile of ArchProfile (span
     * along x from -Span/2 to +Span/2, springings at z = 0) extruded along
     * y over 0 <= y <= Length, optionally skewed: x += y tan(Skew angle).
     *
     * Two patches, "west half" (x <= 0 before skewing) and "east half",
     * meeting at the crown. For each: u from the springing (u=0) to the
     * crown (u=1), v from the front gable y=0 (v=0) to the back gable
     * y=Length (v=1). Edge labels (u=0, u=1, v=0, v=1): "springing left"
     * (west) / "springing right" (east), "crown", "gable front",
     * "gable back".
     *
     * `Span` and `Rise` are those of the middle surface, the intrados or
     * the extrados (`Span and rise of`, make_middle_profile()). The
     * defaults are the numbers of the Bothwell Parish Church vault
     * (pointed, span 6.1 m, rise 3.8 m, length 16.8 m), but taken as the
     * middle surface's; the paper gives them for the intrados
     * (prm/examples/bothwell-*.prm set `Span and rise of = intrados`).
     */
    class BarrelVault : public Interface
    {
    public:
      /**
       * Declare `Shape`, `Span`, `Rise`, `Span and rise of`, `Length`,
       * `Skew angle`.
       */
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Shape",
                          "pointed",
                          dealii::Patterns::Selection(arch_shape_pattern()),
                          "Cross-section: `circular' (semicircular for "
                          "Rise = Span/2, segmental below) or `pointed' "
                          "(two-centred, centres on the springing line, "
                          "Rise > Span/2).");
        prm.declare_entry("Span",
                          "6.1",
                          dealii::Patterns::Double(),
                          "Span (m), > 0, of the surface `Span and rise of' "
                          "names (the middle surface by default): it "
                          "springs at x = -Span/2 and x = +Span/2, z = 0.");
        prm.declare_entry("Rise",
                          "3.8",
                          dealii::Patterns::Double(),
                          "Crown height (m) of the surface `Span and rise "
                          "of' names above its springings: <= Span/2 for "
                          "circular, > Span/2 for pointed.");
        declare_reference_surface(prm);
        prm.declare_entry("Length",
                          "16.8",
                          dealii::Patterns::Double(),
                          "Length of the vault along y (m), > 0: from the "
                          "front gable y = 0 to the back gable y = Length.");
        prm.declare_entry("Skew angle",
                          "0",
                          dealii::Patterns::Double(-80, 80),
                          "Skew of the vault (degrees, -80..80): the "
                          "cross-section at y is shifted by y tan(angle) "
                          "along x.");
      }

      /** Read the entries and build the two patches. */
      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        const ReferenceSurface reference =
          parse_reference_surface(prm.get("Span and rise of"));
        const ArchProfile profile =
          make_middle_profile(parse_arch_shape(prm.get("Shape")),
                              prm.get_double("Span"),
                              prm.get_double("Rise"),
                              reference,
                              reference == ReferenceSurface::middle ?
                                0. :
                                constant_thickness("Span and rise of"));
        const double length = prm.get_double("Length");
        AssertThrow(length > 0,
                    ExcParameter("Length", "must be positive (m)."));
        const double shear =
          std::tan(prm.get_double("Skew angle") * M_PI / 180.);
        set_patches(
          {make_patch(
             extrude_arc(profile.left, length, shear),
             "west half",
             {{"springing left", "crown", "gable front", "gable back"}}),
           make_patch(
             extrude_arc(profile.right, length, shear),
             "east half",
             {{"springing right", "crown", "gable front", "gable back"}})});
      }
    };
  } // namespace geometry
} // namespace masonry

MASONRY_REGISTER_GEOMETRY_MODEL(
  masonry::geometry::BarrelVault,
  "barrel vault",
  "A circular or pointed barrel vault of given Span and Rise (m) of its "
  "middle surface, intrados or extrados (`Span and rise of'), extruded "
  "along y over Length (m), optionally skewed by Skew angle (degrees: "
  "x += y tan(angle)). Span along x from -Span/2 to Span/2, springings at "
  "z = 0. Two exact rational patches, `west half' and `east half', meeting "
  "at the crown; u from the springing (u=0) to the crown (u=1), v from "
  "y=0 to y=Length. Edge labels: `springing left' / `springing right' "
  "(u=0), `crown' (u=1), `gable front' (y=0), `gable back' (y=Length). "
  "The defaults are the numbers of the Bothwell Parish Church vault "
  "(pointed, span 6.1 m, rise 3.8 m, length 16.8 m) taken as the middle "
  "surface's; the paper's vault has them at the intrados (`Span and rise "
  "of = intrados', as in prm/examples/bothwell-*.prm).")
