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
      /** Rise (m). */
      double rise;
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
