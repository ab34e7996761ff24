/**
 * The Bothwell examples are the seed paper's vault: interior (intrados)
 * span 6.1 m, rise 3.8 m, thickness 0.36 m, length 16.8 m, 520 kg/m³.
 *
 * - Weight from theory: the cross-section of each half is the annulus
 *   sector between the intrados (radius R_i = c + 3.05 m) and the extrados
 *   (R_i + t) about its centre (∓c, 0) on the springing line,
 *   c = (3.8² − 3.05²)/6.1 m, from the springing to the radial line through
 *   the middle surface's crown (angle θ = atan(H_m/c) from the springing
 *   line, H_m = sqrt((R_i + t/2)² − c²)), so the vault weighs
 *   2 θ (R_i + t/2) t L ρ g: `total_weight' of the vertical settlement
 *   example within 1e-9 (the blocks integrate the exact NURBS volume).
 * - The vertical and horizontal settlement examples and the seismic one:
 *   status, optimum (the work minus the dissipation, or the load
 *   multiplier) equal to GLPK's on the same LP (the independent solver of
 *   the LP tests) within 1e-6 relative, and the settlements' prescribed
 *   1 cm (`max_settlement').
 */
#include <deal.II/base/mpi.h>

#include "vault_tests.h"

using namespace vault_tests;

namespace
{
  std::string
  example(const std::string &name)
  {
    const std::string text = example_text(name);
    check(!text.empty(), name + " is read");
    // the data of the run, no pictures or pages
    return text + "subsection Postprocess\n  subsection Rigid blocks\n"
                  "    set List of postprocessors = cracks\n  end\nend\n";
  }

  std::string
  glpk()
  {
    return "subsection LP solver\n  set Solver = glpk\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(10);

  const double s = 6.1, r = 3.8, t = 0.36, L = 16.8, rho = 520, g = 9.81;
  const double c = (r * r - s * s / 4) / s, Ri = c + s / 2, Rm = Ri + t / 2;
  const double theta  = std::atan(std::sqrt(Rm * Rm - c * c) / c);
  const double weight = 2 * theta * Rm * t * L * rho * g;
  std::cout << "weight from theory: " << weight << " N" << std::endl;

  for (const std::string name :
       {"bothwell-vertical-settlement", "bothwell-horizontal-settlement"})
    {
      const masonry::Json clp   = run(name, example(name));
      const masonry::Json other = run(name + "_glpk", example(name) + glpk());
      if (name == "bothwell-vertical-settlement")
        {
          std::cout << "total_weight: " << clp.at("total_weight").get<double>()
                    << " N" << std::endl;
          check(relative(clp.at("total_weight").get<double>(), weight) <= 1e-9,
                name + ": total weight from theory (1e-9)");
        }
      check(std::abs(clp.at("max_settlement").get<double>() - 0.01) <= 1e-15,
            name + ": settlement 1 cm");
      const bool optimal = clp.at("status").get<std::string>() == "optimal" &&
                           other.at("status").get<std::string>() == "optimal";
      const double error = optimal ?
                             relative(clp.at("objective").get<double>(),
                                      other.at("objective").get<double>()) :
                             1.;
      if (!(error <= 1e-6))
        std::cout << "  relative difference " << error << "\n";
      check(optimal && error <= 1e-6,
            name + ": optimal, the optimum of GLPK (1e-6)");
    }
  {
    const std::string   name  = "bothwell-seismic";
    const masonry::Json clp   = run(name, example(name));
    const masonry::Json other = run(name + "_glpk", example(name) + glpk());
    const bool optimal = clp.at("status").get<std::string>() == "optimal" &&
                         other.at("status").get<std::string>() == "optimal";
    const double error = optimal ?
                           relative(clp.at("load_multiplier").get<double>(),
                                    other.at("load_multiplier").get<double>()) :
                           1.;
    if (!(error <= 1e-6))
      std::cout << "  relative difference " << error << "\n";
    check(optimal && error <= 1e-6,
          name + ": optimal, the load multiplier of GLPK (1e-6)");
  }
}
