// Warm starts (lp::Interface::solve_warm): a sequence of LPs of one shape is
// solved cold and warm (each from the basis of the previous optimal solve),
// and both must give the same status and optimum (1e-9 relative; 1e-8
// absolute at the degenerate optimum 0, the solver's tolerance). The set
// has statuses known from theory:
// - cones "max c^T x, a_i^T x >= 0, x free" (the shape of a mechanism LP of
//   minimum thickness): with c = -sum mu_i a_i, mu >= 0, the optimum is 0 at
//   a fully degenerate vertex (all rows active, Farkas); with c = x* and
//   a_i^T x* > 0 for all i, x* is a ray: unbounded ("mechanism");
// - the same cone with a_0^T x >= 1 and a_1 = -a_0: infeasible
//   ("incompatible");
// - random bounded LPs (lp_common.h) perturbed from one to the next, whose
//   optimum is also computed by GLPK (an independent solver);
// - the cones again with some rows left out (a different set in each LP)
//   and the rows identified by WarmStart::row_keys (their index in the full
//   cone), as the bisection of `minimum thickness' does when rows implied by
//   others are left out: a warm start from an LP with other rows. Leaving
//   out rows can make the optimal cone unbounded, so there the status is
//   GLPK's (and 0 is the optimum if bounded).

#include "lp_common.h"

using namespace lp_test;
using masonry::lp::infinity;
using masonry::lp::WarmStart;

namespace
{
  constexpr unsigned int n_cone = 12, m_cone = 40;

  /** The cone LP number @p k of the sequence (kind = k % 3). */
  LinearProgram
  cone_lp(const unsigned int k, std::mt19937 &g, double *mu_sum = nullptr)
  {
    std::vector<std::vector<double>> a(m_cone, std::vector<double>(n_cone));
    std::vector<double>              ray(n_cone);
    for (auto &r : ray)
      r = uniform(g, -1, 1);
    for (auto &row : a)
      {
        double dot = 0;
        for (unsigned int j = 0; j < n_cone; ++j)
          {
            row[j] = std::round(uniform(g, -5, 5) * 4) / 4;
            dot += row[j] * ray[j];
          }
        if (dot < 0) // orient every row so that the ray is inside
          for (auto &v : row)
            v = -v;
      }
    const unsigned int kind = k % 3;
    LinearProgram      lp;
    lp.maximize = true;
    std::vector<double> c(n_cone, 0.);
    if (kind == 1)
      c = ray;
    else
      for (unsigned int i = 0; i < m_cone; ++i)
        {
          const double mu = std::floor(uniform(g, 0, 3));
          if (mu_sum)
            *mu_sum += mu;
          for (unsigned int j = 0; j < n_cone; ++j)
            c[j] -= mu * a[i][j];
        }
    for (unsigned int j = 0; j < n_cone; ++j)
      lp.add_column(c[j], -infinity, infinity);
    for (unsigned int i = 0; i < m_cone; ++i)
      {
        if (kind == 2 && i == 1)
          a[1] = a[0];
        const double sign = (kind == 2 && i == 1) ? -1 : 1;
        lp.add_row(kind == 2 && i == 0 ? 1 : 0, infinity);
        for (unsigned int j = 0; j < n_cone; ++j)
          if (a[i][j] != 0)
            lp.add_entry(i, j, sign * a[i][j]);
      }
    return lp;
  }

  const char *
  expected_status(const unsigned int k)
  {
    return k % 3 == 0 ? "optimal" : k % 3 == 1 ? "unbounded" : "infeasible";
  }

  /** Random LP number @p k: one draw, its costs and bounds perturbed. */
  LinearProgram
  perturbed_lp(const unsigned int k)
  {
    const LinearProgram base = random_lp(60, 90, 7);
    std::mt19937        g(100 + k);
    LinearProgram       lp;
    lp.maximize = true;
    for (unsigned int j = 0; j < base.n_columns(); ++j)
      lp.add_column(base.objective()[j] * (1 + 0.2 * uniform(g, -1, 1)),
                    base.column_lower()[j],
                    base.column_upper()[j]);
    for (unsigned int i = 0; i < base.n_rows(); ++i)
      {
        const double shift = 0.1 * uniform(g, 0, 1);
        lp.add_row(base.row_lower()[i] - shift, base.row_upper()[i] + shift);
      }
    for (const auto &e : base.entries())
      lp.add_entry(e.row, e.column, e.value * (1 + 0.05 * uniform(g, -1, 1)));
    return lp;
  }
} // namespace

