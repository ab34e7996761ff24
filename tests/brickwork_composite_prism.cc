/**
 * A stack-bonded prism of three enlarged bricks (elastic, E = 10 GPa) with
 * `Interface law = composite' in its two bed joints, free platens, under
 * monotonic compression to strain 0.008 (implicit). The stress is uniform,
 * so each joint is in pure compression on the cap: with c = H/E + 2/k_n the
 * platen displacement is U = sigma c + 2 kappa_3 with sigma = sbar(kappa_3)
 * (Lourenço-Rots cap law, written out here): linear to sbar_i = sbar_p/3,
 * the sqrt hardening to sbar_p = 10.5 MPa, the parabola and the exponential
 * tail. The curve must follow that closed form at every step (the cap's
 * softening is flatter than 2 / c, so U(kappa_3) increases and there is no
 * snap-back), the peak is sbar_p and the initial modulus H / c.
 * With `Mortar Young's modulus' set, the penalties come from E_b, E_m, nu
 * and the joint thickness: the initial modulus then follows from them.
 */
#include <cmath>

#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  const double E = 10e9, H = 3 * 0.075, sp = 10.5e6, si = sp / 3, sm = sp / 2,
               sr = sp / 7, kp = 0.09e-3, Gfc = 5000;

  double
  sbar(const double k, const double km)
  {
    if (k <= 0)
      return si;
    if (k < kp)
      return si + (sp - si) * std::sqrt(2 * k / kp - k * k / (kp * kp));
    if (k < km)
      return sp + (sm - sp) * std::pow((k - kp) / (km - kp), 2);
    const double m = 2 * (sm - sp) / (km - kp);
    return sr + (sm - sr) * std::exp(m * (k - km) / (sm - sr));
  }

  std::string
  prism(const std::string &joint)
  {
    return prm("  set Courses = 3\n"
               "  set Length in bricks = 1\n"
               "  set Elements along the length = 2\n"
               "  set Elements along the width = 1\n"
               "  set Elements along the height = 1\n"
               "  set Platen lateral restraint = free\n"
               "  set Target strain = 0.008\n"
               "  set Number of steps = 80\n",
               "subsection Bond\n  set Pattern = stack\nend\n"
               "subsection Brick material\n"
               "  set Model = elastic\n"
               "  subsection Elastic\n"
               "    set Young's modulus = 10e9\n"
               "    set Poisson's ratio = 0.15\n"
               "  end\n"
               "end\n"
               "subsection Interface law\n"
               "  set Law = composite\n" +
                 joint + "end\n");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // kappa_m from G_fc = int_{kappa_p}^inf (sbar - sbar_r)
  const double B =
    sp + (sm - sp) / 3 - sr + (sm - sr) * (sm - sr) / (2 * (sp - sm));
  const double km = kp + Gfc / B;
  {
    const double kn = 2.5e11, c = H / E + 2 / kn;
    auto   summary = run("prism", prism("  set Normal stiffness = 2.5e11\n"));
    double err     = 0;
    for (const auto &row : curve("prism"))
      {
        const double U = row[1], sigma = row[4];
        double       ref;
        if (U <= si * c)
          ref = U / c;
        else
          {
            double a = 0, b = 0.01;
            for (unsigned int i = 0; i < 200; ++i)
              {
                const double k                        = 0.5 * (a + b);
                (sbar(k, km) * c + 2 * k > U ? b : a) = k;
              }
            ref = sbar(0.5 * (a + b), km);
          }
        err = std::max(err, std::abs(std::abs(sigma) - ref) / sp);
      }
    check(err < 1e-6,
          "stack prism: stress = closed-form cap curve at every step (1e-6 "
          "of sbar_p)");
    check(relative(summary["peak_stress"].get<double>(), sp) < 5e-3,
          "stack prism: peak = cap strength 10.5 MPa (0.5 %, step "
          "sampling)");
    check(relative(summary["initial_modulus"].get<double>(), H / c) < 1e-6,
          "stack prism: initial modulus H / (H / E + 2 / k_n)");
  }
  {
    // penalties from E_b = 10 GPa, nu_b = 0.15, E_m = 2 GPa, nu_m = 0.2,
    // h_m = 10 mm: k_n = 2.5e11 Pa/m
    auto         summary = run("prism_moduli",
                       prism("  set Normal stiffness = 1e9\n"
                                     "  subsection Composite\n"
                                     "    set Mortar Young's modulus = 2e9\n"
                                     "  end\n"));
    const double c       = H / E + 2 / 2.5e11;
    check(relative(summary["initial_modulus"].get<double>(), H / c) < 1e-6,
          "stack prism: penalties from E_b, E_m, nu and h_m replace the "
          "given Normal stiffness");
    // the derived values in summary.json and log.txt: k_s from the shear
    // moduli G = E / (2 (1 + nu)) written out here
    const double Gb = 10e9 / 2.3, Gm = 2e9 / 2.4,
                 ks = Gb * Gm / (0.01 * (Gb - Gm));
    auto &d         = summary["derived_values"]["interface_law"];
    check(relative(d["normal_stiffness"].get<double>(), 2.5e11) < 1e-12 &&
            relative(d["shear_stiffness"].get<double>(), ks) < 1e-12,
          "summary.json: derived k_n = 2.5e11 Pa/m and k_s = 1.0309e11 "
          "Pa/m");
    check(relative(d["cap_middle_jump"].get<double>(), km) < 1e-12,
          "summary.json: derived kappa_m from G_fc");
    std::ifstream     log("results/prism_moduli/log.txt");
    std::stringstream text;
    text << log.rdbuf();
    check(text.str().find("normal_stiffness = 2.5e+11 Pa/m") !=
            std::string::npos,
          "log.txt: the derived normal stiffness is printed");
  }
}
