#include <masonry/core/parameters.h>
#include <masonry/geometry/arch_profile.h>

#include <cmath>
#include <sstream>

namespace masonry
{
  namespace geometry
  {
    std::string
    arch_shape_pattern()
    {
      return "circular|pointed";
    }

    ArchProfile::Shape
    parse_arch_shape(const std::string &name)
    {
      return name == "pointed" ? ArchProfile::Shape::pointed :
                                 ArchProfile::Shape::circular;
    }

    ArchProfile
    make_arch_profile(const ArchProfile::Shape shape,
                      const double             span,
                      const double             rise,
                      const std::string       &span_entry,
                      const std::string       &rise_entry)
    {
      std::ostringstream s;
      s << span;
      AssertThrow(span > 0 && std::isfinite(span),
                  ExcParameter(span_entry,
                               "must be positive (m), not " + s.str() + "."));
      std::ostringstream r;
      r << rise;
      AssertThrow(rise > 0 && std::isfinite(rise),
                  ExcParameter(rise_entry,
                               "must be positive (m), not " + r.str() + "."));
      ArchProfile p;
      p.shape        = shape;
      p.span         = span;
      p.rise         = rise;
      const double a = span / 2;
      if (shape == ArchProfile::Shape::circular)
        {
          AssertThrow(rise <= a * (1 + 1e-14),
                      ExcParameter(rise_entry,
                                   "a circular arch needs a rise of at most "
                                   "half the span (" +
                                     r.str() + " > " + s.str() +
                                     "/2); use the pointed shape for a "
                                     "higher rise."));
          p.radius        = (a * a + rise * rise) / (2 * rise);
          const double zc = rise - p.radius;
          p.centre_left   = {{0, zc}};
          p.centre_right  = {{0, zc}};
          p.left =
            circular_arc(0, zc, p.radius, std::atan2(0.0 - zc, -a), 0.5 * M_PI);
          p.right =
            circular_arc(0, zc, p.radius, std::atan2(0.0 - zc, a), 0.5 * M_PI);
        }
      else
        {
          AssertThrow(rise > a,
                      ExcParameter(rise_entry,
                                   "a pointed (two-centred) arch needs a rise "
                                   "above half the span (" +
                                     r.str() + " <= " + s.str() +
                                     "/2); use the circular shape for a "
                                     "lower rise."));
          const double c = (rise * rise - a * a) / span;
          p.radius       = c + a;
          p.centre_left  = {{c, 0}};
          p.centre_right = {{-c, 0}};
          p.left  = circular_arc(c, 0, p.radius, M_PI, std::atan2(rise, -c));
          p.right = circular_arc(-c, 0, p.radius, 0, std::atan2(rise, c));
        }
      // exact end points (remove round-off of cos/sin)
      for (auto *arc : {&p.left, &p.right})
        {
          (*arc)[0].z = 0;
          (*arc)[2].x = 0;
          (*arc)[2].z = rise;
        }
      p.left[0].x  = -a;
      p.right[0].x = a;
      return p;
    }

    std::string
    reference_surface_pattern()
    {
      return "middle surface|intrados|extrados";
    }

    ReferenceSurface
    parse_reference_surface(const std::string &name)
    {
      return name == "intrados" ? ReferenceSurface::intrados :
             name == "extrados" ? ReferenceSurface::extrados :
                                  ReferenceSurface::middle;
    }

    void
    declare_reference_surface(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        "Span and rise of",
        "middle surface",
        dealii::Patterns::Selection(reference_surface_pattern()),
        "The surface whose span and rise `Span' and `Rise' give (m): "
        "`middle surface' (the surface the blocks are built on), "
        "`intrados' (the inner surface: a surveyed interior span and rise) "
        "or `extrados' (the outer surface). That surface springs at "
        "x = -Span/2 and x = +Span/2, z = 0, with its crown at z = Rise; "
        "the other two are its offsets by half the Thickness along the "
        "normal (arcs of the same centres, radii differing by Thickness/2, "
        "on the same radial joints at the springings), so with `intrados' "
        "the middle surface of a pointed profile has the span Span + "
        "Thickness and of a semicircular one the span Span + Thickness and "
        "the rise Rise + Thickness/2. `intrados' and `extrados' need a "
        "constant Thickness (a number). The minimum thickness analysis "
        "keeps the middle surface found here and scales the thickness "
        "about it.");
    }

    ArchProfile
    make_middle_profile(const ArchProfile::Shape shape,
                        const double             span,
                        const double             rise,
                        const ReferenceSurface   reference,
                        const double             thickness,
                        const std::string       &reference_entry,
                        const std::string       &span_entry,
                        const std::string       &rise_entry)
    {
      const ArchProfile given =
        make_arch_profile(shape, span, rise, span_entry, rise_entry);
      if (reference == ReferenceSurface::middle)
        return given;
      // the middle surface is half a thickness outside the intrados and
      // inside the extrados; the intrados is a whole thickness inside the
      // extrados
      const double offset =
        (reference == ReferenceSurface::intrados ? 0.5 : -0.5) * thickness;
      const double       radius = given.radius + offset;
      std::ostringstream t;
      t << thickness;
      if (shape == ArchProfile::Shape::circular)
        {
          AssertThrow(radius - 0.5 * thickness > 0,
                      ExcParameter(reference_entry,
                                   "the Thickness (" + t.str() +
                                     " m) is at least the radius of the "
                                     "extrados: no intrados is left."));
          // concentric arcs on the same radial lines: the reference
          // profile scaled about its centre (0, zc)
          const double zc = given.centre_left[1];
          const double k  = radius / given.radius;
          ArchProfile  p  = make_arch_profile(
            shape, k * span, k * rise, span_entry, rise_entry);
          p.springing_height = zc * (1 - k);
          for (auto *arc : {&p.left, &p.right})
            for (auto &point : *arc)
              point.z += p.springing_height;
          p.centre_left[1] += p.springing_height;
          p.centre_right[1] += p.springing_height;
          return p;
        }
      // pointed: the centres (±c, 0) stay on the springing line
      const double c = given.centre_left[0];
      AssertThrow(radius - 0.5 * thickness > c,
                  ExcParameter(reference_entry,
                               "the Thickness (" + t.str() +
                                 " m) is at least half the span of the "
                                 "extrados: no intrados is left."));
      return make_arch_profile(shape,
                               2 * (radius - c),
                               std::sqrt(radius * radius - c * c),
                               span_entry,
                               rise_entry);
    }

    Handle(Geom_BSplineSurface)
      extrude_arc(const std::array<WeightedPoint2D, 3> &arc,
                  const double                          length,
                  const double                          shear)
    {
      std::vector<std::vector<dealii::Point<3>>> points(3);
      std::vector<std::vector<double>>           weights(3);
      for (unsigned int i = 0; i < 3; ++i)
        for (const double y : {0., length})
          {
            points[i].emplace_back(arc[i].x + y * shear, y, arc[i].z);
            weights[i].push_back(arc[i].w);
          }
      return make_bspline_surface(points, weights, 2, 1, {0, 1}, 1, {0, 1}, 1);
    }
  } // namespace geometry
} // namespace masonry
