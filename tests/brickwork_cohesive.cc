/**
 * Two enlarged bricks (stack bond, one brick long, two courses) joined by one
 * bilinear cohesive bed joint, pulled apart by the top platen (laterally
 * fixed, Poisson's ratio 0, so that the joint opens uniformly):
 * - mode I (pulled up): the peak stress (force / joint area) is f_t and the
 *   work of the platen until the joint is fully debonded is G_I x area;
 * - mode II (moved sideways, bricks nearly rigid): peak c, work G_II x area;
 * - mixed mode (moved at 45 degrees, opening = slip, beta = 1): the work is
 *   G_c x area with Benzeggagh-Kenane G_c = G_I + (G_II - G_I) (1/2)^eta,
 *   and the peak stress along the motion is that at the quadratic onset,
 *   (k_n + k_s) d_m0 / 2 with d_m0 = d_n0 d_s0 sqrt(2 / (d_n0^2 + d_s0^2)).
 * Elastic energy left in the bricks at the end is zero (no force), so the
 * platen's work is the energy dissipated by the joint. Tolerance 1 %.
 */
#include "brickwork_tests.h"

using namespace brickwork_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double f_t = 0.2e6, c = 0.28e6, G_I = 15, G_II = 100, eta = 2;
  const double k_n = 2.5e11, k_s = 1e11;
  const double area = (0.215 + 0.01) * (0.1025 + 0.01);
  const double H    = 2 * (0.065 + 0.01);

  auto text = [&](const std::string &direction,
                  const double       final_displacement,
                  const double       E,
                  const std::string &integration) {
    std::ostringstream w, p;
    w.precision(12);
    p.precision(12);
    w << "set Courses = 2\nset Length in bricks = 1\n"
      << "set Platen lateral restraint = fixed\n"
      << "set Platen direction = " << direction << "\n"
      << "set Target strain = " << final_displacement / H << "\n"
      << "set Number of steps = 200\n"
      << "set Interface integration = " << integration << "\n";
    p << "subsection Bond\nset Pattern = stack\nend\n"
      << "subsection Brick material\nsubsection Elastic\n"
      << "set Young's modulus = " << E << "\nset Poisson's ratio = 0\n"
      << "end\nend\n"
      << "subsection Interface law\nset Law = bilinear\n"
      << "set Normal stiffness = " << k_n << "\n"
      << "set Shear stiffness = " << k_s << "\n"
      << "subsection Bilinear\n"
      << "set Tensile strength = " << f_t << "\nset Cohesion = " << c << "\n"
      << "set Mode I fracture energy = " << G_I << "\n"
      << "set Mode II fracture energy = " << G_II << "\n"
      << "set BK exponent = " << eta << "\nend\nend\n";
    return prm(w.str(), p.str());
  };

  for (const std::string integration : {"lobatto", "gauss"})
    {
      // mode I: final opening 2 G_I / f_t = 0.15 mm; go to 0.2 mm
      const masonry::Json s1 =
        run("mode_I_" + integration, text("0, 0, 1", 2e-4, 10e9, integration));
      check(relative(s1.at("peak_stress").get<double>(), f_t) < 0.01,
            integration + ", mode I: peak stress = f_t within 1 %");
      check(relative(s1.at("external_work").get<double>(), G_I * area) < 0.01,
            integration +
              ", mode I: dissipated energy = G_I x area within 1 %");
      check(s1.at("max_damage").get<double>() == 1 &&
              std::abs(s1.at("final_stress").get<double>()) < 1e-6 * f_t,
            integration + ", mode I: joint fully debonded, no force left");

      // mode II: final slip 2 G_II / c = 0.71 mm; go to 0.9 mm
      const masonry::Json s2 =
        run("mode_II_" + integration, text("1, 0, 0", 9e-4, 1e13, integration));
      check(relative(s2.at("peak_stress").get<double>(), c) < 0.01,
            integration + ", mode II: peak stress = c within 1 %");
      check(relative(s2.at("external_work").get<double>(), G_II * area) < 0.01,
            integration +
              ", mode II: dissipated energy = G_II x area within 1 %");

      // mixed mode, beta = 1
      const double dn0 = f_t / k_n, ds0 = c / k_s;
      const double dm0  = dn0 * ds0 * std::sqrt(2 / (dn0 * dn0 + ds0 * ds0));
      const double peak = (k_n + k_s) * dm0 / 2;
      const double G_c  = G_I + (G_II - G_I) * std::pow(0.5, eta);
      const masonry::Json s3 =
        run("mixed_" + integration, text("1, 0, 1", 6e-4, 1e13, integration));
      check(relative(s3.at("peak_stress").get<double>(), peak) < 0.01,
            integration + ", mixed mode: peak stress = onset value within 1 %");
      check(relative(s3.at("external_work").get<double>(), G_c * area) < 0.01,
            integration + ", mixed mode: dissipated energy = B-K G_c x area "
                          "within 1 %");
    }
}
