/**
 * Element deletion end to end on a wallette that deletes (the coarse cracked
 * cyclic wallette of the solver tests: damage-plasticity units, bilinear
 * joints, `Deletion strain = 0.005', cycled to 0.008), against the two
 * promises of the entries' documentation:
 *
 * - `Deletion stress' s_d: a cell goes only once the largest absolute
 *   principal value of its cell-averaged stress is at most s_d. Every
 *   deleted cell is in deletions.csv with the six components of the
 *   cell-averaged stress of the step after which it went; the test takes
 *   their principal values itself (deal.II's eigenvalues of the symmetric
 *   tensor) and compares the largest absolute one with s_d.
 * - `Maximum deletions per step' m: at most m cells go after one step,
 *   counted from deletions.csv by step and, independently, from the growth
 *   of curve.csv's `deleted_cells' from one step to the next (both counts
 *   must agree).
 *
 * So that the first check can fail, the same wallette also runs without
 * the stress condition (s_d = 0): it must delete at least one cell that
 * carried more than the s_d of the first run (the condition holds back
 * cells that the strain alone would take). And both runs must delete
 * cells at all, and more than m in all (so that the cap is met with room
 * to break it).
 */
#include <deal.II/base/symmetric_tensor.h>

#include <iomanip>
#include <map>

#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  const double       s_d = 0.5e6; // Pa
  const unsigned int m   = 2;

  /** The wallette with `Deletion stress' @p stress (Pa). */
  std::string
  wall(const double stress)
  {
    std::ostringstream extra;
    extra << "set Deletion stress = " << stress
          << "\nset Maximum deletions per step = " << m << "\n";
    return cracked_cyclic_wallette(extra.str());
  }

  // deletions.csv columns
  constexpr unsigned int step_column = 0, first_stress = 9;

  /** The largest absolute principal value of the stress of a row of
   * deletions.csv, Pa. */
  double
  largest_principal(const std::vector<double> &row)
  {
    dealii::SymmetricTensor<2, 3> s;
    s[0][0]      = row[first_stress];
    s[1][1]      = row[first_stress + 1];
    s[2][2]      = row[first_stress + 2];
    s[0][1]      = row[first_stress + 3];
    s[1][2]      = row[first_stress + 4];
    s[0][2]      = row[first_stress + 5];
    const auto e = dealii::eigenvalues(s);
    return std::max(std::abs(e[0]), std::abs(e[2]));
  }

  /** Runs @p name with `Deletion stress' @p stress and checks the cap;
   * the rows of its deletions.csv. */
  std::vector<std::vector<double>>
  deleting_run(const std::string &name, const double stress)
  {
    run(name, wall(stress));
    const auto rows = table(name, "deletions.csv");
    check(rows.size() > m,
          name + ": more cells deleted than the cap of one "
                 "step");
    std::map<unsigned int, unsigned int> by_step;
    for (const auto &r : rows)
      ++by_step[static_cast<unsigned int>(r[step_column])];
    unsigned int most = 0;
    for (const auto &[step, n] : by_step)
      most = std::max(most, n);
    // the growth of curve.csv's deleted_cells column (10) step by step
    const auto   curve_rows = curve(name);
    bool         agree      = curve_rows.back()[10] == rows.size();
    unsigned int most_curve = 0;
    for (unsigned int i = 1; i < curve_rows.size(); ++i)
      {
        const auto grown =
          static_cast<unsigned int>(curve_rows[i][10] - curve_rows[i - 1][10]);
        most_curve = std::max(most_curve, grown);
        const auto k =
          by_step.find(static_cast<unsigned int>(curve_rows[i][0]));
        agree = agree && grown == (k == by_step.end() ? 0 : k->second);
      }
    check(agree,
          name + ": deletions.csv and curve.csv count the same deletions "
                 "at every step");
    check(most <= m && most_curve <= m,
          name + ": at most `Maximum deletions per step' cells after one "
                 "step");
    return rows;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(3);

  const auto held = deleting_run("held", s_d);
  double     most = 0;
  for (const auto &r : held)
    most = std::max(most, largest_principal(r));
  std::cout << "held: the deleted cells carried at most "
            << (most <= s_d ? "the deletion stress" :
                              "MORE than the deletion stress")
            << "\n";
  check(most <= s_d,
        "no cell deleted while the largest absolute principal value of its "
        "cell-averaged stress is above `Deletion stress'");

  const auto   free = deleting_run("free", 0);
  unsigned int over = 0;
  for (const auto &r : free)
    over += largest_principal(r) > s_d;
  std::cout << "free: " << (over > 0 ? "some" : "no")
            << " deleted cells carried more than " << s_d / 1e6 << " MPa\n";
  check(over > 0,
        "without `Deletion stress' some cells go that carry more than it "
        "(the condition of the first run holds cells back)");
  return 0;
}
