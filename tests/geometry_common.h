/**
 * @file
 * Helpers of the geometry tests: create a geometry model from a parameter
 * string and check values against theory, printing "OK ..." lines.
 */
#ifndef masonry_tests_geometry_common_h
#define masonry_tests_geometry_common_h

#include <masonry/core/parameters.h>
#include <masonry/geometry/interface.h>

#include <deal.II/base/quadrature_lib.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>

namespace test
{
  /** Number of failed checks (the exit code of the test). */
  inline int &
  failures()
  {
    static int n = 0;
    return n;
  }

  /** Print "OK what" or "FAILED what (detail)". */
  inline void
  check(const bool ok, const std::string &what, const std::string &detail = "")
  {
    if (ok)
      std::cout << "OK " << what << std::endl;
    else
      {
        std::cout << "FAILED " << what << " " << detail << std::endl;
        ++failures();
      }
  }

  /** Check |a - b| <= tol. */
  inline void
  check_close(const double       a,
              const double       b,
              const double       tol,
              const std::string &what)
  {
    std::ostringstream d;
    d << std::setprecision(17) << a << " vs " << b << " (diff "
      << std::abs(a - b) << ")";
    check(std::abs(a - b) <= tol, what, d.str());
  }

  /**
   * Create the geometry model @p name with the entries @p entries (lines
   * "set X = Y" of its subsection) and @p common (lines of
   * `subsection Geometry model`).
   */
  inline std::unique_ptr<masonry::geometry::Interface>
  create(const std::string &name,
         const std::string &entries,
         const std::string &common = "")
  {
    using Registry = masonry::plugins::Registry<masonry::geometry::Interface>;
    dealii::ParameterHandler prm;
    Registry::declare_parameters(prm);
    std::string section = name;
    section[0]          = std::toupper(section[0]);
    prm.parse_input_from_string("subsection Geometry model\n"
                                "set Model name = " +
                                name + "\n" + common + "\nsubsection " +
                                section + "\n" + entries + "\nend\nend\n");
    return Registry::create(prm);
  }

  /** Message of the exception thrown by @p f, or "" if none. */
  template <typename F>
  std::string
  error_of(F f)
  {
    try
      {
        f();
      }
    catch (const std::exception &exc)
      {
        return masonry::one_line_message(exc);
      }
    return "";
  }

  /** The unit-square point on edge @p e (0: u=0, 1: u=1, 2: v=0, 3: v=1). */
  inline dealii::Point<2>
  edge_point(const unsigned int e, const double s)
  {
    return e < 2 ? dealii::Point<2>(e, s) : dealii::Point<2>(s, e - 2.);
  }

  /**
   * Area of a patch, by the tensor Gauss rule with @p n points per
   * direction on @p m x @p m sub-squares, integrating |x_u x x_v|.
   */
  inline double
  area(const masonry::geometry::Patch &patch,
       const unsigned int              n,
       const unsigned int              m = 1)
  {
    const dealii::QGauss<2> q(n);
    double                  a = 0;
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        for (unsigned int k = 0; k < q.size(); ++k)
          {
            const dealii::Point<2> uv((i + q.point(k)[0]) / m,
                                      (j + q.point(k)[1]) / m);
            a += q.weight(k) * patch.jacobian(uv) / (m * m);
          }
    return a;
  }

  /** Length of the curve u -> point(u, v) by n-point Gauss on m pieces. */
  inline double
  length_u(const masonry::geometry::Patch &patch,
           const double                    v,
           const unsigned int              n,
           const unsigned int              m = 1)
  {
    const dealii::QGauss<1> q(n);
    double                  l = 0;
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int k = 0; k < q.size(); ++k)
        l += q.weight(k) / m *
             patch.tangents(dealii::Point<2>((i + q.point(k)[0]) / m, v))[0]
               .norm();
    return l;
  }

  /** Print a number rounded to @p digits significant digits. */
  inline std::string
  rounded(const double x, const int digits = 2)
  {
    std::ostringstream s;
    s << std::setprecision(digits) << std::scientific << x;
    return s.str();
  }
} // namespace test

#endif
