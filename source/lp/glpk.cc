/**
 * @file
 * The `glpk` LP solver back-end: the GNU Linear Programming Kit's simplex.
 */
#include <masonry/lp/interface.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <climits>
#include <cmath>
#include <csetjmp>
#include <glpk.h>

namespace masonry
{
  namespace lp
  {
    namespace
    {
      /** GLPK's bound type for the bounds @p lower, @p upper. */
      int
      bound_type(const double lower, const double upper)
      {
        const bool has_lower = lower > -infinity, has_upper = upper < infinity;
        if (has_lower && has_upper)
          return lower == upper ? GLP_FX : GLP_DB;
        if (has_lower)
          return GLP_LO;
        if (has_upper)
          return GLP_UP;
        return GLP_FR;
      }

      /** A finite value for GLPK (which ignores the unused bound). */
      double
      finite(const double bound)
      {
        return std::isfinite(bound) ? bound : 0.;
      }

      /** Where GLPK's error hook returns to. */
      struct ErrorJump
      {
        std::jmp_buf buffer;
      };

      extern "C" void
      glpk_error_hook(void *info)
      {
        // GLPK's documented recovery: free the environment (and with it
        // every problem object), then leave the failing routine
        glp_free_env();
        std::longjmp(static_cast<ErrorJump *>(info)->buffer, 1);
      }

      /**
       * @p method (glp_simplex() or glp_exact()) that returns -1 instead of
       * aborting the process when GLPK hits an internal error; @p problem
       * is then freed already. No object with a destructor may live in
       * this frame (longjmp).
       */
      int
      guarded(int (*method)(glp_prob *, const glp_smcp *),
              glp_prob       *problem,
              const glp_smcp *parameters)
      {
        ErrorJump jump;
        if (setjmp(jump.buffer) != 0)
          return -1;
        glp_error_hook(glpk_error_hook, &jump);
        const int result = method(problem, parameters);
        glp_error_hook(nullptr, nullptr);
        return result;
      }

      /** glp_simplex() through guarded(). */
      int
      guarded_simplex(glp_prob *problem, const glp_smcp *parameters)
      {
        return guarded(glp_simplex, problem, parameters);
      }

      /** The optimal point and row duals of @p problem into @p solution,
       * checked on @p lp. */
      void
      read_optimum(glp_prob *problem, const LinearProgram &lp, Solution &s)
      {
        const unsigned int n = lp.n_columns(), m = lp.n_rows();
        s.x.resize(n);
        for (unsigned int j = 0; j < n; ++j)
          s.x[j] = glp_get_col_prim(problem, j + 1);
        // GLPK's row duals are d(c^T x)/d(row bound) in the sense of the
        // problem: our convention already
        s.row_duals.resize(m);
        for (unsigned int i = 0; i < m; ++i)
          s.row_duals[i] = glp_get_row_dual(problem, i + 1);
        s.objective = lp.objective_value(s.x);
        s.check     = check_pair(lp, s.x, s.row_duals);
        s.checked   = true;
      }
    } // namespace

    /**
     * LP solver back-end on GLPK's simplex method (glp_simplex), with
     * automatic scaling and optional presolve.
     */
    class Glpk : public Interface
    {
    public:
      /** Declare `Method` and `Presolve` in `subsection Glpk`. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Read `subsection Glpk`. */
      void
      parse_parameters(dealii::ParameterHandler &prm) override;

      /** Solve @p lp with GLPK. */
      Solution
      solve(const LinearProgram &lp) const override;

    private:
      /** Value of `Method`. */
      std::string method = "dual simplex";
      /** Value of `Presolve`. */
      bool presolve = true;

      /** A GLPK problem object holding @p lp (scaled). */
      static glp_prob *
      create(const LinearProgram &lp);

      /**
       * An optimum in @p solution that fails the check on the LP (GLPK's
       * tolerances apply to its scaled problem: a dome's LP came back with
       * a row violated by 1.7e-3): the primal simplex from the basis of
       * @p problem on the unscaled problem, then, if that fails too, GLPK's
       * exact rational simplex from the basis. Keeps the first optimum
       * that passes, else the one with the smallest violation, and says
       * so in the message. Returns the problem object (nullptr if GLPK
       * freed it on an internal error).
       */
      glp_prob *
      resolve(glp_prob            *problem,
              const LinearProgram &lp,
              glp_smcp             parameters,
              Solution            &solution) const;
    };


