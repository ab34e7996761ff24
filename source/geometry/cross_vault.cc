#include <masonry/core/parameters.h>
#include <masonry/geometry/arch_profile.h>
#include <masonry/geometry/interface.h>

#include <cmath>

namespace masonry
{
  namespace geometry
  {
    /**
     * A cross (groin) vault over the rectangular bay
     * -Span x/2 <= x <= Span x/2, -Span y/2 <= y <= Span y/2, springing at
     * z = 0 at the four corners (piers), crown at (0, 0, Rise).
     *
     * It is the union of two barrels: barrel A, axis along y, whose
     * cross-section in the (x, z) plane is the circular or pointed profile
     * of ArchProfile (span Span x); barrel B, axis along x, whose
     * cross-section in the (y, z) plane is the same profile stretched
     * horizontally by Span y/Span x (so with Span x = Span y both barrels are
     * circular or pointed; for a rectangular bay barrel B is elliptical or a
     * stretched pointed arch of the same rise). With this classical
     * construction the groins are the diagonals of the bay in plan,
     * |x|/(Span x/2) = |y|/(Span y/2), and every web is an EXACT rational
     * patch: for a profile point (X(u), Z(u)) the web of barrel A over the
     * north wall is the ruling y from Span y/2 (v=0) to
     * (Span y/Span x)|X(u)| (v=1); since |X| is X or -X on each half of the
     * profile, this is a degree (2,1) NURBS with a double knot at the crown
     * u = 1/2. The edges u=0 and u=1 collapse to the piers (degenerate
     * edges), the edge v=1 consists of the two groins meeting at the
     * centre (u = 1/2).
     *
     * Four patches (webs), each over the triangle between one wall and the
     * centre in plan: "north web", "south web" (barrel A, walls
     * y = +-Span y/2), "east web", "west web" (barrel B, walls
     * x = +-Span x/2). Edge labels (u=0, u=1, v=0, v=1):
     * north: "pier north-west", "pier north-east", "wall arch north", "groin";
     * south: "pier south-west", "pier south-east", "wall arch south", "groin";
     * east:  "pier south-east", "pier north-east", "wall arch east", "groin";
     * west:  "pier south-west", "pier north-west", "wall arch west", "groin".
     *
     * Limits: two genuinely circular barrels of different spans intersect
     * in a quartic that no NURBS represents exactly; that case is not
     * offered (barrel B is the affine image of barrel A instead).
     */
    class CrossVault : public Interface
    {
    public:
      /** Declare `Shape`, `Span x`, `Span y`, `Rise`. */
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Shape",
                          "circular",
                          dealii::Patterns::Selection(arch_shape_pattern()),
                          "Profile of the barrel spanning along x: "
                          "`circular' (semicircular or segmental, "
                          "Rise <= Span x/2) or `pointed' (two-centred, "
                          "Rise > Span x/2). The other barrel has the same "
                          "profile stretched by Span y/Span x.");
        prm.declare_entry("Span x",
                          "6",
                          dealii::Patterns::Double(),
                          "Side of the bay along x (m), > 0: the bay is "
                          "-Span x/2 <= x <= Span x/2.");
        prm.declare_entry("Span y",
                          "6",
                          dealii::Patterns::Double(),
                          "Side of the bay along y (m), > 0: the bay is "
                          "-Span y/2 <= y <= Span y/2.");
        prm.declare_entry("Rise",
                          "3",
                          dealii::Patterns::Double(),
                          "Height of the crown of the middle surface above "
                          "the springing (m), common to both barrels.");
      }

      /** Read the entries and build the four webs. */
      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        const ArchProfile p =
          make_arch_profile(parse_arch_shape(prm.get("Shape")),
                            prm.get_double("Span x"),
                            prm.get_double("Rise"),
                            "Span x");
        const double span_y = prm.get_double("Span y");
        AssertThrow(span_y > 0 && std::isfinite(span_y),
                    ExcParameter("Span y", "must be positive (m)."));
        const double ax = p.span / 2, ay = span_y / 2, ratio = ay / ax;

        // the whole profile, left springing - crown - right springing
        const std::array<WeightedPoint2D, 5> c = {
          {p.left[0], p.left[1], p.left[2], p.right[1], p.right[0]}};

        // web(i, v) = control point i at v (0: wall, 1: groin)
        auto web = [&](auto                              point,
                       const std::string                &name,
                       const std::array<std::string, 4> &labels) {
          std::vector<std::vector<dealii::Point<3>>> points(5);
          std::vector<std::vector<double>>           weights(5);
          for (unsigned int i = 0; i < 5; ++i)
            {
              const double abs_x = (i <= 2 ? -c[i].x : c[i].x);
              for (unsigned int v = 0; v < 2; ++v)
                {
                  points[i].push_back(point(c[i].x, abs_x, c[i].z, v));
                  weights[i].push_back(c[i].w);
                }
            }
          return make_patch(make_bspline_surface(
                              points, weights, 2, 1, {0, 0.5, 1}, 2, {0, 1}, 1),
                            name,
                            labels);
        };
        using P = dealii::Point<3>;
        std::vector<Patch> webs;
        webs.push_back(web(
          [&](double x, double abs_x, double z, unsigned int v) {
            return P(x, v == 0 ? ay : ratio * abs_x, z);
          },
          "north web",
          {{"pier north-west",
            "pier north-east",
            "wall arch north",
            "groin"}}));
        webs.push_back(web(
          [&](double x, double abs_x, double z, unsigned int v) {
            return P(v == 0 ? ax : abs_x, ratio * x, z);
          },
          "east web",
          {{"pier south-east", "pier north-east", "wall arch east", "groin"}}));
        webs.push_back(web(
          [&](double x, double abs_x, double z, unsigned int v) {
            return P(x, v == 0 ? -ay : -ratio * abs_x, z);
          },
          "south web",
          {{"pier south-west",
            "pier south-east",
            "wall arch south",
            "groin"}}));
        webs.push_back(web(
          [&](double x, double abs_x, double z, unsigned int v) {
            return P(v == 0 ? -ax : -abs_x, ratio * x, z);
          },
          "west web",
          {{"pier south-west", "pier north-west", "wall arch west", "groin"}}));
        set_patches(webs);
      }
    };
  } // namespace geometry
} // namespace masonry

MASONRY_REGISTER_GEOMETRY_MODEL(
  masonry::geometry::CrossVault,
  "cross vault",
  "A cross (groin) vault over the bay |x| <= Span x/2, |y| <= Span y/2 (m), "
  "crown height Rise (m), springing at z = 0 at the corners: two "
  "intersecting barrels, the one spanning x with a circular or pointed "
  "profile (Shape), the other with the same profile stretched by "
  "Span y/Span x, so that the groins are the diagonals in plan. Four exact "
  "rational patches (webs) `north web', `south web' (over the walls "
  "y = +-Span y/2), `east web', `west web' (walls x = +-Span x/2); u along "
  "the wall arch from pier to pier (u=0 and u=1 are degenerate edges at "
  "the piers), v from the wall (v=0) to the groins (v=1). Edge labels: "
  "`pier north-west' etc. (u=0, u=1), `wall arch north' etc. (v=0), "
  "`groin' (v=1).")
