// Every LP solver configuration (Clp: dual/primal simplex, barrier with
// crossover; GLPK: dual/primal simplex; each with and without presolve)
// against linear programs whose optimum is known analytically, and the
// detection of unbounded and infeasible problems.

#include "lp_common.h"

using namespace lp_test;
using masonry::lp::infinity;

namespace
{
  /** Compare @p s with the known optimum and (optionally) known duals. */
  void
  check(const std::string         &name,
        const std::string         &label,
        const LinearProgram       &lp,
        const Solution            &s,
        const double               objective,
        const std::vector<double> &x,
        const std::vector<double> &duals = {})
  {
    bool ok =
      s.status == Status::optimal && close(s.objective, objective, 1e-10);
    for (unsigned int j = 0; ok && j < x.size(); ++j)
      ok = close(s.x[j], x[j], 1e-10);
    for (unsigned int i = 0; ok && i < duals.size(); ++i)
      ok = close(s.row_duals[i], duals[i], 1e-10);
    if (!ok)
      {
        std::cout << "FAILED " << name << ", " << label << ": "
                  << to_string(s.status) << " " << s.message << " objective "
                  << std::setprecision(17) << s.objective << std::endl;
        return;
      }
    std::cout << "OK " << name << ", " << label
              << ": objective = " << round6(s.objective) << ", x =";
    for (const double v : s.x)
      std::cout << " " << round6(v);
    if (!duals.empty())
      {
        std::cout << ", y =";
        for (const double v : s.row_duals)
          std::cout << " " << round6(v);
      }
    std::cout << std::endl;
    check_duality(name + ", " + label, lp, s);
  }

  void
  check_status(const std::string &name,
               const std::string &label,
               const Solution    &s,
               const Status       expected)
  {
    std::cout << (s.status == expected ? "OK " : "FAILED ") << name << ", "
              << label << ": " << to_string(s.status)
              << (s.status == expected ? "" : " (" + s.message + ")")
              << std::endl;
  }

  // (1) max 3x + 2y  s.t.  x + y <= 4,  x + 3y <= 6,  0 <= x <= 3, y >= 0.
  // Vertices of the feasible polygon: (0,0) -> 0, (3,0) -> 9, (3,1) -> 11,
  // (0,2) -> 4, and x + y = 4 meets x + 3y = 6 at (3,1) as well. Optimum
  // (3, 1) with value 11 (unique: the objective gradient (3,2) lies strictly
  // inside the cone of the active normals (1,1), (1,0)).
  LinearProgram
  make_lp1()
  {
    LinearProgram      lp1;
    const unsigned int x = lp1.add_column(3, 0, 3, "x");
    const unsigned int y = lp1.add_column(2, 0, infinity, "y");
    const unsigned int r = lp1.add_row(-infinity, 4, "r1");
    const unsigned int s = lp1.add_row(-infinity, 6, "r2");
    lp1.add_entry(r, x, 1);
    lp1.add_entry(r, y, 1);
    lp1.add_entry(s, x, 1);
    lp1.add_entry(s, y, 2); // duplicate entries: 2 + 1 = 3
    lp1.add_entry(s, y, 1);
    return lp1;
  }

  // (2) max 5x + 4y  s.t.  6x + 4y <= 24,  x + 2y <= 6,  x, y >= 0.
  // Both rows active: x = 3, y = 1.5, value 21. Duals from
  // A^T y = c: 6 y1 + y2 = 5, 4 y1 + 2 y2 = 4 -> y1 = 0.75, y2 = 0.5
  // (d(21)/d(24) = 0.75 > 0 as a larger bound gives a larger maximum);
  // b^T y = 18 + 3 = 21.
  LinearProgram
  make_lp2()
  {
    LinearProgram lp2;
    lp2.add_column(5, 0, infinity);
    lp2.add_column(4, 0, infinity);
    lp2.add_row(-infinity, 24);
    lp2.add_row(-infinity, 6);
    lp2.add_entry(0, 0, 6);
    lp2.add_entry(0, 1, 4);
    lp2.add_entry(1, 0, 1);
    lp2.add_entry(1, 1, 2);
    return lp2;
  }

  // (3) Transportation: supplies 20, 30; demands 10, 25, 15 (balanced);
  // costs [[8, 6, 10], [9, 12, 13]]; minimise. Source 2 is costlier by
  // (1, 6, 3): its 30 units go where the penalty is least: 10 to customer 1,
  // 15 to customer 3, 5 to customer 2; source 1 sends 20 to customer 2.
  // Cost 9*10 + 12*5 + 13*15 + 6*20 = 465. Optimality: potentials u2 = 0,
  // v = (9, 12, 13), u1 = -6 give reduced costs 5 (x11) and 3 (x13) > 0, so
  // the optimum is unique. (Duals not unique: one equality is redundant.)
  LinearProgram
  make_lp3()
  {
    LinearProgram lp3;
    lp3.maximize = false;
    {
      const double supply[2]  = {20, 30};
      const double demand[3]  = {10, 25, 15};
      const double cost[2][3] = {{8, 6, 10}, {9, 12, 13}};
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          lp3.add_column(cost[i][j], 0, infinity);
      for (unsigned int i = 0; i < 2; ++i)
        {
          const unsigned int r = lp3.add_row(supply[i], supply[i]);
          for (unsigned int j = 0; j < 3; ++j)
            lp3.add_entry(r, 3 * i + j, 1);
        }
      for (unsigned int j = 0; j < 3; ++j)
        {
          const unsigned int r = lp3.add_row(demand[j], demand[j]);
          for (unsigned int i = 0; i < 2; ++i)
            lp3.add_entry(r, 3 * i + j, 1);
        }
    }
    return lp3;
  }

