/**
 * What an unfilled strip of the bed joints along the collar joint (`Collar
 * bed gap' g) costs the double wall's strength, against an estimate made
 * here from the geometry and the units' failure envelope: the double
 * monotonic example (prm/examples/wallette-double-monotonic.prm) on the
 * coarse mesh (2 x 1 x 1 cells per unit + joint), with the example's
 * g = 10 mm and with full bed joints (g = 0).
 *
 * The strip is the collar joint and g either side, h_m + 2 g = 30 mm of the
 * t = 215 mm wall in every bed joint, so the bed mortar's net area is
 * a = 1 - (h_m + 2 g) / t = 0.8605 of the gross plan. The units fail on
 * the tension-compression interaction of the example's law, t/f_bt + s/f_c
 * = 1: their lateral tension t comes from the squeezed bed mortar, whose
 * stress is the platen force over the net area, and their vertical stress s
 * from the force over the area they spread it to, between the net area (no
 * spreading) and the gross area (spread over the strip within the unit's
 * height). With the full joints' peak sigma_0 the compressive share of the
 * envelope is c = sigma_0 / f_c (f_c = 0.8 f_b, the law's uniaxial
 * strength of the normalised f_b) and the tensile share 1 - c, so the
 * peak ratio sigma_g / sigma_0 lies between
 *   a                       (both at the net area: the net-area rule) and
 *   1 / ((1 - c) / a + c)   (the tension at the net area, the compression
 *                            at the gross area).
 * The model's ratio must lie in that range: a gap that did nothing (ratio
 * 1) or that took more than its area (below a) fails.
 */
#include <iomanip>

#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  /** The double monotonic example on the coarse mesh with `Collar bed gap'
   * @p gap (m), only the curve tables written. */
  std::string
  wall(const std::string &gap)
  {
    const std::string text = example_text("wallette-double-monotonic");
    check(!text.empty(), "the double monotonic example is read");
    return text +
           "subsection Wallette\n"
           "  set Collar bed gap = " +
           gap +
           "\n"
           "  set Elements along the length = 2\n"
           "  set Elements along the width = 1\n"
           "  set Elements along the height = 1\n"
           "  set Output interval = 0\n"
           "  set Write plot = false\n"
           "  set Write VTU = false\n"
           "end\n"
           "subsection Postprocess\n"
           "  subsection Wallette\n"
           "    set List of postprocessors = curve tables\n"
           "  end\n"
           "end\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(3);
  // the example's inputs: wall thickness, mortar joint, gap, f_b
  const double t = 0.215, h_m = 0.010, g = 0.01, f_c = 0.8 * 20e6;
  const auto   full = run("full", wall("0"));
  const auto   gap  = run("gap", wall("0.01"));
  check(full.at("status").get<std::string>() == "completed" &&
          gap.at("status").get<std::string>() == "completed",
        "both walls run to the target strain");
  const double sigma_0 = full.at("peak_stress").get<double>(),
               sigma_g = gap.at("peak_stress").get<double>();
  const double a = 1 - (h_m + 2 * g) / t, c = sigma_0 / f_c,
               upper = 1 / ((1 - c) / a + c), ratio = sigma_g / sigma_0;
  std::cout << "net bed area " << a << " of the gross plan\n";
  check(ratio >= a && ratio <= upper,
        "the gap lowers the peak by what the net bed area predicts, between "
        "the net-area rule and the units' spreading of the compression");
  return 0;
}
