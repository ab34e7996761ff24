// Every LP solver configuration on a random sparse feasible bounded LP of
// 200 rows and 300 columns (fixed seed, portable uniform mapping): all agree
// on the optimum to relative 1e-8, every solution is primal feasible, and
// strong duality c^T x = b^T y (+ reduced costs times active column bounds)
// holds to relative 1e-8 with the documented dual sign convention.

#include "lp_common.h"

using namespace lp_test;

int
main()
{
  const LinearProgram lp = random_lp(200, 300, 20240607);
  std::cout << "random LP: " << lp.n_rows() << " rows, " << lp.n_columns()
            << " columns, " << lp.n_nonzeros() << " entries" << std::endl;

  const std::vector<Config> configs   = all_configs();
  double                    reference = 0;
  bool                      first     = true;
  for (const Config &config : configs)
    {
      const Solution s = config.solver->solve(lp);
      if (s.status != Status::optimal)
        {
          std::cout << "FAILED " << config.label << ": " << to_string(s.status)
                    << " " << s.message << std::endl;
          continue;
        }
      if (first)
        {
          reference = s.objective;
          first     = false;
          std::cout << "optimum = " << round6(reference) << std::endl;
        }

      // primal feasibility
      double                    violation = 0;
      const std::vector<double> ax        = lp.row_activities(s.x);
      for (unsigned int i = 0; i < lp.n_rows(); ++i)
        violation = std::max(
          {violation, lp.row_lower()[i] - ax[i], ax[i] - lp.row_upper()[i]});
      for (unsigned int j = 0; j < lp.n_columns(); ++j)
        violation = std::max({violation,
                              lp.column_lower()[j] - s.x[j],
                              s.x[j] - lp.column_upper()[j]});

      if (close(s.objective, reference, 1e-8) && violation < 1e-7)
        std::cout << "OK " << config.label
                  << ": objective = " << round6(s.objective)
                  << ", primal feasible" << std::endl;
      else
        std::cout << "FAILED " << config.label << ": objective "
                  << std::setprecision(17) << s.objective << " vs " << reference
                  << ", violation " << violation << std::endl;
      check_duality(config.label, lp, s);
    }
}
