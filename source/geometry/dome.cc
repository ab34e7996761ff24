#include <masonry/core/parameters.h>
#include <masonry/geometry/interface.h>
#include <masonry/geometry/patch_occt.h>

#include <cmath>

namespace masonry
{
  namespace geometry
  {
    /**
     * A spherical dome (hemisphere or spherical cap) of given span and
     * rise: springing circle of radius Span/2 at z = 0 centred on the z
     * axis, pole at (0, 0, Rise). Sphere radius
     * R = (Span^2/4 + Rise^2)/(2 Rise), centre (0, 0, Rise - R).
     *
     * Four patches, the quadrants in plan, each the exact revolution by 90
     * degrees of the rational quadratic meridian arc: a degree (2,2) NURBS
     * (weights: meridian weights times 1, sqrt(2)/2, 1). u runs along the
     * meridian from the springing (u=0) to the pole (u=1, a degenerate
     * edge), v counter-clockwise in plan (seen from above) from one
     * meridian (v=0) to the next (v=1).
     *
     * Names and edge labels (u=0, u=1, v=0, v=1):
     * "quadrant north-east": "springing", "pole", "meridian east",
     * "meridian north"; "quadrant north-west": ..., "meridian north",
     * "meridian west"; "quadrant south-west": "meridian west",
     * "meridian south"; "quadrant south-east": "meridian south",
     * "meridian east" (east = +x, north = +y).
     */
    class Dome : public Interface
    {
    public:
      /** Declare `Span`, `Rise`. */
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Span",
                          "10",
                          dealii::Patterns::Double(),
                          "Diameter of the springing circle of the middle "
                          "surface (m), > 0.");
        prm.declare_entry("Rise",
                          "5",
                          dealii::Patterns::Double(),
                          "Height of the pole above the springing (m): "
                          "0 < Rise <= Span/2; Rise = Span/2 is a "
                          "hemisphere, a lower rise a spherical cap.");
      }

      /** Read the entries and build the four quadrants. */
      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        const double span = prm.get_double("Span");
        const double rise = prm.get_double("Rise");
        AssertThrow(span > 0 && std::isfinite(span),
                    ExcParameter("Span", "must be positive (m)."));
        AssertThrow(rise > 0 && std::isfinite(rise),
                    ExcParameter("Rise", "must be positive (m)."));
        const double a = span / 2;
        AssertThrow(rise <= a * (1 + 1e-14),
                    ExcParameter("Rise",
                                 "a spherical dome needs a rise of at most "
                                 "half the span."));
        const double R  = (a * a + rise * rise) / (2 * rise);
        const double zc = rise - R;
        auto         meridian =
          circular_arc(0, zc, R, std::atan2(0.0 - zc, a), M_PI / 2);
        meridian[0].x = a;
        meridian[0].z = 0;
        meridian[2].x = 0;
        meridian[2].z = rise;

        const std::array<std::string, 4> compass = {
          {"north-east", "north-west", "south-west", "south-east"}};
        const std::array<std::string, 5> meridians = {{"meridian east",
                                                       "meridian north",
                                                       "meridian west",
                                                       "meridian south",
                                                       "meridian east"}};
        std::vector<Patch>               quadrants;
        for (unsigned int k = 0; k < 4; ++k)
          {
            // exact directions: multiples of 90 degrees
            const int    c0[4] = {1, 0, -1, 0}, s0[4] = {0, 1, 0, -1};
            const double d[3][2]           = {{double(c0[k]), double(s0[k])},
                                              {double(c0[k] + c0[(k + 1) % 4]),
                                               double(s0[k] + s0[(k + 1) % 4])},
                                              {double(c0[(k + 1) % 4]),
                                               double(s0[(k + 1) % 4])}};
            const double azimuth_weight[3] = {1, std::sqrt(0.5), 1};
            std::vector<std::vector<dealii::Point<3>>> points(3);
            std::vector<std::vector<double>>           weights(3);
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                {
                  points[i].emplace_back(meridian[i].x * d[j][0],
                                         meridian[i].x * d[j][1],
                                         meridian[i].z);
                  weights[i].push_back(meridian[i].w * azimuth_weight[j]);
                }
            quadrants.push_back(make_patch(
              make_bspline_surface(points, weights, 2, 2, {0, 1}, 1, {0, 1}, 1),
              "quadrant " + compass[k],
              {{"springing", "pole", meridians[k], meridians[k + 1]}}));
          }
        set_patches(quadrants);
      }
    };
  } // namespace geometry
} // namespace masonry

MASONRY_REGISTER_GEOMETRY_MODEL(
  masonry::geometry::Dome,
  "dome",
  "A spherical dome of given Span (diameter of the springing circle, m) and "
  "Rise (m, <= Span/2; = Span/2 for a hemisphere): springing circle at "
  "z = 0 centred on the z axis. Four exact rational patches, the quadrants "
  "`quadrant north-east', `quadrant north-west', `quadrant south-west', "
  "`quadrant south-east' (east = +x, north = +y); u along the meridian "
  "from the springing (u=0) to the pole (u=1, degenerate edge), v "
  "counter-clockwise. Edge labels: `springing' (u=0), `pole' (u=1), "
  "`meridian east' / `meridian north' / `meridian west' / `meridian south' "
  "(v=0, v=1).")
