/**
 * Tension cut-off: a horizontal slab (length 2 m along x, width w = 0.5 m,
 * thickness t = 0.3 m, density 2000 kg/m³) cut into two blocks, the first
 * clamped (bonded support at x = 0), the joint at x = 1 m glued with
 * Mohr–Coulomb (c, tan φ, f_t, no compression cap). A point load P = 1 kN
 * downwards at the free end (x = 2, on the middle surface) is the live
 * load; self weight is dead.
 *
 * Statics: the free block rotates about the bottom edge of the joint; the
 * normal opening grows linearly to θ t at the top, the dissipation is
 * f_eff w t² θ / 2 with f_eff = min(f_t, c / tan φ) (opening through
 * the cut-off or through the cohesive planes). Work: W₂ θ (1/2 m) for the
 * weight W₂ = ρ g w t (1 m) of the free block and λ P θ (1 m) for the load:
 *   λ = (f_eff w t² / 2 − W₂ / 2) / P.
 * Sliding of the free block needs λ = (c w t − W₂)/P, larger here.
 *
 * The same load as a line load q = P / w along the free edge (N/m) gives
 * the same λ (its resultant acts at the same lever arm).
 */
#include <deal.II/base/mpi.h>

#include "vault_tests.h"

using namespace vault_tests;

namespace
{
  std::string
  cantilever_prm(const double       f_t,
                 const double       c,
                 const double       tan_phi,
                 const std::string &load = "set Point loads = 0, 1, 0.5, 0, 0, "
                                           "-1000")
  {
    std::ostringstream s;
    s.precision(17);
    s << "set Analysis = limit load\n"
      << "subsection Geometry model\n  set Model name = panel\n"
      << "  set Thickness = 0.3\n  set Density = 2000\n"
      << "  subsection Panel\n    set Orientation = horizontal\n"
      << "    set Length = 2\n    set Width = 0.5\n  end\nend\n"
      << "subsection Interface model\n  set Model = mohr coulomb\n"
      << "  subsection Mohr coulomb\n    set Friction coefficient = " << tan_phi
      << "\n    set Cohesion = " << c << "\n    set Tensile strength = " << f_t
      << "\n  end\nend\n"
      << "subsection Limit load\n  set Blocks along u = 2\n"
      << "  set Blocks along v = 1\n  set Supported edges = left\n"
      << "  set Support contact = bonded\n"
      << "  set Live acceleration = 0; 0; 0\n"
      << "  " << load << "\n"
      << "  set Write picture = false\nend\n";
    return s.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double w = 0.5, t = 0.3, P = 1000, W2 = 2000 * 9.81 * w * t * 1.0;
  struct Case
  {
    double      f_t, c, tan_phi;
    std::string what;
  };
  for (const Case &k :
       {Case{1e5, 1e6, 0.5, "cut-off f_t = 0.1 MPa governs"},
        Case{1e7, 1e5, 0.5, "cohesive opening c/tan φ = 0.2 MPa governs"}})
    {
      const double        f_eff  = std::min(k.f_t, k.c / k.tan_phi);
      const double        lambda = (f_eff * w * t * t / 2 - W2 / 2) / P;
      const masonry::Json s =
        run("cantilever", cantilever_prm(k.f_t, k.c, k.tan_phi));
      const double got = s.at("load_multiplier").get<double>();
      std::cout << k.what << ": λ = " << std::setprecision(10) << lambda
                << " (statics)\n";
      check(relative(got, lambda) < 1e-8, k.what + ": λ to 1e-8");
    }
  const double        lambda = (1e5 * w * t * t / 2 - W2 / 2) / P;
  const masonry::Json line =
    run("line_load",
        cantilever_prm(
          1e5, 1e6, 0.5, "set Line loads = 0, 1, 0, 1, 1, 0, 0, -2000"));
  check(relative(line.at("load_multiplier").get<double>(), lambda) < 1e-8,
        "line load 2 kN/m along the free edge: the same λ to 1e-8");
}
