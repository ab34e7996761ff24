/**
 * The IMPL-EX extrapolation after a tiny step, and the end of an unloading
 * leg, on a coarse cut of the single cyclic example
 * (prm/examples/wallette-single-cyclic.prm with 3 courses, 2 x 1 x 1 cells
 * per unit, 40 nominal steps, the mortar's `Tensile plastic flow =
 * elastic', one thread).
 *
 * An unloading leg aims its last step at `Unloading stress' with the slope
 * of the step before; the IMPL-EX states lag one step, so the aimed step
 * lands a little off. Unloaded to zero force, the leg took four steps of
 * 1e-8 to 2e-9 m (the stress at 361, 143, 2.6, 8.9 Pa), then one of the
 * IMPL-EX floor, 4.3e-6 m, whose internal variables were extrapolated
 * from the last tiny step by the ratio of the two steps, 14108: the
 * changes of that step were not proportional to its length (the update
 * after a step also carries the redistribution that follows the update of
 * the step before, at any platen increment), a mortar cell cracked and the
 * largest damage jumped from 0.038 to 0.70 in that one step at zero force,
 * and the next cycle reloaded the wall to 0.76 of the stress it had
 * carried at the previous amplitude. The ratio is now at most `Step
 * growth factor'.
 *
 * (a) Unloading stress 0: unloading with the platen retracting and the
 *     wall's force falling to zero does not load it, so no damage may jump
 *     on an unloading leg: the largest damage (curve.csv max_damage)
 *     grows by less than `IMPL-EX damage tolerance' (0.05) per unloading
 *     step; and after every unloading the reloading reaches, at the
 *     previous amplitude, at least 0.9 of the stress the wall carried
 *     there, from the 0.003 amplitude on (a damaged, unloaded wall
 *     reloads along its secant to the envelope point it left; 0.9 leaves
 *     room for the cyclic degradation of the joints: measured 0.95 to 1.0;
 *     before the fix 0.76 after the jump. The first cycles, where the
 *     joints close, reload to 0.80 and 0.91 at the 0.002 and 0.0025
 *     amplitudes, before and after the fix).
 * (b) Unloading stress 0.1 MPa: every unloading leg ends at its first
 *     step at or below 1.01 x the unloading stress (the protocol's
 *     definition; the aim lands within 0.2 %: before, two legs went on
 *     with a tiny step and a step of the floor, to 62-68 kPa in the
 *     example).
 */
#include <iomanip>

#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  /** The example with the overrides of this test and @p unloading (Pa). */
  std::string
  wall(const std::string &unloading)
  {
    const std::string text = example_text("wallette-single-cyclic");
    check(!text.empty(), "the single cyclic example is read");
    return text +
           "subsection Wallette\n"
           "  set Courses = 3\n"
           "  set Elements along the length = 2\n"
           "  set Elements along the width = 1\n"
           "  set Elements along the height = 1\n"
           "  set Number of steps = 40\n"
           "  set Unloading stress = " +
           unloading +
           "\n"
           "  set Assembly threads = 1\n"
           "  set Output interval = 0\n"
           "  set Checkpoint interval = 0\n"
           "  set Write plot = false\n"
           "  set Write VTU = false\n"
           "end\n"
           "subsection Mortar material\n"
           "  subsection Mortar\n"
           "    set Tensile plastic flow = elastic\n"
           "  end\n"
           "end\n"
           "subsection Postprocess\n"
           "  subsection Wallette\n"
           "    set List of postprocessors = curve tables\n"
           "  end\n"
           "end\n";
  }

  // curve.csv columns
  constexpr unsigned int strain = 2, stress = 4, max_damage = 6, cycle = 8,
                         unloading = 9;

  void
  to_zero()
  {
    const masonry::Json s = run("zero", wall("0"));
    check(s.at("status").get<std::string>() == "completed",
          "unloading to zero force: completed to the last amplitude");
    const auto rows   = curve("zero");
    double     growth = 0;
    for (unsigned int i = 1; i < rows.size(); ++i)
      if (rows[i][unloading] == 1 && rows[i - 1][cycle] == rows[i][cycle])
        growth =
          std::max(growth, rows[i][max_damage] - rows[i - 1][max_damage]);
    std::cout << "zero: largest growth of the largest damage in one "
                 "unloading step "
              << (growth < 0.05 ? "below" : "NOT below") << " 0.05\n";
    check(growth < 0.05,
          "no damage jumps on an unloading leg (max_damage grows by less "
          "than the IMPL-EX tolerance 0.05 per step)");
    // the reloading at the previous amplitude against the stress there
    double lowest = 1e9;
    for (unsigned int k = 5; k <= 9; ++k)
      {
        double top_strain = -1, top_stress = 0, back = -1;
        for (const auto &r : rows)
          if (r[cycle] == k - 1 && r[unloading] == 0 && r[strain] > top_strain)
            top_strain = r[strain], top_stress = r[stress];
        double reach = -1;
        for (const auto &r : rows)
          if (r[cycle] == k && r[unloading] == 0 &&
              r[strain] <= top_strain + 1e-12 && r[strain] > reach)
            reach = r[strain], back = r[stress];
        lowest = std::min(lowest, back / top_stress);
      }
    check(lowest >= 0.9,
          "every reloading from the 0.003 amplitude on reaches at least 0.9 of "
          "the stress it left at the previous amplitude");
  }

  void
  to_unloading_stress()
  {
    const double        s_u = 0.1e6;
    const masonry::Json s   = run("holding", wall("0.1e6"));
    check(s.at("status").get<std::string>() == "completed",
          "unloading to 0.1 MPa: completed to the last amplitude");
    const auto   rows  = curve("holding");
    unsigned int legs  = 0;
    bool         first = true;
    for (unsigned int i = 1; i < rows.size(); ++i)
      if (rows[i][unloading] == 1 && rows[i - 1][unloading] == 1 &&
          rows[i - 1][cycle] == rows[i][cycle] &&
          rows[i - 1][stress] <= 1.01 * s_u)
        first = false;
    for (unsigned int i = 1; i + 1 < rows.size(); ++i)
      if (rows[i][unloading] == 1 && rows[i + 1][unloading] == 0)
        ++legs;
    std::cout << "holding: " << legs << " unloading legs before the last\n";
    check(first && legs == 8,
          "every unloading leg ends at its first step at or below 1.01 x "
          "the unloading stress");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  to_zero();
  to_unloading_stress();
}
