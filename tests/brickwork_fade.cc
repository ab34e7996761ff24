/**
 * Gradual element deletion (`Deletion fade opening'), against a closed
 * form computed here: cubes of one elastic unit (E, nu) between
 * frictionless platens are in uniaxial stress, sigma = E eps, and every cell
 * has the same largest principal strain, the lateral nu eps. Past `Deletion
 * strain' e_d a cell's stress and stiffness are scaled by
 *   f = 1 - (e1 - e_d) l / w
 * (e1: the largest lateral strain reached, l: the cube root of the cell's
 * volume, w: the fade opening), updated after each converged step, so each
 * point of curve.csv is E eps f(e1 of the step before), and the cells are
 * deleted (zero force) once f reaches 0. Two meshes of the same 0.1 m cube,
 * 1 and 2 x 2 x 2 cells: the same opening fades the smaller cells over a
 * twice larger strain (crack band). Two cycles at 0.006: the second one
 * reaches E 0.006 f(nu 0.006) (unloading and reloading with the modulus
 * f E). The one-cell cube then goes through two cycles at 0.013: its fade
 * is over at (e_d + w / l) / nu = 0.008, the cell deleted and the force
 * zero. (The eight cells do not fade alike to the end: the fade softens,
 * and once f is below about 0.1 round-off localises it in half of them,
 * as softening does.) Tolerance 1e-5 of E x 0.01: the Newton tolerance and the
 * digits of curve.csv.
 *
 * `Deletion crushing length' alone: the one-cell cube fades with its
 * shortening since the step at which it passed `Deletion strain'; the same
 * checks with that fade (check_crushing).
 *
 * `Deletion stress' s_d (check_stress): the one-cell cube passes `Deletion
 * strain' at its first step but carries E eps > s_d, so it stays, however
 * far past the strain, until a converged step at which its stress E eps is
 * at most s_d while its lateral strain nu eps is still past e_d (on
 * unloading); it is deleted then and carries nothing from the next step on.
 */
#include <iomanip>

