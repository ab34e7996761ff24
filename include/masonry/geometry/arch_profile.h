/**
 * @file
 * Circular and pointed arch profiles as exact rational quadratic arcs, shared
 * by the arch, barrel vault and cross vault models.
 */
#ifndef masonry_geometry_arch_profile_h
#define masonry_geometry_arch_profile_h

#include <masonry/geometry/patch_occt.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace masonry
{
  namespace geometry
  {
    /**
     * The cross-section of an arch or barrel in the (x, z) plane: span from
     * x = -span/2 (left springing) to x = +span/2 (right springing), both at
     * z = 0, crown at (0, rise).
     *
     * - circular: one circle through the springings and the crown, radius
     *   R = (span^2/4 + rise^2)/(2 rise), centre (0, rise - R); semicircular
     *   for rise = span/2, segmental for rise < span/2.
     * - pointed: two-centred arch, centres on the springing line: the left
     *   half has its centre at (c, 0), the right half at (-c, 0), with
     *   c = (rise^2 - span^2/4)/span and R = c + span/2
     *   = (span^2/4 + rise^2)/span (needs rise > span/2).
     */
    struct ArchProfile
    {
      /** The shape of the profile. */
      enum class Shape
      {
        /** Semicircular or segmental. */
        circular,
        /** Two-centred pointed arch. */
        pointed
      };

      /** The shape. */
      Shape shape;
      /** Span (m). */
      double span;
      /** Rise (m), above the springings. */
      double rise;
      /**
       * Height of the springings (m): 0, except for the middle surface of
       * a segmental arch whose intrados or extrados springs at z = 0
       * (make_middle_profile()).
       */
      double springing_height = 0;
      /** Radius of the circle(s) (m). */
      double radius;
      /** Centres (x, z) of the left and right halves (m). */
      std::array<double, 2> centre_left, centre_right;
      /**
       * The rational quadratic Bezier arcs of the halves, each from its
       * springing to the crown.
       */
      std::array<WeightedPoint2D, 3> left, right;
    };

    /** "circular|pointed". */
    std::string
    arch_shape_pattern();

    /** Convert "circular" or "pointed". */
    ArchProfile::Shape
    parse_arch_shape(const std::string &name);

    /**
     * Build the profile; throws ExcParameter naming @p span_entry or
     * @p rise_entry (entries of the subsection being parsed) for a
     * non-positive span or rise, a circular rise above span/2 or a pointed
     * rise at or below span/2.
     */
    ArchProfile
    make_arch_profile(const ArchProfile::Shape shape,
                      const double             span,
                      const double             rise,
                      const std::string       &span_entry = "Span",
                      const std::string       &rise_entry = "Rise");

    /**
     * The surface whose span and rise a model's `Span' and `Rise' give.
     */
    enum class ReferenceSurface
    {
      /** The middle surface, on which the blocks are built. */
      middle,
      /** The inner (lower, visible) surface. */
      intrados,
      /** The outer (upper) surface. */
      extrados
    };

    /** "middle surface|intrados|extrados". */
    std::string
    reference_surface_pattern();

    /** Convert a value of reference_surface_pattern(). */
    ReferenceSurface
    parse_reference_surface(const std::string &name);

    /**
     * Declare the entry `Span and rise of' (in the model's subsection):
     * which surface `Span' and `Rise' describe.
     */
    void
    declare_reference_surface(dealii::ParameterHandler &prm);

    /**
     * The profile of the middle surface of an arch or barrel of constant
     * @p thickness (m) whose @p reference surface has the given @p shape,
     * @p span and @p rise (m), springing at x = ∓span/2, z = 0, its crown
     * at z = rise. Intrados, middle surface and extrados are offsets of
     * each other along the normal by half the thickness: for these
     * profiles, arcs of the same centres with radii differing by
     * thickness/2, ending on the same radial lines. So the middle surface
     * of a pointed arch is the pointed arch of the same centres on the
     * springing line with radius R ± t/2 (span ± t); that of a circular
     * arch is the reference profile scaled by (R ± t/2)/R about its
     * centre (a segmental arch then springs off z = 0:
     * ArchProfile::springing_height). Throws ExcParameter naming
     * @p reference_entry if the thickness leaves no intrados (a radius or,
     * for a pointed arch, a half-span at most the thickness), and as
     * make_arch_profile() for the span and rise.
     */
    ArchProfile
    make_middle_profile(const ArchProfile::Shape shape,
                        const double             span,
                        const double             rise,
                        const ReferenceSurface   reference,
                        const double             thickness,
                        const std::string       &reference_entry = "Span and "
                                                                   "rise of",
                        const std::string       &span_entry      = "Span",
                        const std::string       &rise_entry      = "Rise");

    /**
     * The degree (2,1) surface (x + y tan(skew), y, z) for (x, z) on the
     * half-arc @p arc (u: springing to crown) and y in [0, @p length]
     * (v). @p shear is tan(skew).
     */
    Handle(Geom_BSplineSurface)
      extrude_arc(const std::array<WeightedPoint2D, 3> &arc,
                  const double                          length,
                  const double                          shear);
  } // namespace geometry
} // namespace masonry

#endif
