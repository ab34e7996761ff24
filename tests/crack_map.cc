// The developed intrados of the crack map (rigid_blocks::postprocess::
// DevelopedSurface), against the arc lengths of the intrados computed here
// from the circles alone: the paper's Bothwell vault (intrados span 6.1 m,
// rise 3.8 m, thickness 0.36 m, length 16.8 m) is a pointed barrel whose
// halves' intrados are arcs of radius R_i = c + 3.05 m about (-+c, 0),
// c = (3.8^2 - 3.05^2)/6.1 m, from the springing (angle pi about the west
// centre) to the radial line through the middle surface's crown, at angle
// atan2(H_m, -c) with H_m the middle surface's rise, sqrt(R_m^2 - c^2),
// R_m = R_i + 0.18 m. The west half must map to 0 <= s <= R_i * sweep, the
// east half, glued at the crown, mirrored next to it up to twice that
// length, and t must run along the vault's length; the parameter lines of
// the blocks map to the arc lengths of their points.

#include <masonry/rigid_blocks/block_model.h>
#include <masonry/rigid_blocks/postprocess/crack_map.h>

#include "geometry_common.h"

using namespace masonry;

int
main()
{
  std::cout << std::setprecision(10);
  const auto                   vault = test::create("barrel vault",
                                  "set Span and rise of = intrados",
                                  "set Thickness = 0.36");
  rigid_blocks::Discretisation options;
  options.n_u = 3;
  options.n_v = 4;
  const rigid_blocks::BlockModel                    model(*vault, options);
  const rigid_blocks::postprocess::DevelopedSurface map(model);

  const double s = 6.1, r = 3.8, t = 0.36, L = 16.8;
  const double c = (r * r - s * s / 4) / s, Ri = c + s / 2, Rm = Ri + t / 2;
  const double crown = std::atan2(std::sqrt(Rm * Rm - c * c), -c);
  const double half  = Ri * (M_PI - crown);
  std::cout << "intrados of a half: " << half << " m" << std::endl;

  // chords of 64 samples: the error of the arc is about half (pi/2/64)^2/24
  const double tol = 1e-3;
  const auto   at  = [&](unsigned int p, double u, double v) {
    return map.map(p, dealii::Point<2>(u, v));
  };
  test::check_close(at(0, 0, 0)[0], 0, 1e-12, "west springing at s = 0");
  test::check_close(at(0, 1, 0)[0], half, tol, "west crown at s = R_i sweep");
  test::check_close(at(1, 1, 0)[0], half, tol, "east crown at the west crown");
  test::check_close(at(1, 0, 0)[0],
                    2 * half,
                    tol,
                    "east springing at s = 2 R_i sweep (mirrored)");
  test::check_close(at(0, 0.5, 1)[1], L, 1e-9, "t runs along the length");
  test::check_close(at(1, 0.5, 1)[1], L, 1e-9, "east half: same t");
  // a parameter line u = const maps to the arc length of its intrados
  // point: the angle of the middle surface point about the west centre
  for (const double u : {1. / 3, 2. / 3})
    {
      const auto   x     = vault->patches()[0].point(dealii::Point<2>(u, 0));
      const double angle = std::atan2(x[2], x[0] - c);
      test::check_close(at(0, u, 0.5)[0],
                        Ri * (M_PI - angle),
                        tol,
                        "block line u = " + std::to_string(u).substr(0, 5) +
                          " at its arc length");
    }
  // every interface's ends lie on the map of its patch
  unsigned int inside = 0;
  for (const auto &i : model.interfaces())
    {
      const auto a = map.map(i.patch, i.edge[0]),
                 b = map.map(i.patch, i.edge[1]);
      inside += a[0] >= -1e-12 && b[0] <= 2 * half + tol && a[1] >= -1e-12 &&
                b[1] <= L + 1e-9;
    }
  test::check(inside == model.interfaces().size(),
              "every interface on the map (" + std::to_string(inside) + ")");
  return test::failures();
}
