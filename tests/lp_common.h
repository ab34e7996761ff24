/**
 * @file
 * Helpers shared by the lp_*.cc tests: create every LP solver configuration,
 * compare with known values, check strong duality.
 */
#ifndef masonry_tests_lp_common_h
#define masonry_tests_lp_common_h

#include <masonry/lp/interface.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace lp_test
{
  using masonry::lp::LinearProgram;
  using masonry::lp::Solution;
  using masonry::lp::Status;

  /** One solver configuration: plugin name plus its settings. */
  struct Config
  {
    /** Label printed in the output. */
    std::string label;
    /** The solver, created through the registry. */
    std::unique_ptr<masonry::lp::Interface> solver;
  };

  /** Create @p plugin with @p entry = @p value and Presolve = @p presolve. */
  inline std::unique_ptr<masonry::lp::Interface>
  create(const std::string &plugin,
         const std::string &entry,
         const std::string &value,
         const bool         presolve)
  {
    dealii::ParameterHandler prm;
    masonry::plugins::Registry<masonry::lp::Interface>::declare_parameters(prm);
    prm.enter_subsection("LP solver");
    prm.enter_subsection(plugin == "clp" ? "Clp" : "Glpk");
    prm.set(entry, value);
    prm.set("Presolve", presolve);
    prm.leave_subsection();
    prm.leave_subsection();
    return masonry::plugins::Registry<masonry::lp::Interface>::create(prm,
                                                                      plugin);
  }

  /** All configurations of both back-ends. */
  inline std::vector<Config>
  all_configs()
  {
    std::vector<Config> configs;
    for (const bool presolve : {true, false})
      {
        const std::string p = presolve ? "presolve" : "no presolve";
        for (const std::string a :
             {"automatic", "dual simplex", "primal simplex", "barrier"})
          configs.push_back({"clp (" + a + ", " + p + ")",
                             create("clp", "Algorithm", a, presolve)});
        for (const std::string m : {"dual simplex", "primal simplex"})
          configs.push_back({"glpk (" + m + ", " + p + ")",
                             create("glpk", "Method", m, presolve)});
      }
    return configs;
  }

  /** @p value rounded to 6 significant digits (and -0 printed as 0). */
  inline std::string
  round6(const double value)
  {
    std::ostringstream s;
    s << std::setprecision(6) << (std::abs(value) < 1e-9 ? 0. : value);
    return s.str();
  }

  /** |a - b| <= tol * max(1, |b|). */
  inline bool
  close(const double a, const double b, const double tol)
  {
    return std::abs(a - b) <= tol * std::max(1., std::abs(b));
  }

  /**
   * The dual objective @f$\sum_i y_i b_i + \sum_j d_j \beta_j@f$ with the
   * bounds b, beta chosen by the signs of the duals y and reduced costs
   * d = c - A^T y under the documented convention; infinite (a NaN is
   * returned) if a dual has the wrong sign for the bounds, i.e. the duals are
   * not dual feasible.
   */
  inline double
  dual_objective(const LinearProgram &lp, const Solution &s)
  {
    const double        sense = lp.maximize ? 1. : -1.;
    std::vector<double> d     = lp.objective();
    for (const auto &e : lp.entries())
      d[e.column] -= e.value * s.row_duals[e.row];
    const std::vector<double> ax    = lp.row_activities(s.x);
    double                    total = 0;
    auto                      add   = [&total, sense](const double dual,
                               const double lower,
                               const double upper,
                               const double activity) {
      // derivative w.r.t. the upper bound is >= 0 for a maximisation
      if (std::abs(dual) <= 1e-9)
        total += dual * activity;
      else if (dual * sense > 0)
        total += std::isfinite(upper) ? dual * upper : NAN;
      else
        total += std::isfinite(lower) ? dual * lower : NAN;
    };
    for (unsigned int i = 0; i < lp.n_rows(); ++i)
      add(s.row_duals[i], lp.row_lower()[i], lp.row_upper()[i], ax[i]);
    for (unsigned int j = 0; j < lp.n_columns(); ++j)
      add(d[j], lp.column_lower()[j], lp.column_upper()[j], s.x[j]);
    return total;
  }

  /** Print "OK"/"FAILED" for the strong-duality check of @p s. */
  inline void
  check_duality(const std::string   &label,
                const LinearProgram &lp,
                const Solution      &s,
                const double         tol = 1e-8)
  {
    const double dual = dual_objective(lp, s);
    if (close(dual, s.objective, tol))
      std::cout << "OK " << label
                << ": strong duality c^T x = b^T y = " << round6(dual)
                << std::endl;
    else
      std::cout << "FAILED " << label << ": primal " << std::setprecision(17)
                << s.objective << " dual " << dual << std::endl;
  }

  /** Uniform double in [a, b) from a 32-bit mt19937 draw (portable). */
  inline double
  uniform(std::mt19937 &g, const double a, const double b)
  {
    return a + (b - a) * (static_cast<double>(g()) + 0.5) / 4294967296.;
  }

  /**
   * A random sparse LP with @p m rows and @p n columns (about 4 entries per
   * column), feasible by construction (rows are built around a point x0
   * within the column bounds) and bounded (every column has finite bounds).
   * Rows are a mix of <=, >=, ranged and equality constraints.
   */
  inline LinearProgram
  random_lp(const unsigned int m, const unsigned int n, const unsigned int seed)
  {
    std::mt19937  g(seed);
    LinearProgram lp;
    lp.maximize = true;
    std::vector<double> x0(n);
    for (unsigned int j = 0; j < n; ++j)
      {
        const double lower = std::floor(uniform(g, -3, 1));
        const double upper = lower + 1 + std::floor(uniform(g, 0, 9));
        lp.add_column(uniform(g, -1, 1), lower, upper);
        x0[j] = uniform(g, lower, upper);
      }
    std::vector<double> ax(m, 0.);
    for (unsigned int i = 0; i < m; ++i)
      lp.add_row(-masonry::lp::infinity, masonry::lp::infinity);
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int k = 0; k < 4; ++k)
        {
          const unsigned int i = static_cast<unsigned int>(uniform(g, 0, m));
          const double       v = std::round(uniform(g, -10, 10) * 100) / 100;
          lp.add_entry(i, j, v); // duplicates are summed
          ax[i] += v * x0[j];
        }
    // rebuild with the bounds now that A x0 is known
    LinearProgram result;
    result.maximize = true;
    for (unsigned int j = 0; j < n; ++j)
      result.add_column(lp.objective()[j],
                        lp.column_lower()[j],
                        lp.column_upper()[j]);
    for (unsigned int i = 0; i < m; ++i)
      {
        const unsigned int kind  = g() % 4;
        const double       slack = uniform(g, 0.1, 2);
        if (kind == 0)
          result.add_row(-masonry::lp::infinity, ax[i] + slack);
        else if (kind == 1)
          result.add_row(ax[i] - slack, masonry::lp::infinity);
        else if (kind == 2)
          result.add_row(ax[i] - slack, ax[i] + slack);
        else
          result.add_row(ax[i], ax[i]);
      }
    for (const auto &e : lp.entries())
      result.add_entry(e.row, e.column, e.value);
    return result;
  }
} // namespace lp_test

#endif
