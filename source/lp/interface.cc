#include <masonry/core/parameters.h>
#include <masonry/lp/interface.h>

namespace masonry
{
  namespace lp
  {
    std::string
    to_string(const Status status)
    {
      switch (status)
        {
          case Status::optimal:
            return "optimal";
          case Status::unbounded:
            return "unbounded";
          case Status::infeasible:
            return "infeasible";
          case Status::failed:
            return "failed";
        }
      return "failed";
    }

    const char *
    Interface::default_plugin()
    {
      return "clp";
    }

    std::string
    Interface::selection_documentation()
    {
      return "The linear-programming solver used for limit analysis and "
             "every other linear program of the run.";
    }

    void
    Interface::declare_common_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Export MPS file",
                        "false",
                        dealii::Patterns::Bool(),
                        "Whether to write each linear program to the file "
                        "`lp.mps' in the output directory (MPS format, "
                        "readable by `clp' and `glpsol --freemps'; a "
                        "maximisation is written as the minimisation of the "
                        "negated objective). Unitless flag.");
      declare_ranged_entry(
        prm,
        "Time limit",
        "0",
        {0, 1e7, "s"},
        "Time limit of one LP solve, in seconds (as measured "
        "by the back-end: CPU time for Clp, wall-clock time "
        "for GLPK); 0 means no limit. A solve that reaches "
        "the limit reports status `failed'.");
      prm.declare_entry(
        "Warm starts",
        "true",
        dealii::Patterns::Bool(),
        "Whether the LPs of one `minimum thickness' bisection start from the "
        "basis of the last LP that stood (Clp: rows matched by contact point "
        "and component, so LPs whose implied rows differ share a basis; GLPK "
        "always starts cold). Settlement and limit-load LPs, also in a "
        "genetic algorithm, are always solved from scratch (warm they were "
        "slower and less accurate, doc/rigid-blocks.md). false: every LP "
        "from scratch, for "
        "checks and timing (the same result within the LP tolerances; near "
        "a minimum thickness the starting basis can decide `stands', see "
        "doc/rigid-blocks.md). Unitless flag.");
      prm.declare_entry(
        "Optimality check tolerance",
        "1e-6",
        dealii::Patterns::Double(1e-12, 1e-2),
        "Every optimum a solver returns is checked on the LP itself: the "
        "largest violation of a row or column bound by the primal point, the "
        "largest dual (or reduced cost) whose sign asks for a bound that is "
        "infinite, both in the LP's scaled units, and the gap between the "
        "primal objective and the bound the duals give, relative to the "
        "objective (at least 1e-6). An optimum with one of them above this "
        "tolerance is solved again (GLPK: from its basis on the unscaled "
        "problem, then in exact rational arithmetic; Clp: by the primal "
        "simplex on the unscaled problem from its basis); if it still fails, "
        "the run warns with the numbers (screen, summary.json `lp_check'). "
        "Dimensionless.");
    }

    void
    Interface::parse_common_parameters(dealii::ParameterHandler &prm)
    {
      export_mps_file       = prm.get_bool("Export MPS file");
      time_limit_seconds    = prm.get_double("Time limit");
      warm_starts_enabled   = prm.get_bool("Warm starts");
      check_tolerance_value = prm.get_double("Optimality check tolerance");
    }


    Solution
    Interface::solve_warm(const LinearProgram &lp, WarmStart &) const
    {
      return solve(lp);
    }

    bool
    Interface::export_mps() const
    {
      return export_mps_file;
    }

    double
    Interface::time_limit() const
    {
      return time_limit_seconds;
    }

    bool
    Interface::warm_starts() const
    {
      return warm_starts_enabled;
    }

    double
    Interface::check_tolerance() const
    {
      return check_tolerance_value;
    }
  } // namespace lp
} // namespace masonry
