/**
 * The speed options of the Newton solver give the same answer: the coarse
 * cracked wallette of brickwork_solver_fallback (2 x 1 x 1 cells per
 * brick, damage-plasticity bricks, bilinear joints, strength scatter,
 * deletion, IMPL-EX, cycled to 2.7 times the strain at peak) run
 *
 * - with the defaults (`Predictor = constant', `Residual reference =
 *   present reaction', chord corrections: `Newton chord contraction' 0.1);
 * - with `Newton chord contraction = 0' (the defaults otherwise: a new
 *   tangent and factorisation for every correction), the reference of the
 *   two below;
 * - with `Predictor = extrapolated', `Residual reference = largest
 *   reaction' and no chord corrections;
 * - with these and `Factorisation reuse iterations = 10' (GMRES with the
 *   last factorisation as the preconditioner).
 *
 * Every run converges each step to the Newton tolerance (1e-8 of the
 * reactions), so the results may differ by no more than what that lets
 * through: the cycle peaks up to the peak agree to 1e-6 of the peak stress.
 * Past the peak the path is sensitive to such differences (the IMPL-EX
 * step control decides on damage errors that differ in the last digits).
 * The wall collapses in the third cycle (its peak there, on the reloading
 * before the collapse, is 0.43 of the peak): the peak of that cycle agrees
 * to 2 % of the peak (measured with `IMPL-EX crack opening' = frozen: 0.4
 * % chord corrections against none, 1.2 % predictor against none; with
 * the cracks' opening extrapolated the wall collapsed in the second
 * cycle's unloading and these agreed to 1 %). After the collapse every run
 * carries less than 0.1 of the peak in the fourth cycle (measured 0.019 to
 * 0.045 of it: what remains depends on which cells went first). The reuse
 * changes only the linear solves, which GMRES does to 1e-10: with it the
 * cycle peaks up to the peak are those of the direct solves to 1e-6, and
 * the third one, where the same sensitivity amplifies the 1e-10, to 0.1 %
 * (measured 6e-6).
 * The chord corrections (the default `Newton chord contraction' 0.1) solve
 * near the solution with the factorisation of the last tangent; they change
 * the iterates, not the equations, and the steps converge to the same
 * tolerance: the cycle peaks up to the peak agree with those without them
 * to 1e-6 of the peak, the third one to 2 % as for the predictor, and the
 * run needs at least 15 % fewer factorisations per step (each Newton
 * correction from a good iterate is replaced by chord corrections).
 * `Newton chord across steps' starts each step with chord corrections
 * with the factorisation kept from the step before: the same equations and
 * tolerance again, so the same cycle peaks to 1e-6 of the peak up to the
 * peak and to 2 % in the collapse (measured 3.9e-7 and 5.6e-5), and at least
 * 25 % fewer factorisations per step (measured 34 % fewer).
 * The extrapolated predictor starts each step
 * nearer the solution, so it needs fewer Newton iterations, and with the
 * reuse fewer factorisations than linear solves are done.
 *
 * `Assembly threads = 2' (the defaults otherwise) sums the same element
 * forces and matrices in the same order, and deal.II's FEValues data are
 * computed on one thread either way, so its curve.csv must equal the
 * serial run's byte for byte (it did not while FEValues were evaluated on
 * the threads: deal.II reuses a translated cell's values on one thread
 * only, which changed the last digits). The same holds with the units'
 * `Nonlocal length' (0.05 m), whose averages use the strains at the
 * points, and which changes the curve.
 */
