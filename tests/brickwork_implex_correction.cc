/**
 * IMPL-EX steps over the damage tolerance at the step floor (`IMPL-EX
 * floor correction'), on one cube of the `damage plasticity' law in
 * uniaxial tension past its peak (0.1 m, Poisson's ratio 0, frictionless
 * platens, tension plastic strain ratio 0, so that the law's state is its
 * damage alone and the stress of the uniform strain e is the closed-form
 * envelope s(e) = E0 e up to e0 = f_t / E0, then f_t exp(-(e - e0) / w),
 * w = G_f / (f_t h) - f_t / (2 E0)).
 *
 * IMPL-EX solves a step with the damage extrapolated from the two steps
 * before, d*, so the platen stress of the step is (1 - d*) E0 e, and the
 * implicit update after it gives the damage d of the envelope at e. A step
 * is redone smaller while |d - d*| exceeds `IMPL-EX damage tolerance' (tol
 * = 0.05), so an accepted step is off the envelope by at most |d - d*| E0 e
 * <= tol E0 e; but not below `IMPL-EX minimum step', and at that floor the
 * step was accepted with any error: its stress, and the states it keeps,
 * are those of another wall. With the floor at the nominal step (minimum
 * step 1, 24 steps to 2.5 w past the peak) every step with a larger error
 * is at the floor (the first step past the peak extrapolates nothing: d*
 * = 0, d = 0.26).
 *
 * - `accept' (before): some step is off the envelope by more than tol E0 e
 *   (5.1 times, the first step past the peak; this shows the check below
 *   can fail).
 * - `iterate': every step is within tol E0 e of the envelope; the steps
 *   solved again with their updated states lie on it (1e-6 of f_t: one
 *   cell under a prescribed strain, so the updated state does not change
 *   in the second solve and the step is the implicit one).
 * - `iterate at any step', with the floor at 0.01 of the nominal step: a
 *   step over the tolerance is corrected at its own size, not redone
 *   smaller first. The correction of the one cell converges in one pass,
 *   so no step is redone and the run takes the 24 nominal steps; every
 *   step lies within tol E0 e of the envelope, the corrected ones on it
 *   (1e-6 of f_t). `iterate' with the same floor redoes steps (this shows
 *   that the count can fail).
 */
#include <iomanip>

#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  const double E0 = 10e9, f_t = 2e6, G_f = 80, h = 0.1, tol = 0.05;
  const double e0 = f_t / E0, w = G_f / (f_t * h) - f_t / (2 * E0);

  /** The closed-form tension envelope. */
  double
  envelope(const double e)
  {
    return e <= e0 ? E0 * e : f_t * std::exp(-(e - e0) / w);
  }

  masonry::Json
  cube(const std::string &name,
       const std::string &correction,
       const double       minimum_step = 1)
  {
    std::ostringstream t;
    t << std::setprecision(17) << "set Brick length = 0.09\n"
      << "set Brick width = 0.09\nset Brick height = " << h - 0.01
      << "\nset Joint thickness = 0.01\nset Courses = 1\n"
      << "set Length in bricks = 1\nset Elements along the length = 1\n"
      << "set Elements along the width = 1\n"
      << "set Elements along the height = 1\n"
      << "set Platen lateral restraint = free\n"
      << "set Platen direction = 0, 0, 1\nset Target strain = " << e0 + 2.5 * w
      << "\nset Number of steps = 24\n"
      << "set Damage integration = implex\n"
      << "set IMPL-EX damage tolerance = " << tol << "\n"
      << "set IMPL-EX minimum step = " << minimum_step << "\n"
      << "set IMPL-EX floor correction = " << correction << "\n";
    std::ostringstream m;
    m << std::setprecision(17)
      << "subsection Brick material\nset Model = damage plasticity\n"
         "subsection Damage plasticity\n"
      << "set Young's modulus = " << E0 << "\nset Poisson's ratio = 0\n"
      << "set Tensile strength = " << f_t
      << "\nset Tensile fracture energy = " << G_f
      << "\nset Tensile plastic strain ratio = 0\n"
      << "end\nend\nsubsection Bond\nset Pattern = stack\nend\n";
    return run(name, prm(t.str(), m.str()));
  }

  /** The largest |stress - envelope| / (tol E0 e) over the curve. */
  double
  off_envelope(const std::string &name)
  {
    double worst = 0;
    for (const auto &row : curve(name))
      if (row[2] > 0)
        worst =
          std::max(worst,
                   std::abs(row[4] - envelope(row[2])) / (tol * E0 * row[2]));
    return worst;
  }

  /** The steps of log.txt that follow a line `solved again with its updated'.
   */
  std::vector<int>
  corrected_steps(const std::string &name)
  {
    return steps_after("results/" + name + "/log.txt",
                       "solved again with its updated");
  }
  /** The largest |stress - envelope| / f_t over the steps @p steps. */
  double
  off_at(const std::string &name, const std::vector<int> &steps)
  {
    double worst = 0;
    for (const auto &row : curve(name))
      if (std::find(steps.begin(), steps.end(), int(row[0])) != steps.end())
        worst = std::max(worst, std::abs(row[4] - envelope(row[2])) / f_t);
    return worst;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const masonry::Json                      a = cube("accept", "accept");
  check(a.at("status").get<std::string>() == "completed", "accept: completed");
  const double accepted = off_envelope("accept");
  std::cout << "accept: largest distance from the envelope / (tol E0 e) "
            << (accepted > 1 ? "above" : "NOT above") << " 1\n";
  check(accepted > 1 && a.at("implex_steps_over_tolerance").get<double>() > 0,
        "accept: some step at the floor is off the envelope by more than "
        "the tolerance allows");

  const masonry::Json c = cube("iterate", "iterate");
  check(c.at("status").get<std::string>() == "completed", "iterate: completed");
  check(off_envelope("iterate") <= 1 + 1e-9,
        "iterate: every step within tol E0 e of the closed-form envelope");
  check(c.at("implex_steps_uncorrected").get<double>() == 0 &&
          c.at("implex_steps_over_tolerance").get<double>() == 0,
        "iterate: no step left over the tolerance");
  const std::vector<int> steps = corrected_steps("iterate");
  const double           exact = off_at("iterate", steps);
  std::cout << "iterate: " << (steps.size() >= 2 ? "two or more" : "fewer")
            << " steps solved again\n";
  check(steps.size() >= 2 &&
          c.at("implex_steps_corrected").get<double>() == steps.size(),
        "iterate: the steps over the tolerance were solved again");
  check(exact < 1e-6,
        "iterate: the steps solved again lie on the envelope (1e-6 of "
        "f_t)");

  const masonry::Json f = cube("floor", "iterate", 0.01);
  check(f.at("implex_steps_redone").get<double>() > 0,
        "iterate, floor 0.01: steps over the tolerance are redone smaller");
  const masonry::Json any = cube("any", "iterate at any step", 0.01);
  check(any.at("status").get<std::string>() == "completed",
        "any step: completed");
  check(any.at("implex_steps_redone").get<double>() == 0 &&
          any.at("steps").get<double>() == 24,
        "any step: no step redone, the 24 nominal steps");
  check(off_envelope("any") <= 1 + 1e-9,
        "any step: every step within tol E0 e of the closed-form envelope");
  const std::vector<int> fixed = corrected_steps("any");
  check(fixed.size() >= 2 &&
          any.at("implex_steps_corrected").get<double>() == fixed.size() &&
          off_at("any", fixed) < 1e-6,
        "any step: the steps over the tolerance were corrected at their own "
        "size and lie on the envelope (1e-6 of f_t)");
}
