// The "cross vault" geometry model: every web lies on its barrel, the webs
// meet along the groins (shared edge points coincide), degenerate pier
// edges, labels, area of a square semicircular groin vault.

#include "geometry_common.h"

using namespace masonry;

namespace
{
  void
  check_vault(const geometry::Interface &vault,
              const double               ax,
              const double               ay,
              const std::string         &what,
              // distance of (s, z) from the profile of span 2 ax
              const std::function<double(double, double)> &off_profile)
  {
    const auto &w = vault.patches();
    test::check(w.size() == 4, what + ": four webs");
    // north/south webs are barrel A (section in x,z), east/west barrel B
    // (section in y,z, stretched by ay/ax)
    double err = 0;
    for (unsigned int k = 0; k < 4; ++k)
      for (unsigned int i = 0; i <= 20; ++i)
        for (unsigned int j = 0; j <= 10; ++j)
          {
            const auto x = w[k].point({i / 20., j / 10.});
            const bool a =
              (w[k].name() == "north web" || w[k].name() == "south web");
            err =
              std::max(err,
                       std::abs(off_profile(a ? x[0] : x[1] * ax / ay, x[2])));
          }
    test::check(err < 1e-12, what + ": webs lie on their barrels");

    // groins: the v=1 edges; the north and east webs meet for u in
    // [1/2, 1] (north-east groin), and so on; the groin is the diagonal
    // |x|/ax = |y|/ay in plan
    auto web = [&](const std::string &name) -> const geometry::Patch & {
      for (const auto &p : w)
        if (p.name() == name)
          return p;
      throw std::runtime_error("no web " + name);
    };
    struct Pair
    {
      std::string a, b;
      bool        a_upper, b_upper;
    };
    const Pair pairs[4] = {{"north web", "east web", true, true},
                           {"north web", "west web", false, true},
                           {"south web", "east web", true, false},
                           {"south web", "west web", false, false}};
    double     err_meet = 0, err_diag = 0;
    for (const auto &pair : pairs)
      for (unsigned int i = 0; i <= 10; ++i)
        {
          const double ua = pair.a_upper ? 0.5 + i / 20. : 0.5 - i / 20.;
          const double ub = pair.b_upper ? 0.5 + i / 20. : 0.5 - i / 20.;
          const auto   xa = web(pair.a).point({ua, 1});
          const auto   xb = web(pair.b).point({ub, 1});
          err_meet        = std::max(err_meet, xa.distance(xb));
          err_diag =
            std::max(err_diag,
                     std::abs(std::abs(xa[0]) / ax - std::abs(xa[1]) / ay));
        }
    test::check(err_meet < 1e-12,
                what + ": neighbouring webs meet along the groins (1e-12)");
    test::check(err_diag < 1e-12, what + ": groins are diagonals in plan");

    // piers: u=0 and u=1 edges collapse to the corners at z = 0
    double err_pier = 0;
    for (const auto &p : w)
      for (unsigned int e = 0; e < 2; ++e)
        {
          const auto c = p.point({double(e), 0.});
          for (unsigned int j = 0; j <= 10; ++j)
            err_pier =
              std::max(err_pier, p.point({double(e), j / 10.}).distance(c));
          const std::string l  = p.edge_labels()[e];
          const double      sx = (l.find("east") != std::string::npos ? 1 : -1);
          const double sy = (l.find("north") != std::string::npos ? 1 : -1);
          err_pier =
            std::max(err_pier,
                     c.distance(dealii::Point<3>(sx * ax, sy * ay, 0)));
        }
    test::check(err_pier < 1e-12,
                what + ": pier edges are degenerate, at the labelled corners");
    // wall arches: v=0 on the wall
    double err_wall = 0;
    for (const auto &p : w)
      for (unsigned int i = 0; i <= 10; ++i)
        {
          const auto        x = p.point({i / 10., 0.});
          const std::string l = p.edge_labels()[2];
          if (l == "wall arch north")
            err_wall = std::max(err_wall, std::abs(x[1] - ay));
          else if (l == "wall arch south")
            err_wall = std::max(err_wall, std::abs(x[1] + ay));
          else if (l == "wall arch east")
            err_wall = std::max(err_wall, std::abs(x[0] - ax));
          else if (l == "wall arch west")
            err_wall = std::max(err_wall, std::abs(x[0] + ax));
          else
            err_wall = 1;
        }
    test::check(err_wall < 1e-14, what + ": wall arches on the walls");
    // normals up at the crown (limit from inside) and outward
    bool up = true;
    for (const auto &p : w)
      up = up && p.normal({0.25, 0.5})[2] > 0 && p.normal({0.5, 0.5})[2] > 0 &&
           p.normal({0.75, 0.5})[2] > 0;
    test::check(up, what + ": normals point up (extrados)");
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(12);
  {
    const auto vault =
      test::create("cross vault",
                   "set Shape = circular\nset Span x = 6\nset Span y = 6\n"
                   "set Rise = 3");
    check_vault(*vault, 3, 3, "square semicircular", [](double s, double z) {
      return std::hypot(s, z) - 3;
    });
    const std::array<std::string, 4> north = {
      {"pier north-west", "pier north-east", "wall arch north", "groin"}};
    const std::array<std::string, 4> east = {
      {"pier south-east", "pier north-east", "wall arch east", "groin"}};
    test::check(vault->patches()[0].name() == "north web" &&
                  vault->patches()[0].edge_labels() == north &&
                  vault->patches()[1].name() == "east web" &&
                  vault->patches()[1].edge_labels() == east,
                "names and edge labels");
    // area of a square semicircular groin vault of radius R:
    // 4 webs; the north web is {x^2 + z^2 = R^2, |x| <= y <= R}; with
    // x = R cos t the area element is R dt dy, y from R|cos t| to R:
    // area = 4 * int_0^pi R (R - R|cos t|) dt = 4 R^2 (pi - 2)
    const double R = 3, exact = 4 * R * R * (M_PI - 2);
    std::cout << "square semicircular groin vault area, exact 4 R^2 (pi-2) = "
              << exact << std::endl;
    for (const unsigned int n : {2, 4, 8, 16, 24})
      {
        double a = 0;
        for (const auto &p : vault->patches())
          a += test::area(p, n, 2);
        const double e = std::abs(a - exact);
        std::cout << "  Gauss " << std::setw(2) << n << "x" << std::setw(2) << n
                  << " on 2x2 cells (crown knot): error "
                  << (e < 1e-11 ? std::string("< 1e-11") : test::rounded(e, 1))
                  << std::endl;
      }
    double a = 0;
    for (const auto &p : vault->patches())
      a += test::area(p, 24, 2);
    test::check_close(a, exact, 1e-10, "area = 4 R^2 (pi - 2)");
  }
  {
    // rectangular, pointed: barrel A is the pointed profile of span 6.1 and
    // rise 3.8 (centres (+-c, 0), radius R); barrel B its stretch
    const double s = 6.1, r = 3.8;
    const double c = (r * r - s * s / 4) / s, R = (s * s / 4 + r * r) / s;
    const auto   vault =
      test::create("cross vault",
                   "set Shape = pointed\nset Span x = 6.1\nset Span y = 8\n"
                   "set Rise = 3.8");
    check_vault(
      *vault, s / 2, 4, "rectangular pointed", [&](double x, double z) {
        return std::hypot(std::abs(x) - (-c), z) - R;
      });
  }
  return test::failures();
}
