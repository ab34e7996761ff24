/**
 * Unfilled strips of the bed joints along the collar joints of the detailed
 * model (`Collar bed gap' g): the bed-joint mortar over [a - g, a + h_m + g]
 * in y, a the face of the wythe before a collar plane, is a void.
 *
 * Geometry, counted by hand from the bond (215 x 102.5 x 65 mm units, 10 mm
 * joints, 2 bricks long, 7 courses: 6 bed joints 2 x 215 + 10 = 440 mm
 * long): the english double wall has one collar plane, so the voids cover
 * 6 x 0.44 x (0.01 + 2 g) m^2 in plan; the triple wall has two, twice that;
 * the stretcher-bond single leaf has none, so the entry changes nothing
 * there (no void cell, the same peak-free elastic force as without it).
 * Mechanics: removing material can only lower the platen force at a
 * prescribed displacement (the elastic energy is a minimum over fewer
 * admissible fields), so two courses of the double wall (one bed joint),
 * elastic between frictionless platens, carry less with the gap than with
 * the full bed joint (a check that the voids are in the mechanics, not only
 * counted). A gap that joins a strip to the next one or to a face leaves a
 * wythe on no bed: an error naming the entry (before, the run completed
 * with a platen stress of 7e-9 Pa).
 */
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  const double L = 0.215, hm = 0.010;

  std::string
  wall(const std::string &bond,
       const std::string &thickness,
       const unsigned int courses,
       const double       gap)
  {
    std::ostringstream gap_entry;
    gap_entry << "  set Collar bed gap = " << gap << "\n";
    return prm(coarse_detailed_wall(courses, gap_entry.str()),
               "subsection Bond\n  set Pattern = " + bond +
                 "\n  subsection English\n    set Thickness = " + thickness +
                 "\n  end\nend\n" + elastic_units_and_mortar("0.2") +
                 elastic_bond);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double gap = 0.02, strip = 6 * (2 * L + hm) * (hm + 2 * gap);
  std::cout << std::setprecision(6);
  for (const auto &[name, n] :
       {std::pair<std::string, int>{"double", 1}, {"triple", 2}})
    {
      auto s = run(name, wall("english", name, 7, gap));
      std::cout << name << " wall, gap " << gap << " m: bed voids "
                << s["bed_void_area"].get<double>() << " m^2 (hand "
                << n * strip << ")\n";
      check(relative(s["bed_void_area"].get<double>(), n * strip) < 1e-9,
            name + " wall: bed voids = collar planes x 6 bed joints x 0.44 "
                   "m x (h_m + 2 g)");
    }
  auto s  = run("single", wall("stretcher", "double", 7, gap));
  auto s0 = run("single0", wall("stretcher", "double", 7, 0));
  check(!s.contains("n_void_cells") &&
          relative(s["peak_stress"].get<double>(),
                   s0["peak_stress"].get<double>()) < 1e-12,
        "single leaf: no collar joint, no void, the same force");
  // two courses of the double wall (one bed joint), elastic
  auto         full = run("two0", wall("english", "double", 2, 0));
  auto         gapd = run("two", wall("english", "double", 2, gap));
  const double f0   = full["peak_stress"].get<double>(),
               f    = gapd["peak_stress"].get<double>();
  std::cout << "two courses: " << f / 1e6 << " MPa with the gap, " << f0 / 1e6
            << " MPa full\n";
  check(f < f0, "two courses: the gap lowers the force");
  // a gap that leaves a wythe on no bed: a one-line error naming the entry.
  // The double wall's strip [0.1025 - g, 0.1125 + g] reaches its faces
  // (0 and 0.215 m) at g = 0.1025 m; the triple wall's two strips meet
  // across its middle wythe (0.1125 to 0.215 m) at g = 0.05125 m
  for (const auto &[name, g] :
       {std::pair<std::string, double>{"double", 0.11}, {"triple", 0.06}})
    {
      {
        std::ofstream file("wide_" + name + ".prm");
        file << "set Output directory = results/wide_" << name << "\n"
             << wall("english", name, 2, g);
      }
      std::ostringstream out, err;
      std::streambuf    *old_out = std::cout.rdbuf(out.rdbuf());
      std::streambuf    *old_err = std::cerr.rdbuf(err.rdbuf());
      const int          code =
        masonry::run_application({"wide_" + name + ".prm"}, MPI_COMM_WORLD);
      std::cout.rdbuf(old_out);
      std::cerr.rdbuf(old_err);
      std::cout << name << " wall, gap " << g << " m: exit code " << code
                << "\n";
      check(code != 0 &&
              err.str().find("'Wallette/Collar bed gap'") !=
                std::string::npos &&
              err.str().find("without bed-joint mortar") != std::string::npos,
            name + " wall: a gap that leaves a wythe on no bed is an error "
                   "naming the entry");
    }
  return 0;
}
