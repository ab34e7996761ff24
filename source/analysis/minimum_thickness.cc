/**
 * @file
 * The minimum-thickness analysis: the smallest factor on the thickness
 * field at which a rigid-block vault stands under its own weight.
 */
#include <masonry/analysis/rigid_block_analysis.h>
#include <masonry/core/json.h>
#include <masonry/core/parameters.h>
#include <masonry/geometry/interface.h>
#include <masonry/rigid_blocks/interface_model.h>
#include <masonry/rigid_blocks/mechanism.h>

#include <chrono>
#include <iomanip>
#include <limits>

namespace masonry
{
  namespace analysis
  {
    /**
     * Bisection on the thickness factor s. The vault stands at s if the LP
     * "maximise q·d − D(d)" over the mechanisms allowed by the interface
     * model (fixed supports, dead loads q) is bounded (its optimum is then
     * 0 at d = 0, and its dual is a statically admissible state); it
     * collapses if the LP is unbounded. The result is the bracket
     * [s_collapse, s_stand] with (s_stand − s_collapse) ≤ tolerance ×
     * s_stand; the thickness reported is s_stand × the thickness field.
     */
    class MinimumThickness : public RigidBlockAnalysis
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        declare_block_parameters(prm);
        prm.declare_entry("Tolerance",
                          "1e-5",
                          dealii::Patterns::Double(1e-12, 0.5),
                          "Relative width of the final bracket of the "
                          "thickness factor (dimensionless): the bisection "
                          "stops when (s_stand − s_collapse) ≤ Tolerance × "
                          "s_stand.");
        declare_ranged_entry(prm,
                             "Largest factor",
                             "64",
                             {1, 10000, "(dimensionless)"},
                             "Largest factor on the thickness field tried "
                             "while bracketing (dimensionless); a vault that "
                             "still collapses at it is reported as `mechanism' "
                             "(it cannot stand at any thickness, e.g. a "
                             "support is missing).");
        prm.declare_entry("Smallest factor",
                          "1e-3",
                          dealii::Patterns::Double(1e-9, 1),
                          "Smallest factor on the thickness field tried "
                          "while bracketing (dimensionless); a vault that "
                          "still stands at it is reported as "
                          "`stands_at_smallest_factor'.");
      }

      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        parse_block_parameters(prm, "Minimum thickness");
        tolerance       = prm.get_double("Tolerance");
        largest_factor  = prm.get_double("Largest factor");
        smallest_factor = prm.get_double("Smallest factor");
      }

      std::string
      fitness_name() const override
      {
        return "minimum thickness factor";
      }

      double
      evaluate(RunContext &context) override
      {
        double       lo = 0, hi = 0;
        unsigned int steps = 0;
        if (bisect(context, lo, hi, steps) != "optimal")
          return -std::numeric_limits<double>::infinity();
        return hi;
      }

      void
      analyse(RunContext &context) override
      {
        auto &pcout          = context.pcout;
        Json &summary        = context.summary;
        summary["tolerance"] = tolerance;

        double            lo = 0, hi = 0; // collapses at lo, stands at hi
        unsigned int      steps  = 0;
        const std::string status = bisect(context, lo, hi, steps);
        if (status == "stands_at_smallest_factor")
          {
            summary["minimum_thickness_factor"] = hi;
            return report(context,
                          status,
                          "The vault stands at the smallest thickness "
                          "factor tried (`Smallest factor'): its strength "
                          "does not depend on thickness in this range (e.g. "
                          "bonded supports or cohesive joints).");
          }
        if (status == "mechanism")
          return report(context,
                        status,
                        "The vault collapses at every thickness factor up "
                        "to `Largest factor': it cannot stand on these "
                        "supports (e.g. a support is missing).");

        // the collapse mechanism just below the minimum: minimise the
        // dissipation with the work of the loads normalised to 1
        const rigid_blocks::Motion motion = collapse_mechanism(lo, context);
        // the statically admissible state at the minimum (dual of the
        // standing problem)
        stands(hi, context);
        const lp::Solution &solution = last_solution;
        record(last_problem->lp, solution, context);
        const auto forces = rigid_blocks::contact_forces(*last_problem,
                                                         solution,
                                                         last_force_scale,
                                                         true);

        const dealii::Point<3> reference =
          geometry->patches().front().point(dealii::Point<2>(0.5, 0.5));
        summary["status"]                    = "optimal";
        summary["minimum_thickness_factor"]  = hi;
        summary["collapse_thickness_factor"] = lo;
        summary["minimum_thickness"]         = geometry->thickness(reference);
        summary["bisection_steps"]           = steps;
        pcout << "Result: minimum thickness factor " << std::setprecision(8)
              << hi << " (collapses at " << lo << "), thickness "
              << summary.at("minimum_thickness").get<double>()
              << " m at the centre of the first patch, " << steps
              << " LP solves\n";
        write_mechanism(motion, forces, context);
      }

    private:
      /**
       * Bracket and bisect the thickness factor: on return the vault
       * collapses at @p lo and stands at @p hi. Returns "optimal",
       * "stands_at_smallest_factor" or "mechanism".
       */
      std::string
      bisect(RunContext &context, double &lo, double &hi, unsigned int &steps)
      {
        // no basis from an earlier bisection (another mesh of the
        // adaptation): near the minimum the starting basis can decide
        // "stands" at the LP tolerances, and the result must depend on the
        // mesh only (the adaptation looks up repeated meshes, and the best
        // mesh is analysed again)
        warm       = lp::WarmStart();
        auto check = [&](const double s) {
          ++steps;
          const bool ok = stands(s, context);
          if (!quiet)
            context.pcout << "  thickness factor " << std::setprecision(8) << s
                          << ": " << (ok ? "stands" : "collapses") << "\n";
          return ok;
        };
        if (check(1.))
          {
            hi = 1;
            lo = 0.5;
            while (check(lo))
              {
                hi = lo;
                lo /= 2;
                if (lo < smallest_factor)
                  return "stands_at_smallest_factor";
              }
          }
        else
          {
            lo = 1;
            hi = 2;
            while (!check(hi))
              {
                lo = hi;
                hi *= 2;
                if (hi > largest_factor)
                  return "mechanism";
              }
          }
        while (hi - lo > tolerance * hi)
          {
            const double mid       = 0.5 * (lo + hi);
            (check(mid) ? hi : lo) = mid;
          }
        return "optimal";
      }

      /**
       * Build the model with thickness factor @p s and the LP "maximise
       * (q·d − D)/|q|" with fixed supports; keep it in last_problem.
       */
      void
      assemble(const double s)
      {
        geometry->set_thickness_factor(s);
        // only the thickness changes between the bisection's models
        if (reuse_evaluations())
          update_thickness();
        else
          build_model();
        const auto start = std::chrono::steady_clock::now();
        last_force_scale = dead_load_magnitude();
        last_problem     = std::make_unique<rigid_blocks::MechanismProblem>(
          rigid_blocks::build_mechanism_problem(
            *model, *joints, nullptr, bonded_supports, leave_out_implied_rows));
        auto      &lp   = last_problem->lp;
        const auto work = rigid_blocks::load_work(dead_force,
                                                  dead_moment,
                                                  last_problem->length,
                                                  last_force_scale);
        for (unsigned int c = 0; c < work.size(); ++c)
          lp.set_cost(c, work[c]);
        for (unsigned int c = last_problem->n_block_columns; c < lp.n_columns();
             ++c)
          lp.set_cost(c, -last_problem->dissipation[c] / last_force_scale);
        lp.maximize = true;
        seconds_assembly += std::chrono::duration<double>(
                              std::chrono::steady_clock::now() - start)
                              .count();
      }

      /** Whether the vault stands at thickness factor @p s. */
      bool
      stands(const double s, RunContext &context)
      {
        assemble(s);
        // each of the bisection's LPs starts from the basis of the last
        // one that stood; the rows left out as implied differ between
        // thicknesses, so rows are matched by contact point and component
        // (before, an LP with another row set started cold: 0.17 s of the
        // 0.75 s of LP solves of the 256-block arch)
        warm.row_keys.resize(last_problem->lp.n_rows());
        for (unsigned int r = 0; r < warm.row_keys.size(); ++r)
          warm.row_keys[r] = -1ll - r;
        for (unsigned int p = 0; p < last_problem->point_rows.size(); ++p)
          for (unsigned int k = 0; k < 3; ++k)
            if (last_problem->point_rows[p][k] >= 0)
              warm.row_keys[last_problem->point_rows[p][k]] = 3ll * p + k;
        last_solution = solve(last_problem->lp, context, "lp.mps", &warm);
        AssertThrow(last_solution.status != lp::Status::infeasible,
                    dealii::ExcMessage(
                      "the LP of a vault at rest is infeasible, which "
                      "cannot happen with fixed supports (d = 0 is "
                      "admissible): a solver failure"));
        return last_solution.status == lp::Status::optimal;
      }

      /**
       * The collapse mechanism at thickness factor @p s: minimise D with
       * q·d = 1, scaled so that its largest centroid translation is 1 cm.
       */
      rigid_blocks::Motion
      collapse_mechanism(const double s, RunContext &context)
      {
        assemble(s);
        auto              &lp  = last_problem->lp;
        const unsigned int row = lp.add_row(1, 1);
        for (unsigned int c = 0; c < last_problem->n_block_columns; ++c)
          {
            if (lp.objective()[c] != 0)
              lp.add_entry(row, c, lp.objective()[c]);
            lp.set_cost(c, 0);
          }
        for (unsigned int c = last_problem->n_block_columns; c < lp.n_columns();
             ++c)
          lp.set_cost(c, last_problem->dissipation[c] / last_force_scale);
        lp.maximize                   = false;
        const lp::Solution   solution = solve(lp, context, "collapse.mps");
        rigid_blocks::Motion motion(model->blocks().size());
        if (solution.status != lp::Status::optimal)
          {
            context.pcout << "Warning: no collapse mechanism found at factor "
                          << s << " (LP " << lp::to_string(solution.status)
                          << ")\n";
            return motion;
          }
        context.summary["collapse_load_multiplier"] = solution.objective;
        return rigid_blocks::motion_from_solution(*last_problem,
                                                  solution.x,
                                                  centimetre_scale(solution.x));
      }

      double                                          tolerance       = 1e-5;
      double                                          largest_factor  = 64;
      double                                          smallest_factor = 1e-3;
      std::unique_ptr<rigid_blocks::MechanismProblem> last_problem;
      lp::Solution                                    last_solution;
      lp::WarmStart                                   warm;
      double                                          last_force_scale = 1;
    };
  } // namespace analysis
} // namespace masonry

MASONRY_REGISTER_ANALYSIS(
  masonry::analysis::MinimumThickness,
  "minimum thickness",
  "The smallest thickness at which a rigid-block vault stands under its "
  "dead loads (self weight and `Surface load'), by bisection on a factor "
  "that multiplies the `Geometry model' thickness field, with fixed "
  "supports and the `Interface model' joints. Writes minimum_thickness (m, "
  "at the centre of the first patch), minimum_thickness_factor, the "
  "hinges of the collapse mechanism just below it (crack list), the "
  "support reactions (thrust) and the line of thrust (thrust_line.csv) of "
  "the statically admissible state at the minimum, and the mechanism as "
  "in `settlement'.")