    void
    Glpk::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        "Method",
        "dual simplex",
        dealii::Patterns::Selection("dual simplex|primal simplex"),
        "Simplex method of GLPK: `dual simplex' (GLPK's GLP_DUALP: dual, "
        "falling back to primal when the start is not dual feasible) or "
        "`primal simplex'. Unitless choice.");
      prm.declare_entry("Presolve",
                        "true",
                        dealii::Patterns::Bool(),
                        "Whether GLPK's LP presolver simplifies the problem "
                        "first. When it finds no dual feasible solution, the "
                        "problem is solved again without presolve to tell "
                        "an unbounded from an infeasible problem. Unitless "
                        "flag.");
    }

    void
    Glpk::parse_parameters(dealii::ParameterHandler &prm)
    {
      method   = prm.get("Method");
      presolve = prm.get_bool("Presolve");
    }

    glp_prob *
    Glpk::create(const LinearProgram &lp)
    {
      const unsigned int n = lp.n_columns(), m = lp.n_rows();
      glp_prob          *problem = glp_create_prob();
      glp_set_obj_dir(problem, lp.maximize ? GLP_MAX : GLP_MIN);
      if (m > 0)
        glp_add_rows(problem, m);
      if (n > 0)
        glp_add_cols(problem, n);
      for (unsigned int i = 0; i < m; ++i)
        {
          const double l = lp.row_lower()[i], u = lp.row_upper()[i];
          glp_set_row_bnds(
            problem, i + 1, bound_type(l, u), finite(l), finite(u));
        }
      for (unsigned int j = 0; j < n; ++j)
        {
          const double l = lp.column_lower()[j], u = lp.column_upper()[j];
          glp_set_col_bnds(
            problem, j + 1, bound_type(l, u), finite(l), finite(u));
          glp_set_obj_coef(problem, j + 1, lp.objective()[j]);
        }

      // GLPK forbids duplicates: load the merged column matrix (1-based
      // arrays, element 0 unused)
      const LinearProgram::ColumnMatrix a  = lp.column_matrix();
      const std::size_t                 ne = a.value.size();
      std::vector<int>                  ia(ne + 1), ja(ne + 1);
      std::vector<double>               ar(ne + 1);
      for (unsigned int j = 0; j < n; ++j)
        for (int k = a.start[j]; k < a.start[j + 1]; ++k)
          {
            ia[k + 1] = a.row_index[k] + 1;
            ja[k + 1] = j + 1;
            ar[k + 1] = a.value[k];
          }
      glp_load_matrix(problem, ne, ia.data(), ja.data(), ar.data());
      glp_scale_prob(problem, GLP_SF_AUTO);
      return problem;
    }

    glp_prob *
    Glpk::resolve(glp_prob            *problem,
                  const LinearProgram &lp,
                  glp_smcp             parameters,
                  Solution            &solution) const
    {
      const std::string first = solution.check.describe();
      // the largest of the three numbers the check compares
      const auto worst = [](const PairCheck &c) {
        return std::max({c.primal_residual, c.dual_residual, c.relative_gap()});
      };
      parameters.presolve = GLP_OFF;
      parameters.meth     = GLP_PRIMAL;
      int counted         = glp_get_it_cnt(problem);
      const std::
        array<std::pair<const char *, int (*)(glp_prob *, const glp_smcp *)>, 2>
          routes = {
            {{"the primal simplex on the unscaled problem", glp_simplex},
             {"the exact (rational) simplex", glp_exact}}};
      for (const auto &[name, method] : routes)
        {
          glp_unscale_prob(problem);
          const int result = guarded(method, problem, &parameters);
          if (result == -1)
            {
              solution.message += " (failed the check, " + first + "; " + name +
                                  " stopped on an internal error)";
              return nullptr;
            }
          solution.iterations += glp_get_it_cnt(problem) - counted;
          counted = glp_get_it_cnt(problem);
          if (result != 0 || glp_get_status(problem) != GLP_OPT)
            continue;
          Solution again;
          read_optimum(problem, lp, again);
          if (worst(again.check) < worst(solution.check))
            {
              solution.x         = std::move(again.x);
              solution.row_duals = std::move(again.row_duals);
              solution.objective = again.objective;
              solution.check     = again.check;
            }
          if (solution.check.within(check_tolerance()))
            {
              solution.message += " (failed the check, " + first +
                                  "; solved again by " + name + ")";
              return problem;
            }
        }
      solution.message +=
        " (failed the check, " + first +
        "; still failing after a re-solve: " + solution.check.describe() + ")";
      return problem;
    }

    Solution
    Glpk::solve(const LinearProgram &lp) const
    {
      const auto start_time = std::chrono::steady_clock::now();
      Solution   solution;
      glp_term_out(GLP_OFF);

      glp_smcp parameters;
      glp_init_smcp(&parameters);
      parameters.msg_lev = GLP_MSG_OFF;
      parameters.meth    = method == "primal simplex" ? GLP_PRIMAL : GLP_DUALP;
      if (time_limit() > 0)
        parameters.tm_lim = time_limit() * 1000 < INT_MAX ?
                              static_cast<int>(std::ceil(time_limit() * 1000)) :
                              INT_MAX;

      glp_prob *problem   = create(lp);
      parameters.presolve = presolve ? GLP_ON : GLP_OFF;
      int result          = guarded_simplex(problem, &parameters);
      if (result == -1)
        problem = nullptr; // freed by the error hook
      int iterations_before = 0;

      // a verdict is final if optimal, infeasible or unbounded with a
      // feasible point (GLPK's primal phase 1 ran), or on the time limit
      const auto decided = [&]() {
        if (result == GLP_ENOPFS || result == GLP_ETMLIM)
          return true;
        if (result != 0)
          return false;
        const int status = glp_get_status(problem);
        return status == GLP_OPT || status == GLP_NOFEAS ||
               (status == GLP_UNBND && glp_get_prim_stat(problem) == GLP_FEAS);
      };
      if (!decided())
        {
          // GLP_ENODFS from presolve (unbounded OR infeasible), an undecided
          // status of the dual simplex, or a failure: solve again without
          // presolve, with the primal simplex whose phase 1 decides
          // feasibility first
          if (problem)
            {
              iterations_before = glp_get_it_cnt(problem);
              glp_delete_prob(problem);
            }
          problem             = create(lp);
          parameters.presolve = GLP_OFF;
          parameters.meth     = GLP_PRIMAL;
          result              = guarded_simplex(problem, &parameters);
          if (result == -1)
            problem = nullptr;
        }

      if (problem)
        solution.iterations = iterations_before + glp_get_it_cnt(problem);

      if (result == GLP_ENOPFS)
        {
          solution.status  = Status::infeasible;
          solution.message = "GLPK: no primal feasible solution (presolve)";
        }
      else if (result == 0)
        {
          const int status = glp_get_status(problem);
          if (status == GLP_OPT)
            {
              solution.status = Status::optimal;
              read_optimum(problem, lp, solution);
              solution.message = "GLPK: optimal";
              if (!solution.check.within(check_tolerance()))
                problem = resolve(problem, lp, parameters, solution);
            }
          else if (status == GLP_NOFEAS)
            {
              solution.status  = Status::infeasible;
              solution.message = "GLPK: no primal feasible solution";
            }
          else if (status == GLP_UNBND &&
                   glp_get_prim_stat(problem) == GLP_FEAS)
            {
              solution.status  = Status::unbounded;
              solution.message = "GLPK: unbounded";
            }
          else
            solution.message =
              "GLPK: finished with status " + std::to_string(status);
        }
      else if (result == GLP_ETMLIM)
        solution.message = "GLPK: time limit reached";
      else if (result == -1)
        solution.message = "GLPK: internal error";
      else
        solution.message =
          "GLPK: glp_simplex failed with code " + std::to_string(result);

      if (problem)
        glp_delete_prob(problem);
      solution.seconds = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start_time)
                           .count();
      return solution;
    }
  } // namespace lp
} // namespace masonry

MASONRY_REGISTER_LP_SOLVER(masonry::lp::Glpk,
                           "glpk",
                           "GNU Linear Programming Kit: primal or dual "
                           "simplex with scaling and optional presolve; an "
                           "optimum that fails the check on the LP "
                           "(`Optimality check tolerance') is solved again "
                           "from its basis on the unscaled problem, then in "
                           "exact rational arithmetic.")
