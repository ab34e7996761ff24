// The "dome" geometry model: points on the sphere, radial outward normals,
// area of a hemisphere 2 pi R^2 and of a spherical cap 2 pi R h (sum over
// the four quadrants of the tensor Gauss rule applied to |x_u x x_v|), edge
// labels, quadrants meeting along their meridians.

#include "geometry_common.h"

using namespace masonry;

int
main()
{
  std::cout << std::setprecision(12);
  {
    const double R    = 5;
    const auto   dome = test::create("dome", "set Span = 10\nset Rise = 5");
    test::check(dome->patches().size() == 4, "hemisphere: four patches");
    double err_r = 0, err_n = 0;
    for (const auto &p : dome->patches())
      for (unsigned int i = 0; i <= 10; ++i)
        for (unsigned int j = 0; j <= 10; ++j)
          {
            const dealii::Point<2> uv(i / 10., j / 10.);
            const auto             x = p.point(uv);
            err_r                    = std::max(err_r, std::abs(x.norm() - R));
            // at the pole (i = 10) the normal is the limit from inside
            err_n = std::max(err_n, (p.normal(uv) - x / R).norm());
          }
    test::check(err_r < 1e-12, "hemisphere: points on the sphere to 1e-12");
    test::check(err_n < 1e-6,
                "hemisphere: normals radial outward (to 1e-6 at the pole, "
                "limit from inside)");
    double err_n_inside = 0;
    for (const auto &p : dome->patches())
      for (unsigned int i = 0; i < 10; ++i)
        for (unsigned int j = 0; j <= 10; ++j)
          {
            const dealii::Point<2> uv(i / 10., j / 10.);
            err_n_inside =
              std::max(err_n_inside, (p.normal(uv) - p.point(uv) / R).norm());
          }
    test::check(err_n_inside < 1e-12,
                "hemisphere: normals radial outward away from the pole to "
                "1e-12");

    // area: 2 pi R^2; the integrand is smooth (rational), so tensor Gauss
    // converges exponentially with the number n of points per direction
    std::cout << "hemisphere area, exact 2 pi R^2 = " << 2 * M_PI * R * R
              << std::endl;
    for (const unsigned int n : {2, 4, 8, 12, 16, 24})
      {
        double a = 0;
        for (const auto &p : dome->patches())
          a += test::area(p, n);
        const double e = std::abs(a - 2 * M_PI * R * R);
        std::cout << "  Gauss " << std::setw(2) << n << "x" << std::setw(2) << n
                  << " points per patch: error "
                  << (e < 1e-11 ? std::string("< 1e-11") : test::rounded(e, 1))
                  << std::endl;
      }
    double a = 0;
    for (const auto &p : dome->patches())
      a += test::area(p, 24);
    test::check_close(a,
                      2 * M_PI * R * R,
                      1e-10,
                      "hemisphere area = 2 pi R^2 (24x24 Gauss points)");

    const std::array<std::string, 4> names     = {{"quadrant north-east",
                                                   "quadrant north-west",
                                                   "quadrant south-west",
                                                   "quadrant south-east"}};
    const std::array<std::string, 5> meridians = {{"meridian east",
                                                   "meridian north",
                                                   "meridian west",
                                                   "meridian south",
                                                   "meridian east"}};
    bool                             labels_ok = true, places_ok = true;
    double                           err_meet = 0;
    for (unsigned int k = 0; k < 4; ++k)
      {
        const auto &p = dome->patches()[k];
        labels_ok     = labels_ok && p.name() == names[k] &&
                    p.edge_labels()[0] == "springing" &&
                    p.edge_labels()[1] == "pole" &&
                    p.edge_labels()[2] == meridians[k] &&
                    p.edge_labels()[3] == meridians[k + 1];
        // springing at z = 0, pole at (0,0,R), meridian v=0 at azimuth k*90
        const auto s = p.point({0, 0.}), pole = p.point({1, 0.3});
        places_ok = places_ok && std::abs(s[2]) < 1e-14 &&
                    pole.distance(dealii::Point<3>(0, 0, R)) < 1e-14 &&
                    std::abs(s[0] - R * std::cos(k * M_PI / 2)) < 1e-14 &&
                    std::abs(s[1] - R * std::sin(k * M_PI / 2)) < 1e-14;
        for (unsigned int i = 0; i <= 10; ++i)
          err_meet = std::max(err_meet,
                              p.point({i / 10., 1.})
                                .distance(dome->patches()[(k + 1) % 4].point(
                                  {i / 10., 0.})));
      }
    test::check(labels_ok, "names and edge labels of the quadrants");
    test::check(places_ok, "springing at z=0, pole at (0,0,R), meridians");
    test::check(err_meet < 1e-12, "neighbouring quadrants share a meridian");
  }
  {
    // spherical cap: span 10, rise 2: R = (25 + 4)/4 = 7.25, centre
    // (0,0,2-R); area 2 pi R h with h = rise
    const double R     = 7.25;
    const auto   dome  = test::create("dome", "set Span = 10\nset Rise = 2");
    double       err_r = 0;
    for (const auto &p : dome->patches())
      for (unsigned int i = 0; i <= 10; ++i)
        for (unsigned int j = 0; j <= 10; ++j)
          err_r = std::max(
            err_r,
            std::abs(p.point({i / 10., j / 10.}).distance({0, 0, 2 - R}) - R));
    test::check(err_r < 1e-12, "spherical cap: points on the sphere");
    double a = 0;
    for (const auto &p : dome->patches())
      a += test::area(p, 24);
    test::check_close(a, 2 * M_PI * R * 2, 1e-10, "cap area = 2 pi R h");
  }
  return test::failures();
}
