// The "barrel vault" geometry model: the default (Bothwell: pointed, span
// 6.1 m, rise 3.8 m, length 16.8 m), middle-surface area = arc length x
// length, skew, edge labels, normal orientation, common parameters.

#include "geometry_common.h"

using namespace masonry;

int
main()
{
  std::cout << std::setprecision(12);
  {
    const auto vault = test::create("barrel vault", "");
    // pointed arch, centres (+-c, 0) on the springing line with
    // c = (r^2 - s^2/4)/s and R = (s^2/4 + r^2)/s (see geometry_arch.cc);
    // each half sweeps pi - atan2(r, -c) about its centre
    const double s = 6.1, r = 3.8, L = 16.8;
    const double c = (r * r - s * s / 4) / s, R = (s * s / 4 + r * r) / s;
    const double arc = 2 * R * (M_PI - std::atan2(r, -c));
    test::check(vault->patches().size() == 2, "Bothwell: two patches");
    double err_r = 0;
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int i = 0; i <= 10; ++i)
        for (unsigned int j = 0; j <= 10; ++j)
          {
            const auto x = vault->patches()[k].point({i / 10., j / 10.});
            err_r        = std::max(
              err_r, std::abs(std::hypot(x[0] - (k == 0 ? c : -c), x[2]) - R));
          }
    test::check(err_r < 1e-12, "Bothwell: cross-section on the two circles");
    const double area =
      test::area(vault->patches()[0], 24) + test::area(vault->patches()[1], 24);
    std::cout << "Bothwell middle surface: arc length " << arc << " m, area "
              << arc * L << " m^2" << std::endl;
    test::check_close(area, arc * L, 1e-9, "area = arc length x length");
    const auto p0 = vault->patches()[0], p1 = vault->patches()[1];
    test::check(p0.name() == "west half" && p1.name() == "east half",
                "patch names");
    test::check(
      p0.edge_labels() ==
          std::array<std::string, 4>{
            {"springing left", "crown", "gable front", "gable back"}} &&
        p1.edge_labels() ==
          std::array<std::string, 4>{
            {"springing right", "crown", "gable front", "gable back"}},
      "edge labels");
    test::check(std::abs(p0.point({0, 0.5})[0] + s / 2) < 1e-14 &&
                  std::abs(p1.point({0, 0.5})[0] - s / 2) < 1e-14 &&
                  std::abs(p1.point({0.5, 1})[1] - L) < 1e-14 &&
                  p0.point({1, 0.2}).distance(p1.point({1, 0.2})) < 1e-14,
                "springings at x = -+span/2, back gable at y = L, halves "
                "meet at the crown");
    // the extrados normal points away from the vault's axis (outwards)
    const auto x = p1.point({0.3, 0.4});
    test::check(p1.normal({0.3, 0.4})[0] > 0 && p1.normal({0.3, 0.4})[2] > 0 &&
                  p0.normal({0.3, 0.4})[0] < 0,
                "normals point to the extrados (outwards and up)");
    (void)x;
    test::check_close(vault->thickness(x), 0.36, 0, "default thickness 0.36");
    test::check_close(vault->density(), 520, 0, "default density 520");
  }
  {
    // semicircular, skewed by 30 degrees: the section at y is the section
    // at 0 shifted by y tan(30 deg) along x
    const auto vault =
      test::create("barrel vault",
                   "set Shape = circular\nset Span = 4\nset Rise = 2\n"
                   "set Length = 3\nset Skew angle = 30",
                   "set Thickness = 0.3 + 0.1*z\nset Density = 2000");
    double err = 0;
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int i = 0; i <= 10; ++i)
        for (unsigned int j = 0; j <= 10; ++j)
          {
            const auto x = vault->patches()[k].point({i / 10., j / 10.});
            err          = std::max(
              err,
              std::abs(std::hypot(x[0] - x[1] * std::tan(M_PI / 6), x[2]) - 2));
          }
    test::check(err < 1e-12, "skewed: sections are shifted semicircles");
    // the skewed surface is a sheared cylinder: the area is the same as that
    // of the cylinder cut by planes y=0 and y=L perpendicular to the shear
    // direction... use the exact area element instead:
    // |x_u x x_v| with x_v = (tan a, 1, 0) L and x_u = (X', 0, Z'):
    // sqrt(Z'^2 (1 + tan^2 a) + X'^2) L; on the semicircle of radius 2,
    // X' = -2 sin(t) t', Z' = 2 cos(t) t', so the area is
    // L * 2 * int_0^pi sqrt(cos^2 t / cos^2 a + sin^2 t) dt
    double reference = 0;
    {
      const dealii::QGauss<1> q(40);
      const double            ca = std::cos(M_PI / 6);
      for (unsigned int m = 0; m < 8; ++m)
        for (unsigned int k = 0; k < q.size(); ++k)
          {
            const double t = M_PI * (m + q.point(k)[0]) / 8;
            reference += q.weight(k) * M_PI / 8 *
                         std::sqrt(std::cos(t) * std::cos(t) / (ca * ca) +
                                   std::sin(t) * std::sin(t));
          }
      reference *= 3 * 2;
    }
    const double area =
      test::area(vault->patches()[0], 24) + test::area(vault->patches()[1], 24);
    test::check_close(area, reference, 1e-9, "skewed: area");
    test::check_close(vault->thickness(dealii::Point<3>(0, 0, 2)),
                      0.5,
                      1e-15,
                      "thickness expression 0.3 + 0.1 z at the crown");
    test::check_close(vault->density(), 2000, 0, "density");
  }
  return test::failures();
}
