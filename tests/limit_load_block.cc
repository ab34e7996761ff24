/**
 * A single block b × h (thickness b along y, height h along z, length L
 * along x) on a rigid base under a horizontal acceleration λ g; statics:
 * - overturning about a base edge: λ = b / h (no tension, no sliding; or
 *   Mohr–Coulomb with tan φ > b/h and c = 0);
 * - sliding, c = 0, tan φ < b/h: λ = tan φ (associative: the dilatancy
 *   tan φ per unit slip lifts the weight);
 * - sliding with cohesion: λ = tan φ + c A / W, A = L b, W = ρ g L b h;
 * - sliding at 45° in the horizontal plane with m = 4 shear directions: the
 *   square circumscribes the Coulomb circle and λ = √2 tan φ
 *   (the documented overestimate 1/cos(π/m)); with m = 8: tan φ;
 * - uniform crushing under a vertical live load λ W on top of the dead
 *   self weight W, compressive strength f_c: (1 + λ) W = f_c A.
 * The support reaction equals minus the loads at collapse (dual of the LP).
 * Also the diagnoses: no support → `mechanism' (unbounded), a vertical
 * load on a no-tension base without cap → `no_collapse' (infeasible).
 */
#include <deal.II/base/mpi.h>

#include "vault_tests.h"

using namespace vault_tests;

namespace
{
  const double b = 0.5, h = 2, L = 1, rho = 2000, g = 9.81;

  std::string
  block_prm(const std::string &joints,
            const std::string &acceleration,
            const std::string &supports = "base")
  {
    return "set Analysis = limit load\n"
           "subsection Geometry model\n  set Model name = panel\n"
           "  set Thickness = 0.5\n  set Density = 2000\n"
           "  subsection Panel\n    set Length = 1\n    set Width = 2\n"
           "  end\nend\n"
           "subsection Interface model\n" +
           joints +
           "end\n"
           "subsection Limit load\n  set Blocks along u = 1\n"
           "  set Blocks along v = 1\n  set Supported edges = " +
           supports + "\n  set Live acceleration = " + acceleration +
           "\n  set Write picture = false\nend\n";
  }

  std::string
  mohr_coulomb(const double       tan_phi,
               const double       c,
               const double       f_c        = 0,
               const unsigned int directions = 8)
  {
    std::ostringstream s;
    s.precision(17);
    s << "  set Model = mohr coulomb\n  subsection Mohr coulomb\n"
      << "    set Friction coefficient = " << tan_phi << "\n"
      << "    set Cohesion = " << c << "\n"
      << "    set Compressive strength = " << f_c << "\n"
      << "    set Shear directions = " << directions << "\n  end\n";
    return s.str();
  }

  void
  expect(const std::string &name,
         const std::string &prm,
         const double       lambda,
         const std::string &what)
  {
    const masonry::Json s   = run(name, prm);
    const double        got = s.at("load_multiplier").get<double>();
    const double        err = relative(got, lambda);
    std::cout << what << ": λ = " << std::setprecision(10) << lambda
              << " (theory)\n";
    check(err < 1e-8, what + " to 1e-8");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             W = rho * g * L * b * h, A = L * b;

  expect("overturning",
         block_prm("  set Model = no tension no sliding\n", "0; 1; 0"),
         b / h,
         "overturning, no tension no sliding, λ = b/h");
  expect("overturning_mc",
         block_prm(mohr_coulomb(0.6, 0), "0; 1; 0"),
         b / h,
         "overturning, Mohr-Coulomb tan φ = 0.6, λ = b/h");
  expect("sliding",
         block_prm(mohr_coulomb(0.1, 0), "0; 1; 0"),
         0.1,
         "sliding, c = 0, λ = tan φ");
  expect("cohesion",
         block_prm(mohr_coulomb(0.1, 1000), "0; 1; 0"),
         0.1 + 1000 * A / W,
         "sliding, c = 1 kPa, λ = tan φ + c A / W");
  const std::string diagonal = "0.70710678118654752; 0.70710678118654752; 0";
  expect("diagonal_m4",
         block_prm(mohr_coulomb(0.1, 0, 0, 4), diagonal),
         std::sqrt(2.) * 0.1,
         "sliding at 45°, m = 4 directions, λ = √2 tan φ");
  expect("diagonal_m8",
         block_prm(mohr_coulomb(0.1, 0, 0, 8), diagonal),
         0.1,
         "sliding at 45°, m = 8 directions, λ = tan φ");
  expect("crushing",
         block_prm(mohr_coulomb(0.5, 0, 2e5), "0; 0; -1"),
         2e5 * A / W - 1,
         "crushing under a multiplier on self weight, λ = f_c A / W − 1");

  // reactions at collapse: the ground carries W and −λ W horizontally
  {
    const masonry::Json r =
      run("reaction", block_prm(mohr_coulomb(0.1, 1000), "0; 1; 0"));
    const double lambda = r.at("load_multiplier").get<double>();
    const auto  &base   = r.at("support_reactions").at("base");
    const double err =
      std::max({std::abs(base.at(0).get<double>()) / W,
                relative(base.at(1).get<double>(), -lambda * W),
                relative(base.at(2).get<double>(), W)});
    check(err < 1e-8, "support reaction (0, −λW, W) from the LP dual to 1e-8");
  }

  // diagnoses
  {
    const masonry::Json free =
      run("free", block_prm(mohr_coulomb(0.1, 0), "0; 1; 0", "top"));
    check(free.at("status").get<std::string>() == "mechanism",
          "block hanging from nothing (support on top, no tension): "
          "mechanism");
    const masonry::Json strong =
      run("strong",
          block_prm("  set Model = no tension no sliding\n", "0; 0; -1"));
    check(strong.at("status").get<std::string>() == "no_collapse",
          "vertical load on a no-tension base without cap: no_collapse");
  }
}
