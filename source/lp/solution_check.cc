/**
 * @file
 * The check of an LP solver's answer on the LP itself (solution_check.h).
 */
#include <masonry/lp/linear_program.h>
#include <masonry/lp/solution_check.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace masonry
{
  namespace lp
  {
    double
    PairCheck::relative_gap() const
    {
      return std::abs(dual_objective - primal_objective) /
             std::max({std::abs(primal_objective),
                       std::abs(dual_objective),
                       gap_floor});
    }

    bool
    PairCheck::within(const double tolerance) const
    {
      return relative_gap() <= tolerance && primal_residual <= tolerance &&
             dual_residual <= tolerance;
    }

    std::string
    PairCheck::describe() const
    {
      char text[200];
      std::snprintf(text,
                    sizeof(text),
                    "relative gap %.2e, primal residual %.2e, dual residual "
                    "%.2e, bound %.12g, objective %.12g, scale %.6g",
                    relative_gap(),
                    primal_residual,
                    dual_residual,
                    dual_objective,
                    primal_objective,
                    work_scale);
      return text;
    }

    double
    work_scale(const LinearProgram &lp)
    {
      // |c|_1 times the largest finite bound
      double largest = 0;
      for (const auto *b : {&lp.row_lower(),
                            &lp.row_upper(),
                            &lp.column_lower(),
                            &lp.column_upper()})
        for (const double v : *b)
          if (std::isfinite(v))
            largest = std::max(largest, std::abs(v));
      double scale = 0;
      for (const double cj : lp.objective())
        scale += std::abs(cj) * largest;
      return scale;
    }

    PairCheck
    check_pair(const LinearProgram       &lp,
               const std::vector<double> &x,
               const std::vector<double> &y)
    {
      PairCheck    c;
      const double sense = lp.maximize ? 1. : -1.;
      // the bound a multiplier's sign selects (maximisation: a positive
      // one the upper), its product into the bound, or the part against
      // an infinite bound into the dual residual
      const auto add = [&](const double dual, const double l, const double u) {
        if (dual == 0)
          return;
        const double bound = sense * dual > 0 ? u : l;
        if (std::isfinite(bound))
          c.dual_objective += dual * bound;
        else
          c.dual_residual = std::max(c.dual_residual, std::abs(dual));
      };
      const auto activity = lp.row_activities(x);
      for (unsigned int i = 0; i < lp.n_rows(); ++i)
        {
          c.primal_residual = std::max({c.primal_residual,
                                        lp.row_lower()[i] - activity[i],
                                        activity[i] - lp.row_upper()[i]});
          add(y[i], lp.row_lower()[i], lp.row_upper()[i]);
        }
      std::vector<double> d = lp.objective();
      for (const auto &e : lp.entries())
        d[e.column] -= e.value * y[e.row];
      for (unsigned int j = 0; j < lp.n_columns(); ++j)
        {
          c.primal_residual = std::max({c.primal_residual,
                                        lp.column_lower()[j] - x[j],
                                        x[j] - lp.column_upper()[j]});
          add(d[j], lp.column_lower()[j], lp.column_upper()[j]);
        }
      c.primal_objective = lp.objective_value(x);
      c.work_scale       = work_scale(lp);
      return c;
    }
  } // namespace lp
} // namespace masonry
