/**
 * `IMPL-EX minimum step when unloading' in a run: the cracked cyclic
 * wallette of brickwork_solver_fallback (2 x 1 x 1 cells per brick,
 * strength scatter, deletion, IMPL-EX with `accept', MUMPS), with the
 * IMPL-EX floor at 0.1 of the nominal step (0.008 H / 40).
 *
 * (a) With the unloading floor 0 (the loading floor on every leg) some
 *     unloading steps are smaller than half the nominal step: joints and
 *     bricks that snap open while the wall unloads keep the damage error
 *     over the tolerance, and the steps shrink towards the loading floor.
 *     This makes the case one where (b) can fail.
 * (b) With the unloading floor 0.5 no unloading step is smaller than half
 *     the nominal step, the first of each leg included (the loading leg
 *     before hands on its last step, often its floor: the unloading leg
 *     starts at its own floor), except the steps aimed at the unloading
 *     stress (they end within 20 % of it) and a step that a Newton
 *     cut-back halved.
 * (c) A run of (b) stopped (`Maximum steps') in the middle of an unloading
 *     leg, just before a step that the damage-error control redid and
 *     accepted at the unloading floor, and resumed, reproduces the
 *     uninterrupted curve (1e-12): the resumed run knows the leg's floor
 *     (with the loading floor that step would shrink below it).
 */
#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  std::string
  wallette(const std::string &unloading_floor, const std::string &extra = "")
  {
    return cracked_cyclic_wallette(
      extra +
      "set Linear solver = direct\nset IMPL-EX minimum step = 0.1\n"
      "set IMPL-EX minimum step when unloading = " +
      unloading_floor + "\n");
  }

  /** Unloading steps (columns: 1 displacement, 4 stress, 8 cycle, 9
   * unloading) smaller than 0.999 x @p limit (m), not counting the last
   * of a leg and those that end below 1.2 x the unloading stress (0.1
   * MPa). */
  unsigned int
  unloading_steps_below(const std::vector<std::vector<double>> &rows,
                        const double                            limit)
  {
    unsigned int n = 0;
    for (unsigned int j = 1; j + 1 < rows.size(); ++j)
      if (rows[j][9] == 1 && rows[j + 1][9] == 1 &&
          rows[j - 1][8] == rows[j][8] && rows[j][4] > 1.2 * 0.1e6 &&
          rows[j - 1][1] - rows[j][1] < 0.999 * limit)
        ++n;
    return n;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const masonry::Json                      same = run("same", wallette("0"));
  const masonry::Json                      own  = run("own", wallette("0.5"));
  check(same.at("status").get<std::string>() == "completed" &&
          own.at("status").get<std::string>() == "completed",
        "both runs completed");
  const double       half = 0.5 * 0.008 * own.at("height").get<double>() / 40;
  const unsigned int a    = unloading_steps_below(curve("same"), half);
  const unsigned int b    = unloading_steps_below(curve("own"), half);
  check(a > 0,
        "(a) with the loading floor on every leg some unloading steps are "
        "smaller than half the nominal step");
  check(b <= own.at("cut_backs").get<double>(),
        "(b) with `IMPL-EX minimum step when unloading' = 0.5 none is, but "
        "those aimed at the unloading stress and a cut-back's");

  // (c) the step before the first redone unloading step accepted at the
  // floor, with two unloading steps of the same leg before it
  const auto rows = curve("own");
  // the steps that the damage-error control redid
  const std::vector<int> redone =
    steps_after("results/own/log.txt", "IMPL-EX: step redone");
  const auto was_redone = [&](const int n) {
    return std::find(redone.begin(), redone.end(), n) != redone.end();
  };
  unsigned int stop = 0;
  for (unsigned int n = 3; stop == 0 && n < rows.size(); ++n)
    if (was_redone(n) && rows[n][9] == 1 && rows[n - 1][9] == 1 &&
        rows[n - 2][9] == 1 && rows[n - 2][8] == rows[n][8] &&
        rows[n][4] > 1.2 * 0.1e6 &&
        std::abs(rows[n - 1][1] - rows[n][1] - half) < 1e-3 * half)
      stop = n - 1;
  check(stop > 0,
        "(c) a redone unloading step accepted at the floor exists in the "
        "middle of a leg");
  const masonry::Json stopped =
    run("resumed",
        wallette("0.5", "set Maximum steps = " + std::to_string(stop) + "\n"));
  check(stopped.at("status").get<std::string>() == "interrupted",
        "(c) the first part stops as interrupted");
  const masonry::Json resumed =
    run("resumed", wallette("0.5", "set Resume = true\n"));
  const double diff = curve_difference(rows, curve("resumed"));
  check(resumed.at("status").get<std::string>() == "completed" && diff < 1e-12,
        "(c) stopped there and resumed, the run reproduces the "
        "uninterrupted curve (1e-12)");
}
