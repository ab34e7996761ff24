/**
 * Clp's barrier without presolve (the route of `automatic' for
 * Mohr–Coulomb LPs) keeps the ordering and symbolic factorisation of its
 * normal matrix between LPs of the same sparsity pattern in a thread, and
 * forms the normal matrix by a plan made once per pattern. On random
 * bounded feasible LPs (150 rows, 250 columns) that share one of two
 * patterns and differ in every coefficient, bound and cost:
 * - every optimum equals the dual simplex's with presolve (an independent
 *   algorithm) to 1e-9 relative, whether the solve reused a structure or
 *   not;
 * - an LP solved after others of its pattern (reused structure) gives
 *   bit for bit the optimum and solution of the same LP solved first in a
 *   new thread (structure computed by Clp): the reuse changes no
 *   arithmetic.
 */
#include <thread>

#include "lp_common.h"

using namespace lp_test;

namespace
{
  /**
   * A feasible bounded LP with the pattern of @p pattern_seed (4 entries
   * per column) and bounds, costs and values from @p value_seed.
   */
  LinearProgram
  patterned_lp(const unsigned int pattern_seed, const unsigned int value_seed)
  {
    const unsigned int                     m = 148, n = 250;
    std::mt19937                           p(pattern_seed), g(value_seed);
    std::uniform_real_distribution<double> u(0, 1);
    const auto uniform = [&u](std::mt19937 &r, double a, double b) {
      return a + (b - a) * u(r);
    };
    LinearProgram lp;
    lp.maximize = true;
    std::vector<double> x0(n), ax(m, 0.);
    for (unsigned int j = 0; j < n; ++j)
      {
        const double lower = -1 - uniform(g, 0, 2);
        const double upper = lower + 1 + uniform(g, 0, 8);
        lp.add_column(uniform(g, -1, 1), lower, upper);
        x0[j] = uniform(g, lower, upper);
      }
    std::vector<unsigned int> rows, kinds;
    std::vector<double>       values;
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int k = 0; k < 4; ++k)
        {
          // distinct rows per column, so that no entry sums to zero
          const unsigned int i = (p() % (m / 4)) * 4 + k;
          const double       v = uniform(g, 1, 10) * (g() % 2 ? 1 : -1);
          rows.push_back(i);
          values.push_back(v);
          ax[i] += v * x0[j];
        }
    for (unsigned int i = 0; i < m; ++i)
      {
        const double slack = uniform(g, 0.1, 2);
        switch (p() % 3)
          {
            case 0:
              lp.add_row(-masonry::lp::infinity, ax[i] + slack);
              break;
            case 1:
              lp.add_row(ax[i] - slack, masonry::lp::infinity);
              break;
            default:
              lp.add_row(ax[i] - slack, ax[i] + slack);
          }
      }
    for (unsigned int j = 0, e = 0; j < n; ++j)
      for (unsigned int k = 0; k < 4; ++k, ++e)
        lp.add_entry(rows[e], j, values[e]);
    return lp;
  }
} // namespace

int
main()
{
  const auto barrier   = create("clp", "Algorithm", "barrier", false);
  const auto reference = create("clp", "Algorithm", "dual simplex", true);

  // (pattern, values): pattern 1 three times, then pattern 2, then
  // pattern 1 again (two patterns are kept)
  const std::vector<std::pair<unsigned int, unsigned int>> sequence = {
    {1, 11}, {1, 12}, {1, 13}, {2, 21}, {1, 14}, {2, 22}};
  bool                  agree = true;
  std::vector<Solution> solutions;
  for (const auto &[pattern, values] : sequence)
    {
      const LinearProgram lp = patterned_lp(pattern, values);
      const Solution      s  = barrier->solve(lp);
      const Solution      r  = reference->solve(lp);
      const bool          ok = s.status == Status::optimal &&
                      r.status == Status::optimal &&
                      close(s.objective, r.objective, 1e-9);
      if (!ok)
        std::cout << "  pattern " << pattern << ", values " << values
                  << ": barrier " << std::setprecision(17) << s.objective
                  << " (" << to_string(s.status) << "), dual simplex "
                  << r.objective << "\n";
      agree = agree && ok;
      solutions.push_back(s);
    }
  std::cout << (agree ? "OK" : "FAILED")
            << " barrier (structure reused) = dual simplex with presolve "
               "(1e-9) on 6 LPs of 2 patterns\n";

  // the same LPs, each first in a new thread: no structure to reuse
  bool identical = true;
  for (unsigned int k = 1; k < sequence.size(); ++k)
    {
      Solution    fresh;
      std::thread t([&]() {
        fresh =
          barrier->solve(patterned_lp(sequence[k].first, sequence[k].second));
      });
      t.join();
      const bool same = fresh.status == solutions[k].status &&
                        fresh.objective == solutions[k].objective &&
                        fresh.x == solutions[k].x &&
                        fresh.iterations == solutions[k].iterations;
      if (!same)
        std::cout << "  LP " << k << ": " << std::setprecision(17)
                  << fresh.objective << " (" << fresh.iterations
                  << " iterations) in a new thread, " << solutions[k].objective
                  << " (" << solutions[k].iterations << ") after others\n";
      identical = identical && same;
    }
  std::cout << (identical ? "OK" : "FAILED")
            << " a reused structure gives bit for bit the solution of a "
               "new one (5 LPs)\n";
}
