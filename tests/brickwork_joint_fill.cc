/**
 * Partly filled head and collar joints of the detailed model (`Head joint
 * fill', `Collar joint fill'): the unfilled top of every vertical joint is a
 * void.
 *
 * 1. Geometry, counted by hand from the bond (215 x 102.5 x 65 mm units,
 *    10 mm joints, 2 bricks long, 7 courses): the english bond's double
 *    wall has 4 stretcher courses (two wythes with aligned head joints and
 *    the collar joint between them, whose crossing with the head joints
 *    counts as collar) and 3 header courses (three headers and two queen
 *    closers: 4 head joints 215 mm deep). Head joints in their plane:
 *    3 x 4 x 0.215 x 0.065 + 4 x 2 x 0.1025 x 0.065 = 0.221 m^2; collar
 *    joint: 4 x 0.44 x 0.065 = 0.1144 m^2. The stretcher bond's single leaf
 *    has 4 courses of two stretchers (one head joint) and 3 of a half bat,
 *    a stretcher and a half bat (two): 10 x 0.1025 x 0.065 = 0.066625 m^2.
 *    The voids are (1 - fill) of each.
 *
 * 2. Load share, exact: one stretcher course of the double wall (no bed
 *    joints) between frictionless platens, units and mortar elastic with the
 *    same Poisson's ratio (E_b = 10 GPa, E_m = 1 GPa, nu = 0.2), stiff
 *    elastic bond. The state is uniaxial in every material (equal lateral
 *    strains, no traction across the vertical interfaces), so the platen
 *    force is eps (E_b A_units + E_m A_mortar), A_mortar the plan area of
 *    the mortar that reaches both platens. Full joints: A_mortar = collar
 *    strip 0.44 x 0.01 plus two head joints 0.01 x 0.1025; an empty collar
 *    joint: the head joints only; both empty: the units carry everything.
 *    A half-filled collar joint stands on the lower platen and is loaded
 *    through the bond on its sides only: between the two.
 */
#include <iomanip>
#include <iostream>
#include <sstream>

#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  const double L = 0.215, W = 0.1025, H = 0.065, hm = 0.010;

  std::string
  wall(const std::string &bond,
       const unsigned int courses,
       const double       head,
       const double       collar,
       const bool         elastic_bond_laws)
  {
    std::ostringstream fills;
    fills << "  set Head joint fill = " << head
          << "\n  set Collar joint fill = " << collar << "\n";
    return prm(coarse_detailed_wall(courses, fills.str()),
               "subsection Bond\n  set Pattern = " + bond + "\nend\n" +
                 elastic_units_and_mortar("0.2") +
                 (elastic_bond_laws ? elastic_bond : std::string()));
  }

  void
  geometry()
  {
    const double head_double = (3 * 4 * L + 4 * 2 * W) * H,
                 collar = 4 * (2 * L + hm) * H, head_single = 10 * W * H;
    for (const auto &[h, c] : {std::pair{0.4, 0.7}, std::pair{0.0, 0.25}})
      {
        auto s = run("double", wall("english", 7, h, c, true));
        std::cout << std::setprecision(6) << "double wall, fills " << h << ", "
                  << c << ": head joints " << s["head_joint_area"].get<double>()
                  << " m^2 (hand " << head_double << "), collar " << collar
                  << " m^2\n";
        check(relative(s["head_joint_area"].get<double>(), head_double) <
                  1e-9 &&
                relative(s["collar_joint_area"].get<double>(), collar) < 1e-9,
              "double wall: head and collar joint areas as counted by hand");
        check(relative(s["head_void_area"].get<double>(),
                       (1 - h) * head_double) < 1e-9 &&
                relative(s["collar_void_area"].get<double>(),
                         (1 - c) * collar) < 1e-9,
              "double wall: voids = (1 - fill) x joint area");
        check((s["n_collar_interface_faces"].get<double>() == 0) == (c == 0),
              "double wall: collar bond interfaces exist unless the collar "
              "joint is empty");
      }
    auto s = run("single", wall("stretcher", 7, 0.5, 1, true));
    check(relative(s["head_joint_area"].get<double>(), head_single) < 1e-9 &&
            relative(s["head_void_area"].get<double>(), 0.5 * head_single) <
              1e-9 &&
            s["collar_joint_area"].get<double>() == 0,
          "single leaf: head joint area as counted by hand, half void, no "
          "collar joint");
  }

  void
  load_share()
  {
    const double Eb = 10e9, Em = 1e9, eps = 1e-4;
    const double gross = (2 * L + hm) * (2 * W + hm), units = 4 * L * W,
                 collar = (2 * L + hm) * hm, heads = 2 * hm * W;
    const struct
    {
      double      head, collar, mortar;
      const char *what;
    } cases[] = {{1, 1, collar + heads, "full joints"},
                 {1, 0, heads, "empty collar joint"},
                 {0,
                  0,
                  0,
                  "empty head and collar joints: the units carry "
                  "all"}};
    double stresses[3];
    for (unsigned int i = 0; i < 3; ++i)
      {
        const auto &c = cases[i];
        auto s = run("course", wall("english", 1, c.head, c.collar, true));
        const double expected = eps * (Eb * units + Em * c.mortar) / gross;
        const double stress   = std::abs(s["final_stress"].get<double>());
        stresses[i]           = stress;
        std::cout << std::setprecision(6) << c.what << ": " << stress * 1e-6
                  << " MPa (hand " << expected * 1e-6 << ")\n";
        check(relative(stress, expected) < 1e-6,
              std::string("one course: platen stress = eps (E_b A_units + "
                          "E_m A_mortar) / A_gross, ") +
                c.what);
      }
    // half filled: the mortar stands on the lower platen and takes load
    // from the units through the bond on its sides only, so less than a
    // full joint and more than none
    auto         s      = run("course", wall("english", 1, 1, 0.5, true));
    const double stress = std::abs(s["final_stress"].get<double>());
    std::cout << "collar joint half filled: " << stress * 1e-6 << " MPa\n";
    check(stress < stresses[0] && stress > stresses[1],
          "one course: a half-filled collar joint carries less than a full "
          "one, more than none");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  geometry();
  load_share();
}
