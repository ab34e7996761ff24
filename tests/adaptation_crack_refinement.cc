/**
 * `Optimiser = crack refinement` (settlement):
 *
 * - semicircular arch (mean radius 5 m, thickness 1 m, no tension no
 *   sliding), one springing settles 1 cm, from 2 blocks per half, 5 stages:
 *   the objective never decreases from one stage to the next and never
 *   exceeds that of the uniform mesh of the finest spacing (64 blocks per
 *   half), of which every mesh is a subset (nested meshes: theory); the
 *   final mesh's work is within 0.5 % of a uniform mesh of 512 blocks (an
 *   independent computation) with fewer than a third of the blocks of the
 *   uniform mesh of the same finest spacing: the lines went to the hinges;
 * - barrel vault with Mohr–Coulomb joints and a settlement varying along
 *   its length (every strip cracks): `Marked fraction = 1' splits every
 *   strip, so one stage from 2 x 2 per half gives the uniform 4 x 4 mesh,
 *   and its objective equals that of uniform 4 x 4 to 1e-8; with 0.5 the
 *   objectives of 2 stages never decrease and the final one stays at or
 *   below uniform 8 x 8;
 * - the same barrel with `Split = blocks' (local refinement): `Marked
 *   fraction = 1' splits every block, so one stage from 2 x 2 per half
 *   gives the blocks of uniform 4 x 4, and its objective equals uniform
 *   4 x 4's to 1e-8; with 0.5, 2 stages (meshes with blocks of different
 *   sizes side by side: interfaces along half an edge, also across the
 *   crown) have objectives that never decrease (nested meshes) and stay
 *   at or below uniform 8 x 8 (every block is a union of its blocks).
 */
#include <deal.II/base/mpi.h>

#include "vault_tests.h"

using namespace vault_tests;

namespace
{
  std::string
  refinement(const unsigned int stages,
             const double       fraction,
             const std::string &split = "lines")
  {
    std::ostringstream s;
    s << "subsection Adaptation\n  set Optimiser = crack refinement\n"
      << "  subsection Crack refinement\n    set Stages = " << stages
      << "\n    set Marked fraction = " << fraction
      << "\n    set Split = " << split << "\n  end\nend\n";
    return s.str();
  }

  /** The barrel vault of the Mohr–Coulomb cases. */
  std::string
  barrel(const unsigned int n)
  {
    return barrel_prm(n,
                      "0; 0; -0.01*y/6",
                      "  set Model = mohr coulomb\n"
                      "  subsection Mohr coulomb\n    set Cohesion = 2e4\n"
                      "    set Tensile strength = 3e4\n  end\n");
  }

  /** Whether the stage objectives never decrease (1e-9 relative). */
  bool
  monotone(const masonry::Json &adaptation)
  {
    const auto &s  = adaptation.at("stages");
    bool        ok = s.size() > 1;
    for (unsigned int k = 1; k < s.size(); ++k)
      {
        const double a = s.at(k - 1).at("fitness").get<double>();
        const double b = s.at(k).at("fitness").get<double>();
        ok             = ok && b >= a - 1e-9 * std::abs(a);
      }
    return ok;
  }

  /** Whether the final objective of a run is at least that of its last
   * stage and at most @p upper (1e-9 relative). */
  bool
  between(const masonry::Json &result, const double upper)
  {
    const double w    = result.at("objective").get<double>();
    const auto  &s    = result.at("adaptation").at("stages");
    const double last = s.at(s.size() - 1).at("fitness").get<double>();
    return w <= upper * (1 + 1e-9) && w >= last - 1e-9 * std::abs(w);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             R = 5;

  const double fine = run("fine", arch_prm(R, 1, 256, "0; 0; -0.01"))
                        .at("objective")
                        .get<double>();
  const double finest = run("finest", arch_prm(R, 1, 64, "0; 0; -0.01"))
                          .at("objective")
                          .get<double>();
  const masonry::Json a =
    run("arch", arch_prm(R, 1, 2, "0; 0; -0.01") + refinement(5, 0.5));
  const auto  &aa = a.at("adaptation");
  const double w  = a.at("objective").get<double>();
  check(aa.at("stages").size() == 5, "arch: 5 stages solved");
  check(monotone(aa), "arch: the objective never decreases between stages");
  check(w >= aa.at("stages").at(4).at("fitness").get<double>() - 1e-9 * w,
        "arch: the final mesh is at least as good as the last stage's");
  check(w <= finest * (1 + 1e-9),
        "arch: at most the objective of uniform 64 blocks per half");
  check(relative(w, fine) < 5e-3,
        "arch: work within 0.5 % of 512 uniform blocks");
  check(a.at("n_blocks").get<double>() < 128 / 3.,
        "arch: fewer than a third of the blocks of uniform 64 per half");

  const double uniform4 =
    run("barrel_4", barrel(4)).at("objective").get<double>();
  const masonry::Json b  = run("barrel_all", barrel(2) + refinement(1, 1));
  const auto         &ba = b.at("adaptation");
  check(ba.at("blocks_along_u").get<double>() == 4 &&
          ba.at("blocks_along_v").get<double>() == 4,
        "barrel, marked fraction 1: every strip split (4 x 4 per half)");
  check(relative(b.at("objective").get<double>(), uniform4) < 1e-8,
        "barrel, marked fraction 1: the objective of uniform 4 x 4 (1e-8)");
  const double uniform8 =
    run("barrel_8", barrel(8)).at("objective").get<double>();
  const masonry::Json c = run("barrel_half", barrel(2) + refinement(2, 0.5));
  check(monotone(c.at("adaptation")),
        "barrel, marked fraction 0.5: the objective never decreases");
  check(between(c, uniform8),
        "barrel, marked fraction 0.5: between the last stage and uniform "
        "8 x 8");

  // `Split = blocks' (local, non-conforming refinement)
  const masonry::Json d =
    run("barrel_blocks_all", barrel(2) + refinement(1, 1, "blocks"));
  check(d.at("n_blocks").get<double>() == 32,
        "barrel, blocks, marked fraction 1: every block split (32 blocks)");
  check(relative(d.at("objective").get<double>(), uniform4) < 1e-8,
        "barrel, blocks, marked fraction 1: the objective of uniform 4 x 4 "
        "(1e-8)");
  const masonry::Json e =
    run("barrel_blocks_half", barrel(2) + refinement(2, 0.5, "blocks"));
  check(monotone(e.at("adaptation")),
        "barrel, blocks, marked fraction 0.5: the objective never decreases");
  check(between(e, uniform8),
        "barrel, blocks, marked fraction 0.5: between the last stage and "
        "uniform 8 x 8");
  check(e.at("n_blocks").get<double>() < 128,
        "barrel, blocks, marked fraction 0.5: fewer blocks than uniform "
        "8 x 8");
}