#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  const double E = 10e9, nu = 0.25, e_d = 0.001, w = 1e-4;

  double
  fade(const double e1, const double l)
  {
    return e1 <= e_d ? 1. : std::max(0., 1 - (e1 - e_d) * l / w);
  }

  /**
   * The parameter text of the 0.1 m cube of the elastic unit (E, nu) in
   * n x n x n cells between frictionless platens; @p loading: the protocol
   * and deletion entries of subsection Wallette.
   */
  std::string
  cube(const unsigned int n, const std::string &loading)
  {
    std::ostringstream t;
    t << "set Brick length = 0.09\nset Brick width = 0.09\n"
         "set Brick height = 0.09\nset Joint thickness = 0.01\n"
         "set Courses = 1\nset Length in bricks = 1\n"
         "set Elements along the length = "
      << n << "\nset Elements along the width = " << n
      << "\nset Elements along the height = " << n
      << "\nset Platen lateral restraint = free\n"
      << loading;
    std::ostringstream m;
    m << std::setprecision(17)
      << "subsection Brick material\nsubsection Elastic\n"
      << "set Young's modulus = " << E << "\nset Poisson's ratio = " << nu
      << "\nend\nend\n";
    return prm(t.str(), m.str());
  }

  void
  check_mesh(const unsigned int n, const bool to_the_end)
  {
    const std::string  amplitudes = to_the_end ? "0.006, 0.013" : "0.006";
    const double       l          = 0.1 / n;
    std::ostringstream t;
    t << std::setprecision(17)
      << "set Protocol = cyclic\nset Cycle amplitudes = " << amplitudes
      << "\nset Cycles per amplitude = 2\nset Unloading stress = 0.1e6\n"
         "set Target strain = "
      << (to_the_end ? 0.013 : 0.006)
      << "\nset Number of steps = " << (to_the_end ? 65 : 30)
      << "\nset Deletion strain = " << e_d
      << "\nset Deletion fade opening = " << w << "\n";
    const std::string   name = "cube_" + std::to_string(n);
    const masonry::Json s    = run(name, cube(n, t.str()));
    check(s.at("status").get<std::string>() == "completed",
          name + ": completed to the last amplitude");
    // columns: 2 strain, 4 stress (compression positive), 10 deleted
    const auto rows = curve(name);
    double     e1 = 0, error = 0, second_peak = -1;
    bool       zero_at_end = false;
    for (unsigned int i = 1; i < rows.size(); ++i)
      {
        const double eps = rows[i][2];
        const double f   = fade(e1, l);
        error =
          std::max(error, std::abs(rows[i][4] - E * eps * f) / (E * 0.01));
        // the second cycle's turning point at 0.006
        if (rows[i][8] == 2 && rows[i][9] == 0 && std::abs(eps - 0.006) < 1e-12)
          second_peak = rows[i][4];
        e1          = std::max(e1, nu * eps);
        zero_at_end = f == 0 && rows[i][10] == n * n * n;
      }
    check(error < 1e-5,
          name + ": every point is E eps f(largest lateral strain before) "
                 "(1e-5 of E x 0.01)");
    const double expected = E * 0.006 * fade(nu * 0.006, l);
    std::cout << name << ": stress at the second 0.006 peak " << std::fixed
              << std::setprecision(3) << second_peak * 1e-6
              << " MPa, closed form " << expected * 1e-6 << " MPa (fade "
              << fade(nu * 0.006, l) << ")\n";
    check(std::abs(second_peak - expected) < 1e-5 * E * 0.01,
          name + ": second 0.006 peak = E 0.006 (1 - (nu 0.006 - e_d) l / w)");
    if (to_the_end)
      check(zero_at_end, name + ": all cells deleted at the end of the fade");
  }

  /**
   * `Deletion crushing length' w_c alone (no lateral fade): the one-cell
   * cube splits at the first step with nu eps > e_s, at strain eps_s, and
   * then fades with its shortening, f = 1 - (eps_max - eps_s) l / w_c;
   * cycles twice to 0.006, then to 0.013, where the fade is over.
   */
  void
  check_crushing()
  {
    const double       e_s = 0.00107, w_c = 2e-4, l = 0.1;
    std::ostringstream t;
    t << std::setprecision(17)
      << "set Protocol = cyclic\nset Cycle amplitudes = 0.006, 0.013\n"
         "set Cycles per amplitude = 2\nset Unloading stress = 0.1e6\n"
         "set Target strain = 0.013\nset Number of steps = 65\n"
         "set Deletion strain = "
      << e_s << "\nset Deletion crushing length = " << w_c << "\n";
    const masonry::Json s = run("crushing", cube(1, t.str()));
    check(s.at("status").get<std::string>() == "completed",
          "crushing: completed to the last amplitude");
    const auto rows = curve("crushing");
    double     f = 1, eps_s = -1, error = 0, second_peak = -1;
    bool       zero_at_end = false;
    for (unsigned int i = 1; i < rows.size(); ++i)
      {
        const double eps = rows[i][2];
        error =
          std::max(error, std::abs(rows[i][4] - E * eps * f) / (E * 0.01));
        if (rows[i][8] == 2 && rows[i][9] == 0 && std::abs(eps - 0.006) < 1e-12)
          second_peak = rows[i][4];
        zero_at_end = f == 0 && rows[i][10] == 1;
        // the update after the step
        if (eps_s < 0 && nu * eps > e_s)
          eps_s = eps;
        if (eps_s >= 0)
          f = std::min(f, std::max(0., 1 - (eps - eps_s) * l / w_c));
      }
    check(error < 1e-5,
          "crushing: every point is E eps f(shortening since the split "
          "before) (1e-5 of E x 0.01)");
    const double expected = E * 0.006 * (1 - (0.006 - eps_s) * l / w_c);
    std::cout << "crushing: split at strain " << std::fixed
              << std::setprecision(4) << eps_s
              << ", stress at the second 0.006 peak " << std::setprecision(3)
              << second_peak * 1e-6 << " MPa, closed form " << expected * 1e-6
              << " MPa\n";
    check(std::abs(eps_s - 0.0044) < 1e-9 &&
            std::abs(second_peak - expected) < 1e-5 * E * 0.01,
          "crushing: split at 0.0044 (the first step past e_s / nu), second "
          "0.006 peak = E 0.006 (1 - (0.006 - 0.0044) l / w_c)");
    check(zero_at_end, "crushing: the cell deleted at the end of the fade");
  }

  /**
   * `Deletion stress' s_d: a cell past `Deletion strain' that still carries
   * more than s_d stays. Closed form of the one-cell elastic cube: row i
   * of curve.csv has the stress E eps_i unless the cell was deleted after
   * an earlier step j, which happens at the first j with nu eps_j > e_d and
   * E eps_j <= s_d; the deletion count of row j is then 1.
   */
  void
  check_stress()
  {
    const double       e_d = 1e-5, s_d = 2e6;
    std::ostringstream t;
    t << std::setprecision(17)
      << "set Protocol = cyclic\nset Cycle amplitudes = 0.0009, 0.002\n"
         "set Cycles per amplitude = 1\nset Unloading stress = 0.1e6\n"
         "set Target strain = 0.002\nset Number of steps = 8\n"
         "set Deletion strain = "
      << e_d << "\nset Deletion stress = " << s_d << "\n";
    const masonry::Json s = run("stress", cube(1, t.str()));
    check(s.at("status").get<std::string>() == "completed",
          "stress: completed to the last amplitude");
    const auto   rows    = curve("stress");
    bool         deleted = false, kept = false, count = true;
    double       error = 0, deleted_at = -1, deleted_stress = -1;
    unsigned int n_rows_after = 0;
    for (unsigned int i = 1; i < rows.size(); ++i)
      {
        const double eps      = rows[i][2];
        const double expected = deleted ? 0. : E * eps;
        error = std::max(error, std::abs(rows[i][4] - expected) / (E * 0.01));
        if (deleted)
          ++n_rows_after;
        // past the strain while carrying more than s_d: kept
        if (!deleted && nu * eps > e_d && E * eps > s_d)
          kept = true;
        const bool now = !deleted && nu * eps > e_d && E * eps <= s_d;
        if (now)
          {
            deleted_at     = eps;
            deleted_stress = E * eps;
          }
        deleted = deleted || now;
        count   = count && rows[i][10] == (deleted ? 1 : 0);
      }
    std::cout << "stress: deleted after the step at strain " << std::fixed
              << std::setprecision(6) << deleted_at << " (stress "
              << std::setprecision(3) << deleted_stress * 1e-6 << " MPa), then "
              << n_rows_after << " steps\n";
    check(kept, "stress: the cell past e_d carrying more than s_d stayed");
    check(deleted && n_rows_after > 0 && deleted_stress > 0,
          "stress: deleted on unloading, once it carried at most s_d");
    check(count, "stress: deleted cells in curve.csv as the closed form");
    check(error < 1e-5,
          "stress: every point is E eps before the deletion, 0 after (1e-5 "
          "of E x 0.01)");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_mesh(1, true);
  check_mesh(2, false);
  check_crushing();
  check_stress();
}
