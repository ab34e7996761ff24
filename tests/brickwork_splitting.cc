/**
 * Splitting interfaces (`Splitting interfaces = true'): one elastic unit,
 * 2.0 x 0.002 x 0.1 m (length x width x height), meshed as two halves joined
 * by a vertical interface at mid-length, between fixed platens (no lateral
 * motion of the top and bottom faces) under compression.
 *
 * Closed form: the unit is a thin plate (width << height << length), so
 * sigma_yy = 0 (plane stress) and, away from its ends, the platens hold
 * eps_xx = 0 over the whole height. With eps_zz = -strain:
 * sigma_zz = -E strain / (1 - nu^2) and the lateral stress across the
 * splitting plane is sigma_xx = nu sigma_zz = -nu E strain / (1 - nu^2).
 * For a unit that contracts laterally (nu = -0.25) the restraint puts the
 * plane in tension: it opens when sigma_xx = f_t, at
 * strain = f_t (1 - nu^2) / (-nu E) = 3.75e-4 for f_t = 1 MPa, E = 10 GPa.
 * (The platen rows of cells are also held across the width, a boundary
 * layer of one row: 8 rows give the closed form within 0.5 %.) With
 * nu = +0.15 the plane is in lateral compression and never opens.
 */
#include <algorithm>
#include <fstream>
#include <sstream>

#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  std::string
  unit(const double       nu,
       const double       target,
       const unsigned int steps = 1000,
       const std::string &extra = "")
  {
    return splitting_unit(nu, target, steps, extra);
  }

  /** Strain of the first step with a damaged interface point; 0: none. */
  double
  opening_strain(const std::string &name)
  {
    for (const auto &row : curve(name))
      if (row[6] > 0)
        return row[2];
    return 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             E = 10e9, f_t = 1e6, f_c = 10e6;
  {
    const double nu       = -0.25;
    auto         summary  = run("auxetic", unit(nu, 0.0005));
    const double expected = f_t * (1 - nu * nu) / (-nu * E);
    check(summary["n_split_units"].get<double>() == 1 &&
            summary["n_splitting_interface_faces"].get<double>() == 8,
          "one unit split: 8 face pairs (1 across the width x 8 up the "
          "height)");
    const double opened = opening_strain("auxetic");
    check(opened > 0 && relative(opened, expected) < 0.01,
          "nu = -0.25: the splitting interface opens at strain f_t (1 - "
          "nu^2) / (-nu E) = 3.75e-4 (1 %)");
    auto &d = summary["derived_values"]["splitting_interfaces"];
    check(relative(d["cohesion"].get<double>(), 0.5 * std::sqrt(f_c * f_t)) <
              1e-12 &&
            relative(d["friction"].get<double>(),
                     (f_c - f_t) / (2 * std::sqrt(f_c * f_t))) < 1e-12,
          "derived cohesion and friction: Mohr-Coulomb through f_c and f_t");
  }
  {
    // the plane's law selected in its own subsection instead of derived
    // from the unit: `bilinear' with the same f_t opens at the same strain
    // (a plane loaded in tension only: its friction does not act)
    const double nu       = -0.25;
    auto         summary  = run("bilinear",
                       splitting_unit(nu,
                                      0.0005,
                                      1000,
                                      "",
                                      "subsection Splitting interface law\n"
                                               "  set Law = bilinear\n"
                                               "  set Normal stiffness = 1e15\n"
                                               "  set Shear stiffness = 6.67e14\n"
                                               "  subsection Bilinear\n"
                                               "    set Tensile strength = 1e6\n"
                                               "    set Mode I fracture energy = 50\n"
                                               "  end\n"
                                               "end\n"));
    const double expected = f_t * (1 - nu * nu) / (-nu * E);
    const double opened   = opening_strain("bilinear");
    const auto  &derived  = summary["derived_values"];
    check(opened > 0 && relative(opened, expected) < 0.01 &&
            !(derived.contains("splitting_interfaces") &&
              derived["splitting_interfaces"].contains("cohesion")),
          "Splitting interface law/Law = bilinear, f_t = 1 MPa: the plane "
          "opens at strain f_t (1 - nu^2) / (-nu E) = 3.75e-4 (1 %), and "
          "no derived composite law is reported");
  }
  {
    // stopped after the interface has opened (step 85 of 100) and resumed:
    // the splitting interfaces' states are in the checkpoint
    run("uninterrupted", unit(-0.25, 0.0005, 100));
    run("resumed", unit(-0.25, 0.0005, 100, "  set Maximum steps = 85\n"));
    run("resumed", unit(-0.25, 0.0005, 100, "  set Resume = true\n"));
    const auto a = curve("uninterrupted"), b = curve("resumed");
    double     diff = a.size() == b.size() ? 0 : 1;
    for (unsigned int i = 0; i < a.size() && i < b.size(); ++i)
      diff = std::max(
        {diff, std::abs(a[i][4] - b[i][4]) / 1e6, std::abs(a[i][6] - b[i][6])});
    check(diff < 1e-12 && a.back()[6] > 0,
          "resumed after the opening = uninterrupted (stress, damage; 1e-12)");
  }
  {
    run("positive", unit(0.15, 0.001));
    check(opening_strain("positive") == 0,
          "nu = 0.15: lateral compression, the interface stays closed to "
          "strain 1e-3");
  }
}
