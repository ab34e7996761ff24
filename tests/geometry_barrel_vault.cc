// The "barrel vault" geometry model: the default (Bothwell's numbers as the
// middle surface: pointed, span 6.1 m, rise 3.8 m, length 16.8 m),
// middle-surface area = arc length x length, skew, edge labels, normal
// orientation, common parameters; `Span and rise of = intrados' and
// `extrados' (the paper's Bothwell vault: interior span 6.1 m, rise 3.8 m,
// thickness 0.36 m) against the circles of those surfaces, computed here
// from the pointed and circular arch formulas alone.

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
  {
    // the paper's vault: the intrados offset of the middle surface by half
    // the thickness along the normal must be the pointed arch of span 6.1
    // and rise 3.8 (centres (+-c, 0), radius R), springing at x = -+3.05,
    // z = 0; likewise the extrados with `extrados'
    const double s = 6.1, r = 3.8, t = 0.36;
    const double c = (r * r - s * s / 4) / s, R = (s * s / 4 + r * r) / s;
    for (const std::string surface : {"intrados", "extrados"})
      {
        const double side  = surface == "intrados" ? -0.5 : 0.5;
        const auto   vault = test::create("barrel vault",
                                        "set Span and rise of = " + surface,
                                        "set Thickness = 0.36");
        double       err_r = 0, err_z = 0;
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int i = 0; i <= 10; ++i)
            for (unsigned int j = 0; j <= 4; ++j)
              {
                const dealii::Point<2> uv(i / 10., j / 4.);
                const auto            &patch = vault->patches()[k];
                const auto x = patch.point(uv) + side * t * patch.normal(uv);
                err_r =
                  std::max(err_r,
                           std::abs(std::hypot(x[0] - (k == 0 ? c : -c), x[2]) -
                                    R));
                if (i == 0)
                  err_z = std::max(
                    {err_z, std::abs(x[2]), std::abs(std::abs(x[0]) - s / 2)});
              }
        test::check(err_r < 1e-12,
                    "paper's vault, " + surface +
                      " given: that surface on the two circles of span 6.1, "
                      "rise 3.8");
        test::check(err_z < 1e-12,
                    "paper's vault, " + surface +
                      " given: it springs at x = -+3.05 m, z = 0");
        // the middle surface: radius R -+ t/2 about the same centres, so
        // span 6.1 -+ 0.36 and rise sqrt((R -+ t/2)^2 - c^2)
        const double Rm  = R - 2 * side * t / 2;
        const auto crown = vault->patches()[0].point(dealii::Point<2>(1, 0.5));
        std::cout << "paper's vault, " << surface << " given: middle surface "
                  << "span " << 2 * vault->patches()[1].point({0, 0})[0]
                  << " m, rise " << crown[2] << " m" << std::endl;
        test::check_close(2 * vault->patches()[1].point({0, 0})[0],
                          s - 2 * side * t,
                          1e-12,
                          "middle surface span");
        test::check_close(crown[2],
                          std::sqrt(Rm * Rm - c * c),
                          1e-12,
                          "middle surface rise");
      }
  }
  {
    // a segmental barrel whose intrados is given: the intrados circle
    // through (-+2, 0) and (0, 1.2) has R = (4 + 1.44)/2.4 and its centre
    // at (0, 1.2 - R); radial springing joints, so the middle surface
    // springs above z = 0
    const double t = 0.3, R = (2. * 2. + 1.2 * 1.2) / (2 * 1.2), zc = 1.2 - R;
    const auto   vault =
      test::create("barrel vault",
                   "set Shape = circular\nset Span = 4\nset Rise = 1.2\n"
                   "set Span and rise of = intrados\nset Length = 2",
                   "set Thickness = 0.3");
    double err_r = 0;
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int i = 0; i <= 10; ++i)
        {
          const dealii::Point<2> uv(i / 10., 0.5);
          const auto            &patch = vault->patches()[k];
          const auto x = patch.point(uv) - 0.5 * t * patch.normal(uv);
          err_r = std::max(err_r, std::abs(std::hypot(x[0], x[2] - zc) - R));
        }
    test::check(err_r < 1e-12, "segmental, intrados given: on its circle");
    const auto &east = vault->patches()[1];
    const auto  x0   = east.point({0, 0.5}) - 0.5 * t * east.normal({0, 0.5});
    const auto  x1   = east.point({1, 0.5}) - 0.5 * t * east.normal({1, 0.5});
    test::check(std::abs(x0[0] - 2) < 1e-12 && std::abs(x0[2]) < 1e-12 &&
                  std::abs(x1[0]) < 1e-12 && std::abs(x1[2] - 1.2) < 1e-12,
                "segmental, intrados given: springs at (2, 0), crown at "
                "(0, 1.2)");
    test::check_close(east.point({0, 0.5})[2],
                      -zc * t / 2 / R,
                      1e-12,
                      "segmental: the middle surface springs at "
                      "-zc (t/2)/R above z = 0");
  }
  return test::failures();
}
