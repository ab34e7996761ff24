// The "arch" geometry model: the patches lie on the theoretical circles, the
// normals are unit and radial (pointing away from the centre, i.e. to the
// extrados), the arc length of a half semicircle is pi R/2, edge labels.

#include "geometry_common.h"

using namespace masonry;

namespace
{
  // Check that the patches of @p model lie on the circles with centres
  // (cx[k], 0, cz[k]) in the xz plane and radius R (patch k), that y = v*depth
  // and that the normal is (x - c)/R.
  void
  check_circles(const geometry::Interface &model,
                const double               cx[2],
                const double               cz[2],
                const double               R,
                const double               depth,
                const std::string         &what)
  {
    double err_r = 0, err_y = 0, err_n = 0, err_unit = 0;
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int i = 0; i <= 10; ++i)
        for (unsigned int j = 0; j <= 10; ++j)
          {
            const dealii::Point<2>     uv(i / 10., j / 10.);
            const auto                 x = model.patches()[k].point(uv);
            const auto                 n = model.patches()[k].normal(uv);
            const dealii::Tensor<1, 3> radial({x[0] - cx[k], 0., x[2] - cz[k]});
            err_r    = std::max(err_r, std::abs(radial.norm() - R));
            err_y    = std::max(err_y, std::abs(x[1] - uv[1] * depth));
            err_unit = std::max(err_unit, std::abs(n.norm() - 1));
            err_n    = std::max(err_n, (n - radial / R).norm());
          }
    test::check(err_r < 1e-12, what + ": points on the circle(s) to 1e-12");
    test::check(err_y < 1e-12, what + ": y = v * depth");
    test::check(err_unit < 1e-12, what + ": normals are unit vectors");
    test::check(err_n < 1e-12,
                what + ": normals radial, pointing away from the centre");
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(12);
  {
    // semicircle: R = span/2, centre at the middle of the springing line
    const auto   arch  = test::create("arch",
                                   "set Shape = circular\nset Span = 4\n"
                                      "set Rise = 2\nset Depth = 0.5");
    const double R     = 2;
    const double cx[2] = {0, 0}, cz[2] = {0, 0};
    test::check(arch->patches().size() == 2, "semicircle: two patches");
    check_circles(*arch, cx, cz, R, 0.5, "semicircle");

    // arc length of a half: pi R / 2; n-point Gauss on [0,1] of |dx/du|
    std::cout << "half semicircle arc length, exact pi R/2 = " << M_PI * R / 2
              << std::endl;
    for (const unsigned int n : {2, 4, 8, 16, 24})
      {
        const double l = test::length_u(arch->patches()[0], 0, n);
        std::cout << "  Gauss " << std::setw(2) << n << " points: error "
                  << (std::abs(l - M_PI * R / 2) < 1e-13 ?
                        std::string("< 1e-13") :
                        test::rounded(std::abs(l - M_PI * R / 2), 1))
                  << std::endl;
      }
    test::check_close(test::length_u(arch->patches()[0], 0.3, 24),
                      M_PI * R / 2,
                      1e-10,
                      "semicircle half arc length = pi R/2 (24-point Gauss)");
    test::check_close(test::area(arch->patches()[1], 24),
                      M_PI * R / 2 * 0.5,
                      1e-10,
                      "semicircle half area = pi R/2 * depth");

    test::check(arch->patches()[0].name() == "left half" &&
                  arch->patches()[1].name() == "right half",
                "patch names");
    const std::array<std::string, 4>
      left  = {{"springing left", "crown", "face front", "face back"}},
      right = {{"springing right", "crown", "face front", "face back"}};
    test::check(arch->patches()[0].edge_labels() == left &&
                  arch->patches()[1].edge_labels() == right,
                "edge labels");
    // the labelled edges are where they should be
    const auto p = arch->patches()[0];
    test::check(std::abs(p.point({0, 0.5})[0] + 2) < 1e-14 &&
                  std::abs(p.point({0, 0.5})[2]) < 1e-14 &&
                  std::abs(p.point({1, 0.5})[2] - 2) < 1e-14 &&
                  std::abs(p.point({0.5, 0})[1]) < 1e-14 &&
                  std::abs(p.point({0.5, 1})[1] - 0.5) < 1e-14,
                "springing at (-span/2, z=0), crown at z=rise, faces at "
                "y=0 and y=depth");
    const auto t = p.tangents({0.5, 0.5});
    test::check_close(t[1][1], 0.5, 1e-14, "dx/dv = depth along y");
    // the intrados is below, the extrados above the middle surface
    const auto c = p.point({1, 0.5});
    test::check((c + 0.18 * p.normal({1, 0.5}))[2] > c[2] &&
                  (c - 0.18 * p.normal({1, 0.5}))[2] < c[2],
                "crown: extrados above, intrados below");
  }
  {
    // segmental: a circle through (+-s/2, 0) and (0, r): the centre (0, zc)
    // satisfies (s/2)^2 + zc^2 = R^2 and r - zc = R, so
    // R = (s^2/4 + r^2)/(2r): s = 4, r = 1 gives R = 2.5, zc = -1.5
    const auto   arch  = test::create("arch",
                                   "set Shape = circular\nset Span = 4\n"
                                      "set Rise = 1\nset Depth = 1");
    const double cx[2] = {0, 0}, cz[2] = {-1.5, -1.5};
    check_circles(*arch, cx, cz, 2.5, 1, "segmental arch");
  }
  {
    // pointed, two-centred, centres on the springing line z = 0.
    // Derivation: the left half has its centre at (c, 0), c > 0, and passes
    // through the left springing (-s/2, 0) and the crown (0, r):
    //   R = c + s/2            (distance to the springing)
    //   R^2 = c^2 + r^2        (distance to the crown)
    // so (c + s/2)^2 = c^2 + r^2, c s + s^2/4 = r^2, c = (r^2 - s^2/4)/s and
    //   R = (r^2 - s^2/4)/s + s/2 = (s^2/4 + r^2)/s;
    // c > 0 iff r > s/2. The right half is the mirror image, centre (-c, 0).
    // Bothwell: s = 6.1, r = 3.8.
    const double s = 6.1, r = 3.8;
    const double c = (r * r - s * s / 4) / s, R = (s * s / 4 + r * r) / s;
    std::cout << "pointed arch s = 6.1, r = 3.8: c = " << c << ", R = " << R
              << std::endl;
    const auto   arch  = test::create("arch",
                                   "set Shape = pointed\nset Span = 6.1\n"
                                      "set Rise = 3.8\nset Depth = 1");
    const double cx[2] = {c, -c}, cz[2] = {0, 0};
    check_circles(*arch, cx, cz, R, 1, "pointed arch");
    double err = 0;
    for (unsigned int j = 0; j <= 10; ++j)
      err = std::max(err,
                     arch->patches()[0]
                       .point({1, j / 10.})
                       .distance(arch->patches()[1].point({1, j / 10.})));
    test::check(err < 1e-12, "pointed arch: the halves meet at the crown edge");
    // the crown is a kink: the two normals differ
    const auto n0 = arch->patches()[0].normal({1, 0.5}),
               n1 = arch->patches()[1].normal({1, 0.5});
    test::check_close(n0[0], -n1[0], 1e-12, "pointed crown: mirror normals");
    test::check(std::abs(n0[0]) > 0.1, "pointed crown: normals differ (kink)");
    // arc length of a half: R times the angle swept from the springing
    // (angle pi about (c,0)) to the crown (angle atan2(r, -c))
    const double sweep = M_PI - std::atan2(r, -c);
    test::check_close(test::length_u(arch->patches()[0], 0.5, 24),
                      R * sweep,
                      1e-10,
                      "pointed half arc length = R * sweep");
  }
  return test::failures();
}