int
main()
{
  const auto glpk = create("glpk", "Method", "dual simplex", true);
  for (const std::string algorithm :
       {"automatic", "dual simplex", "primal simplex", "barrier"})
    {
      const auto   solver = create("clp", "Algorithm", algorithm, true);
      WarmStart    warm;
      std::mt19937 g(3);
      unsigned int n_ok = 0, n_lp = 0;
      for (unsigned int k = 0; k < 12; ++k, ++n_lp)
        {
          const LinearProgram lp   = cone_lp(k, g);
          const Solution      cold = solver->solve(lp);
          const Solution      hot  = solver->solve_warm(lp, warm);
          // the optimum 0 is reached to the solver tolerance (a few 1e-9
          // here), warm or cold
          const bool same = cold.status == hot.status &&
                            (cold.status != Status::optimal ||
                             std::abs(hot.objective - cold.objective) < 1e-8);
          const bool right =
            to_string(cold.status) == expected_status(k) &&
            (cold.status != Status::optimal || std::abs(cold.objective) < 1e-8);
          n_ok += same && right;
          if (!same || !right)
            std::cout << "FAILED clp (" << algorithm << ") cone " << k
                      << ": expected " << expected_status(k) << ", cold "
                      << to_string(cold.status) << " " << cold.objective
                      << ", warm " << to_string(hot.status) << " "
                      << hot.objective << std::endl;
        }
      for (unsigned int k = 0; k < 8; ++k, ++n_lp)
        {
          const LinearProgram lp   = perturbed_lp(k);
          const Solution      cold = solver->solve(lp);
          const Solution      hot  = solver->solve_warm(lp, warm);
          const Solution      ref  = glpk->solve(lp);
          const bool          ok   = cold.status == Status::optimal &&
                          hot.status == Status::optimal &&
                          close(hot.objective, cold.objective, 1e-9) &&
                          close(cold.objective, ref.objective, 1e-7);
          n_ok += ok;
          if (!ok)
            std::cout << "FAILED clp (" << algorithm << ") perturbed " << k
                      << ": cold " << std::setprecision(17) << cold.objective
                      << " warm " << hot.objective << " glpk " << ref.objective
                      << std::endl;
          if (algorithm == "automatic")
            std::cout << "perturbed LP " << k
                      << ": optimum = " << round6(ref.objective) << std::endl;
        }
      // rows left out: row i of the full cone is dropped from LP k if
      // (i + k) % 5 == 0 (rows 0 and 1 make the infeasible kind: kept)
      WarmStart    keyed;
      unsigned int n_keyed_ok = 0;
      std::mt19937 h(5);
      for (unsigned int k = 0; k < 12; ++k)
        {
          double              mu_sum = 0;
          const LinearProgram full   = cone_lp(k, h, &mu_sum);
          LinearProgram       lp;
          lp.maximize = true;
          for (unsigned int j = 0; j < full.n_columns(); ++j)
            lp.add_column(full.objective()[j], -infinity, infinity);
          std::vector<int> row_of(full.n_rows(), -1);
          keyed.row_keys.clear();
          for (unsigned int i = 0; i < full.n_rows(); ++i)
            if (i < 2 || (i + k) % 5 != 0)
              {
                row_of[i] =
                  lp.add_row(full.row_lower()[i], full.row_upper()[i]);
                keyed.row_keys.push_back(i);
              }
          for (const auto &e : full.entries())
            if (row_of[e.row] >= 0)
              lp.add_entry(row_of[e.row], e.column, e.value);
          const Solution cold = solver->solve(lp);
          const Solution hot  = solver->solve_warm(lp, keyed);
          const Solution ref  = glpk->solve(lp);
          // at the degenerate optimum 0, c^T x = -sum mu_i a_i^T x is at
          // most sum mu_i times the largest violation of a row a_i^T x >= 0,
          // which a simplex keeps below its primal tolerance (1e-7 in Clp)
          const auto within = [&](const Solution &s) {
            double violation = 0;
            for (const double a : full.row_activities(s.x))
              violation = std::max(violation, -a);
            return violation <= 1e-7 &&
                   std::abs(s.objective) <= 1e-9 + mu_sum * violation;
          };
          const bool ok =
            cold.status == hot.status && cold.status == ref.status &&
            (cold.status != Status::optimal || (within(cold) && within(hot)));
          n_keyed_ok += ok;
          if (!ok)
            std::cout << "FAILED clp (" << algorithm << ") cone " << k
                      << " with rows left out: glpk " << to_string(ref.status)
                      << ", cold " << to_string(cold.status) << " "
                      << cold.objective << ", warm " << to_string(hot.status)
                      << " " << hot.objective << std::endl;
        }
      std::cout << (n_keyed_ok == 12 ? "OK" : "FAILED") << " clp (" << algorithm
                << "): warm = cold = glpk on " << n_keyed_ok
                << " of 12 cones with rows left out (rows matched by key)"
                << (keyed.n_warm > 0 ? ", warm starts used" :
                                       ", NO warm start used")
                << std::endl;
      std::cout << (n_ok == n_lp ? "OK" : "FAILED") << " clp (" << algorithm
                << "): warm = cold on " << n_ok << " of " << n_lp
                << " LPs (4 optimal at a degenerate vertex, 4 unbounded, 4 "
                   "infeasible, 8 perturbed)"
                << (warm.n_warm > 0 ? ", warm starts used" :
                                      ", NO warm start used")
                << std::endl;
    }
}