#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  std::string
  wallette(const std::string &options)
  {
    return cracked_cyclic_wallette("set Linear solver = direct\n" + options);
  }

  /** The peak stresses of the cycles (cycles.csv) of run @p name. */
  std::vector<double>
  cycle_peaks(const std::string &name)
  {
    std::ifstream       in("results/" + name + "/cycles.csv");
    std::string         line;
    std::vector<double> peaks;
    std::getline(in, line); // header
    while (std::getline(in, line))
      {
        std::stringstream s(line);
        std::string       cell;
        for (unsigned int k = 0; k < 3; ++k)
          std::getline(s, cell, ',');
        peaks.push_back(std::stod(cell));
      }
    return peaks;
  }

  /** The text of file @p file of run @p name. */
  std::string
  text(const std::string &name, const std::string &file)
  {
    std::ifstream     in("results/" + name + "/" + file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  /** Largest difference of the cycle peaks of two runs, relative to
   * @p peak, over the cycles [first, last); 1 when the runs have different
   * numbers of cycles. */
  double
  peak_difference(const std::vector<double> &a,
                  const std::vector<double> &b,
                  const double               peak,
                  const unsigned int         first,
                  const unsigned int         last)
  {
    if (a.size() != b.size() || last > a.size())
      return 1;
    double diff = 0;
    for (unsigned int k = first; k < last; ++k)
      diff = std::max(diff, std::abs(a[k] - b[k]) / peak);
    return diff;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const masonry::Json                      before =
    run("before",
        wallette("set Predictor = constant\n"
                 "set Residual reference = present reaction\n"));
  const std::string   largest   = "set Predictor = extrapolated\n"
                                  "set Residual reference = largest reaction\n"
                                  "set Newton chord contraction = 0\n";
  const masonry::Json predictor = run("predictor", wallette(largest));
  const masonry::Json reuse =
    run("reuse",
        wallette(largest + "set Factorisation reuse iterations = 10\n"));
  const masonry::Json no_chord =
    run("no_chord",
        wallette("set Predictor = constant\n"
                 "set Residual reference = present reaction\n"
                 "set Newton chord contraction = 0\n"));
  const masonry::Json across =
    run("across",
        wallette("set Predictor = constant\n"
                 "set Residual reference = present reaction\n"
                 "set Newton chord across steps = true\n"));
  const masonry::Json threads =
    run("threads",
        wallette("set Predictor = constant\n"
                 "set Residual reference = present reaction\n"
                 "set Assembly threads = 2\n"));
  // the same with the units' nonlocal average (its strains and points are
  // computed on one thread too)
  const std::string   local    = "set Predictor = constant\n"
                                 "set Residual reference = present reaction\n";
  const std::string   nonlocal = "set Nonlocal length = 0.05\n";
  const masonry::Json nonlocal_serial =
    run("nonlocal",
        cracked_cyclic_wallette("set Linear solver = direct\n" + local,
                                nonlocal));
  const masonry::Json nonlocal_threads =
    run("nonlocal_threads",
        cracked_cyclic_wallette("set Linear solver = direct\n" + local +
                                  "set Assembly threads = 2\n",
                                nonlocal));
  for (const auto &[name, s] :
       {std::pair{"before", &before},
        std::pair{"across", &across},
        std::pair{"nonlocal", &nonlocal_serial},
        std::pair{"nonlocal_threads", &nonlocal_threads},
        std::pair{"no_chord", &no_chord},
        std::pair{"predictor", &predictor},
        std::pair{"reuse", &reuse},
        std::pair{"threads", &threads}})
    check(s->at("status").get<std::string>() == "completed",
          std::string(name) + ": completed");

  check(!text("before", "curve.csv").empty() &&
          text("threads", "curve.csv") == text("before", "curve.csv"),
        "two assembly threads: curve.csv the same byte for byte as one "
        "thread's");
  check(!text("nonlocal", "curve.csv").empty() &&
          text("nonlocal", "curve.csv") != text("before", "curve.csv") &&
          text("nonlocal_threads", "curve.csv") ==
            text("nonlocal", "curve.csv"),
        "nonlocal length 0.05 m: a different curve, and two assembly threads "
        "give it byte for byte");

  const double peak = before.at("peak_stress").get<double>();
  const auto   a = cycle_peaks("before"), b = cycle_peaks("predictor"),
             c = cycle_peaks("reuse"), d = cycle_peaks("no_chord");
  // the cycle of the peak (the second) and those before it
  const unsigned int n = 2;
  check(a.size() == 4 && relative(a[1], peak) < 1e-9,
        "before: four cycles, the peak in the second");
  check(peak_difference(a, d, peak, 0, n) < 1e-6,
        "chord corrections: the same cycle peaks (1e-6 of the peak) up to the "
        "peak as a new tangent for every correction");
  check(peak_difference(a, d, peak, n, n + 1) < 2e-2,
        "chord corrections: the peak of the cycle of the collapse within 2 % "
        "of the peak");
  const auto per_step = [](const masonry::Json &s, const std::string &key) {
    return s.at(key).get<double>() / s.at("steps").get<double>();
  };
  const auto e = cycle_peaks("across");
  check(peak_difference(a, e, peak, 0, n) < 1e-6,
        "chord corrections across steps: the same cycle peaks (1e-6 of the "
        "peak) up to the peak");
  check(peak_difference(a, e, peak, n, n + 1) < 2e-2,
        "chord corrections across steps: the peak of the cycle of the "
        "collapse within 2 % of the peak");
  check(e.size() == 4 && e[2] < 0.5 * peak && e[3] < 0.1 * peak,
        "chord corrections across steps: collapsed in the third cycle");
  check(across.at("chord_solves").get<double>() >
            before.at("chord_solves").get<double>() &&
          per_step(across, "factorisations") <
            0.75 * per_step(before, "factorisations"),
        "chord corrections across steps: at least 25 % fewer factorisations "
        "per step than chord corrections within a step only");
  check(before.at("chord_solves").get<double>() > 0 &&
          no_chord.at("chord_solves").get<double>() == 0 &&
          per_step(before, "factorisations") <
            0.85 * per_step(no_chord, "factorisations"),
        "chord corrections: at least 15 % fewer factorisations per step");
  check(peak_difference(d, b, peak, 0, n) < 1e-6,
        "extrapolated predictor: the same cycle peaks (1e-6 of the peak) up "
        "to the peak");
  check(peak_difference(d, b, peak, n, n + 1) < 2e-2,
        "extrapolated predictor: the peak of the cycle of the collapse within "
        "2 % of the peak");
  check(peak_difference(b, c, peak, 0, n) < 1e-6,
        "factorisation reuse: the same cycle peaks as the direct solves "
        "(1e-6 of the peak) up to the peak");
  check(peak_difference(b, c, peak, n, n + 1) < 1e-3,
        "factorisation reuse: the peak of the cycle of the collapse within "
        "0.1 % of the peak");
  bool collapsed = true;
  for (const auto *p : {&a, &b, &c, &d})
    collapsed = collapsed && p->size() == 4 && (*p)[2] < 0.5 * peak &&
                (*p)[3] < 0.1 * peak;
  check(collapsed,
        "every run: the third cycle's peak below 0.5 of the peak, the "
        "fourth's below 0.1 (collapsed in the third cycle)");
  check(predictor.at("newton_iterations").get<double>() <
          0.9 * no_chord.at("newton_iterations").get<double>() *
            predictor.at("steps").get<double>() /
            no_chord.at("steps").get<double>(),
        "extrapolated predictor: at least 10 % fewer Newton iterations per "
        "step");
  check(before.at("factorisations").get<double>() +
              before.at("factorisations_reused").get<double>() +
              before.at("chord_solves").get<double>() ==
            before.at("linear_solves").get<double>() &&
          reuse.at("reuse_gmres_solves").get<double>() > 0 &&
          reuse.at("factorisations").get<double>() +
              reuse.at("reuse_gmres_solves").get<double>() +
              reuse.at("factorisations_reused").get<double>() +
              reuse.at("chord_solves").get<double>() ==
            reuse.at("linear_solves").get<double>() &&
          reuse.at("factorisations").get<double>() <
            0.5 * reuse.at("linear_solves").get<double>(),
        "factorisation reuse: fewer than half the solves factorise, the rest "
        "are GMRES solves");
}