  // (4) Equalities, free variables, a ranged row and a free row:
  // min 2a + 3b - c  s.t.  a + b + c = s (= 10),  a - b = t (= 2),
  // -1 <= b + c <= U (= 5.5),  -inf < a + c < inf,  a, b free, 0 <= c <= 4.
  // Eliminating a = t + b, b = (s - t - c)/2 gives 2a + 3b - c =
  // 2.5 s - 0.5 t - 3.5 c: c as large as b + c <= U allows. With b + c = U
  // active: c = t + 2U - s = 3 (inside [0, 4]), b = s - t - U = 2.5,
  // a = s - U = 4.5, value 6s - 4t - 7U = 13.5. Duals (derivatives of the
  // minimum): y = (6, -4, -7, 0); y3 = -7 <= 0 at an active upper bound of a
  // minimisation, as documented.
  LinearProgram
  make_lp4()
  {
    LinearProgram lp4;
    lp4.maximize = false;
    {
      const unsigned int a  = lp4.add_column(2, -infinity, infinity);
      const unsigned int b  = lp4.add_column(3, -infinity, infinity);
      const unsigned int c  = lp4.add_column(-1, 0, 4);
      const unsigned int r1 = lp4.add_row(10, 10);
      const unsigned int r2 = lp4.add_row(2, 2);
      const unsigned int r3 = lp4.add_row(-1, 5.5);
      const unsigned int r4 = lp4.add_row(-infinity, infinity);
      lp4.add_entry(r1, a, 1);
      lp4.add_entry(r1, b, 1);
      lp4.add_entry(r1, c, 1);
      lp4.add_entry(r2, a, 1);
      lp4.add_entry(r2, b, -1);
      lp4.add_entry(r3, b, 1);
      lp4.add_entry(r3, c, 1);
      lp4.add_entry(r4, a, 1);
      lp4.add_entry(r4, c, 1);
    }
    return lp4;
  }

  // (5) Unbounded: max x + y  s.t.  x - y <= 1,  x, y >= 0 (ray (1, 1)).
  LinearProgram
  make_unbounded()
  {
    LinearProgram unbounded;
    unbounded.add_column(1, 0, infinity);
    unbounded.add_column(1, 0, infinity);
    unbounded.add_row(-infinity, 1);
    unbounded.add_entry(0, 0, 1);
    unbounded.add_entry(0, 1, -1);
    return unbounded;
  }

  // (6) Infeasible: x + y <= 1 and x + y >= 3.
  LinearProgram
  make_infeasible()
  {
    LinearProgram infeasible;
    infeasible.add_column(1, 0, infinity);
    infeasible.add_column(1, 0, infinity);
    infeasible.add_row(-infinity, 1);
    infeasible.add_row(3, infinity);
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        infeasible.add_entry(i, j, 1);
    return infeasible;
  }

  // (7) Infeasible through the column bounds: x + y >= 5, 0 <= x, y <= 2.
  LinearProgram
  make_infeasible_bounds()
  {
    LinearProgram infeasible_bounds;
    infeasible_bounds.maximize = false;
    infeasible_bounds.add_column(1, 0, 2);
    infeasible_bounds.add_column(1, 0, 2);
    infeasible_bounds.add_row(5, infinity);
    infeasible_bounds.add_entry(0, 0, 1);
    infeasible_bounds.add_entry(0, 1, 1);
    return infeasible_bounds;
  }

  // (8) Primal and dual infeasible: max x + y, y <= -1 as a row, y >= 0,
  // x free and unconstrained (a ray, but no feasible point): infeasible.
  LinearProgram
  make_both()
  {
    LinearProgram both;
    both.add_column(1, -infinity, infinity);
    both.add_column(1, 0, infinity);
    both.add_row(-infinity, -1);
    both.add_entry(0, 1, 1);
    return both;
  }

} // namespace

int
main()
{
  const std::vector<Config> configs           = all_configs();
  const LinearProgram       lp1               = make_lp1();
  const LinearProgram       lp2               = make_lp2();
  const LinearProgram       lp3               = make_lp3();
  const LinearProgram       lp4               = make_lp4();
  const LinearProgram       unbounded         = make_unbounded();
  const LinearProgram       infeasible        = make_infeasible();
  const LinearProgram       infeasible_bounds = make_infeasible_bounds();
  const LinearProgram       both              = make_both();

  for (const Config &config : configs)
    {
      const auto &s = *config.solver;
      check("max 3x+2y", config.label, lp1, s.solve(lp1), 11, {3, 1});
      check("max 5x+4y",
            config.label,
            lp2,
            s.solve(lp2),
            21,
            {3, 1.5},
            {0.75, 0.5});
      check("transportation",
            config.label,
            lp3,
            s.solve(lp3),
            465,
            {0, 20, 0, 10, 5, 15});
      check("equalities/free",
            config.label,
            lp4,
            s.solve(lp4),
            13.5,
            {4.5, 2.5, 3},
            {6, -4, -7, 0});
      check_status("unbounded",
                   config.label,
                   s.solve(unbounded),
                   Status::unbounded);
      check_status("infeasible rows",
                   config.label,
                   s.solve(infeasible),
                   Status::infeasible);
      check_status("infeasible bounds",
                   config.label,
                   s.solve(infeasible_bounds),
                   Status::infeasible);
      check_status("primal and dual infeasible",
                   config.label,
                   s.solve(both),
                   Status::infeasible);
    }
}
