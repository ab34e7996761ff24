#include <masonry/core/parameters.h>
#include <masonry/geometry/arch_profile.h>
#include <masonry/geometry/interface.h>

namespace masonry
{
  namespace geometry
  {
    /**
     * A strip of an arch: the profile of ArchProfile (span along x from
     * -Span/2 to +Span/2, springings at z = 0, crown at (0, Rise), for the
     * middle surface, the intrados or the extrados: `Span and rise of`,
     * make_middle_profile()) extruded over the depth y in [0, Depth].
     *
     * Two patches, "left half" (x <= 0) and "right half" (x >= 0), so that
     * the crown of a pointed arch is a patch edge. For each: u from the
     * springing (u=0) to the crown (u=1), v from the front face y=0 (v=0)
     * to the back face y=Depth (v=1). Edge labels (u=0, u=1, v=0, v=1):
     * "springing left"/"springing right", "crown", "face front",
     * "face back".
     */
    class Arch : public Interface
    {
    public:
      /** Declare `Shape`, `Span`, `Rise`, `Span and rise of`, `Depth`. */
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Shape",
                          "circular",
                          dealii::Patterns::Selection(arch_shape_pattern()),
                          "`circular': semicircular (Rise = Span/2) or "
                          "segmental (Rise < Span/2) arch; `pointed': "
                          "two-centred arch with both centres on the "
                          "springing line (Rise > Span/2).");
        prm.declare_entry("Span",
                          "4",
                          dealii::Patterns::Double(),
                          "Span (m), > 0, of the surface `Span and rise of' "
                          "names (the middle surface by default): it "
                          "springs at x = -Span/2 and x = +Span/2, z = 0.");
        prm.declare_entry("Rise",
                          "2",
                          dealii::Patterns::Double(),
                          "Crown height (m) of the surface `Span and rise "
                          "of' names above its springings: 0 < Rise <= "
                          "Span/2 for a circular arch, Rise > Span/2 for a "
                          "pointed one.");
        declare_reference_surface(prm);
        prm.declare_entry("Depth",
                          "1",
                          dealii::Patterns::Double(),
                          "Depth of the strip of arch (m) along y, > 0: the "
                          "arch occupies 0 <= y <= Depth.");
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
        const double depth = prm.get_double("Depth");
        AssertThrow(depth > 0, ExcParameter("Depth", "must be positive (m)."));
        set_patches(
          {make_patch(extrude_arc(profile.left, depth, 0),
                      "left half",
                      {{"springing left", "crown", "face front", "face back"}}),
           make_patch(
             extrude_arc(profile.right, depth, 0),
             "right half",
             {{"springing right", "crown", "face front", "face back"}})});
      }
    };
  } // namespace geometry
} // namespace masonry

MASONRY_REGISTER_GEOMETRY_MODEL(
  masonry::geometry::Arch,
  "arch",
  "A strip of a circular (semicircular or segmental) or pointed "
  "(two-centred) arch of given Span, Rise (of the middle surface, the "
  "intrados or the extrados: `Span and rise of') and Depth (m): span along "
  "x from "
  "-Span/2 to Span/2, springings at z = 0, depth along y from 0 to Depth. "
  "Two exact rational patches, `left half' and `right half', with u from "
  "the springing (u=0) to the crown (u=1) and v across the depth. Edge "
  "labels: `springing left' / `springing right' (u=0), `crown' (u=1), "
  "`face front' (y=0), `face back' (y=Depth).")
