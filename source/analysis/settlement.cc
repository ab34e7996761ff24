/**
 * @file
 * The settlement analysis: rigid blocks and linear programming (seed paper
 * eqs. 5–8).
 */
#include <masonry/analysis/rigid_block_analysis.h>
#include <masonry/core/json.h>
#include <masonry/core/parameters.h>
#include <masonry/rigid_blocks/interface_model.h>
#include <masonry/rigid_blocks/mechanism.h>
#include <masonry/rigid_blocks/support_check.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>

#include "support_motion_report.h"

namespace masonry
{
  namespace analysis
  {
    namespace
    {
      using Clock = std::chrono::steady_clock;

      double
      seconds_since(const Clock::time_point &start)
      {
        return std::chrono::duration<double>(Clock::now() - start).count();
      }

    } // namespace

    /**
     * A vault of rigid blocks whose supports move: the mechanism that
     * maximises the work of the loads minus the dissipation of the joints,
     * subject to the flow rule of the interface model and the prescribed
     * support motion.
     *
     * Scaling: the LP is solved for a unit settlement (the largest
     * settlement at a support point), with forces divided by the total dead
     * load and rotations multiplied by the model's length scale; the
     * solution is scaled back (the problem is homogeneous in the
     * settlement).
     */
    class Settlement : public RigidBlockAnalysis
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        declare_block_parameters(prm);
        prm.declare_entry("Settling edges",
                          "springing right",
                          dealii::Patterns::Anything(),
                          "Comma-separated labels of supported edges that "
                          "move by the prescribed settlement; the other "
                          "supports stay fixed.");
        prm.declare_entry("Settlement",
                          "0; 0; -0.01",
                          dealii::Patterns::Anything(),
                          "Displacement of the settling supports as a "
                          "function of position: three components (x; y; z), "
                          "m, in the variables x, y, z (m); e.g. "
                          "`0; 0; -0.01*y/16.8` for a linear drop of 1 cm "
                          "over 16.8 m.");
        prm.declare_entry(
          "Check support motion",
          "true",
          dealii::Patterns::Bool(),
          "Whether the prescribed support motion is checked directly, "
          "before the linear program: at bonded supports the motion of the "
          "support points of every block must be a rigid motion of that "
          "block (at unilateral ones its components in which the joints "
          "can neither open nor slide), and where the supports fix the "
          "motions of the blocks on both sides of a joint, the joint must "
          "admit their jump. A misfit above 1e-6 of the largest settlement "
          "ends the run as `incompatible' in milliseconds, naming the "
          "support edge, the block, its centroid and the misfit (m) "
          "(summary.json: `incompatibility'); what the check cannot see is "
          "left to the LP (doc/rigid-blocks.md, Statuses). false: every "
          "verdict comes from the LP (for checks and timing). Unitless "
          "flag.");
      }

      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        parse_block_parameters(prm, "Settlement");
        check_support  = prm.get_bool("Check support motion");
        settling_edges = split_labels(prm.get("Settling edges"));
        for (const auto &e : settling_edges)
          AssertThrow(options.supported_edges.count(e) > 0,
                      ExcParameter("Settling edges",
                                   "'" + e +
                                     "' is not among the Supported edges"));
        try
          {
            settlement.initialize("x,y,z", prm.get("Settlement"), {});
          }
        catch (...)
          {
            AssertThrow(false,
                        ExcParameter("Settlement",
                                     "not three ';'-separated functions of x, "
                                     "y, z: '" +
                                       prm.get("Settlement") + "'"));
          }
      }

      std::string
      fitness_name() const override
      {
        return "work of the loads minus dissipation (J)";
      }

      double
      evaluate(RunContext &context) override
      {
        build_model();
        bool known_feasible = false;
        if (!followable(known_feasible))
          return -std::numeric_limits<double>::infinity();
        const auto         problem  = assemble(known_feasible);
        const lp::Solution solution = solve(problem.lp, context);
        if (solution.status != lp::Status::optimal)
          return -std::numeric_limits<double>::infinity();
        return solution.objective * force_scale * settlement_scale;
      }

      double
      evaluate_cracks(RunContext          &context,
                      std::vector<double> &activity) override
      {
        build_model();
        activity.assign(model->interfaces().size(), 0.);
        bool known_feasible = false;
        if (!followable(known_feasible))
          return -std::numeric_limits<double>::infinity();
        const auto         problem  = assemble(known_feasible);
        const lp::Solution solution = solve(problem.lp, context);
        if (solution.status != lp::Status::optimal)
          return -std::numeric_limits<double>::infinity();
        activity = crack_activity(rigid_blocks::motion_from_solution(
                                    problem, solution.x, settlement_scale),
                                  settlement_function());
        return solution.objective * force_scale * settlement_scale;
      }

      void
      analyse(RunContext &context) override
      {
        auto &pcout = context.pcout;
        build_model();
        const auto &blocks     = model->blocks();
        const auto &interfaces = model->interfaces();
        pcout << "Blocks: " << blocks.size()
              << ", interfaces: " << interfaces.size()
              << ", contact points: " << model->n_contact_points() << "\n";
        const auto u0             = settlement_function();
        bool       known_feasible = false;
        if (refused_by_check(context, known_feasible))
          return;
        const auto  problem = assemble(known_feasible);
        const auto &lp      = problem.lp;
        pcout << "Linear program: " << lp.n_rows() << " rows, "
              << lp.n_columns() << " columns, " << lp.n_nonzeros()
              << " non-zeros\n";

        const lp::Solution solution = solve(lp, context);
        record(lp, solution, context);
        Json &summary             = context.summary;
        summary["total_weight"]   = force_scale;
        summary["max_settlement"] = settlement_scale;

        if (solution.status != lp::Status::optimal)
          return report_no_optimum(problem, solution, context);

        const double scale = force_scale * settlement_scale;
        const double dissipation =
          rigid_blocks::dissipated(problem, solution.x) * settlement_scale;
        summary["status"]        = "optimal";
        summary["external_work"] = solution.objective * scale + dissipation;
        summary["dissipation"]   = dissipation;
        summary["objective"]     = solution.objective * scale;
        summary["lp_objective"]  = solution.objective;
        pcout << "Result: optimal, work of the loads = " << std::setprecision(6)
              << summary.at("external_work").get<double>()
              << " J, dissipation = " << dissipation << " J, "
              << solution.iterations << " LP iterations\n";

        const auto forces =
          rigid_blocks::contact_forces(problem, solution, force_scale, true);
        write_results(rigid_blocks::motion_from_solution(problem,
                                                         solution.x,
                                                         settlement_scale),
                      u0,
                      true,
                      forces,
                      context);
      }

      rigid_blocks::SupportMotion
      prescribed_support_motion() const override
      {
        return settlement_function();
      }

    private:
      /**
       * The direct check (`Check support motion`) of the current model,
       * with its numbers in the summary; true if it refuses the support
       * motion (the run has then ended `incompatible`, with the LP written
       * to lp.mps if `Export MPS file`), else @p known_feasible says
       * whether it proves the LP feasible (SupportCheck::exact).
       */
      bool
      refused_by_check(RunContext &context, bool &known_feasible)
      {
        known_feasible = false;
        if (!check_support)
          return false;
        const double cpu_start               = thread_cpu_seconds();
        const auto   check                   = check_support_motion();
        context.summary["cpu_seconds_check"] = thread_cpu_seconds() - cpu_start;
        record_support_check(check, context.summary);
        if (!check.incompatible)
          {
            known_feasible = check.exact;
            return false;
          }
        std::unique_ptr<rigid_blocks::MechanismProblem> problem;
        if (solver->export_mps())
          {
            // the LP the check spared, for an independent solver
            problem =
              std::make_unique<rigid_blocks::MechanismProblem>(assemble());
            export_lp(problem->lp, context);
          }
        record_model(context, problem ? &problem->lp : nullptr);
        context.summary["total_weight"]   = dead_load_magnitude();
        context.summary["max_settlement"] = largest_settlement();
        report(context,
               "incompatible",
               "The prescribed support motions cannot be followed by rigid "
               "blocks: " +
                 check.worst.describe() + ".");
        return true;
      }

      /**
       * End a run whose LP has no optimum: `mechanism` (unbounded; the
       * number of blocks that move in the mechanism the solver found) or
       * `incompatible` (infeasible; where the rows cannot be met, if the
       * solver says so).
       */
      void
      report_no_optimum(const rigid_blocks::MechanismProblem &problem,
                        const lp::Solution                   &solution,
                        RunContext                           &context) const
      {
        Json &summary = context.summary;
        if (solution.status == lp::Status::unbounded)
          {
            std::string moving;
            if (!solution.ray.empty())
              {
                // the blocks that move in the mechanism the solver found
                const auto motion =
                  rigid_blocks::motion_from_solution(problem, solution.ray, 1.);
                double       largest = 0;
                unsigned int n       = 0;
                for (const auto &t : motion.translation)
                  largest = std::max(largest, t.norm());
                for (const auto &t : motion.translation)
                  n += t.norm() > 1e-3 * largest;
                summary["mechanism_blocks"] = n;
                moving = " (in the one found, " + std::to_string(n) + " of " +
                         std::to_string(model->blocks().size()) +
                         " blocks move)";
              }
            return report(
              context,
              "mechanism",
              "The linear program is unbounded: a mechanism exists whose "
              "loads do positive work without any support motion" +
                moving +
                ", so the vault cannot stand under its own weight on these "
                "supports (too thin, or a support is missing).");
          }
        std::string where;
        if (!solution.row_misfit.empty())
          {
            const auto x =
              rigid_blocks::locate_row_misfit(*model,
                                              problem,
                                              solution.row_misfit,
                                              settlement_scale,
                                              1e-6 * settlement_scale);
            if (!x.kind.empty())
              {
                summary["incompatibility"] = incompatibility_json(x);
                where                      = ": " + x.describe();
              }
          }
        report(context,
               "incompatible",
               "The linear program is infeasible: the prescribed support "
               "motions cannot be followed by rigid blocks without violating "
               "the joints' flow rule" +
                 (where.empty() ?
                    std::string(" (e.g. bonded supports moving apart).") :
                    where + "."));
      }

      /** The largest ground motion at a support point of the model, m. */
      double
      largest_settlement() const
      {
        const auto u0      = settlement_function();
        double     largest = 0;
        for (const auto &i : model->interfaces())
          if (i.second == rigid_blocks::Interface::support)
            for (const auto &c : i.points)
              largest =
                std::max(largest, u0(c.position, i.support_label).norm());
        return largest;
      }

      /**
       * The direct check of the support motion of the current model
       * (`Check support motion`), with a tolerance of 1e-6 of the largest
       * settlement: the LP's rows hold to about 1e-7 of it, so that a
       * larger misfit is one the LP cannot follow either.
       */
      rigid_blocks::SupportCheck
      check_support_motion() const
      {
        return rigid_blocks::check_support_motion(*model,
                                                  *joints,
                                                  settlement_function(),
                                                  bonded_supports,
                                                  1e-6 * largest_settlement());
      }

      /**
       * Whether the support check (if `Check support motion`) lets the
       * LP be solved, with @p known_feasible whether it proves the LP
       * feasible (SupportCheck::exact).
       */
      bool
      followable(bool &known_feasible) const
      {
        known_feasible = false;
        if (!check_support)
          return true;
        const auto check = check_support_motion();
        known_feasible   = check.exact && !check.incompatible;
        return !check.incompatible;
      }

      /**
       * The scaled LP of the current model (sets settlement_scale and
       * force_scale); @p known_feasible: the support check proved it
       * feasible (lp::LinearProgram::known_feasible).
       */
      rigid_blocks::MechanismProblem
      assemble(const bool known_feasible = false)
      {
        const auto start = Clock::now();
        const auto u0    = settlement_function();
        // unit settlement: the largest ground motion at a support point
        settlement_scale = largest_settlement();
        if (settlement_scale == 0)
          settlement_scale = 1;
        force_scale  = dead_load_magnitude();
        auto problem = rigid_blocks::build_mechanism_problem(
          *model,
          *joints,
          [&](const dealii::Point<3> &x, const std::string &label) {
            return u0(x, label) / settlement_scale;
          },
          bonded_supports,
          leave_out_implied_rows);
        const auto work = rigid_blocks::load_work(dead_force,
                                                  dead_moment,
                                                  problem.length,
                                                  force_scale);
        for (unsigned int c = 0; c < work.size(); ++c)
          problem.lp.set_cost(c, work[c]);
        for (unsigned int c = problem.n_block_columns;
             c < problem.lp.n_columns();
             ++c)
          problem.lp.set_cost(c, -problem.dissipation[c] / force_scale);
        problem.lp.maximize       = true;
        problem.lp.known_feasible = known_feasible;
        seconds_assembly += seconds_since(start);
        return problem;
      }

      /** Settlement at a support point, m (zero on fixed supports). */
      rigid_blocks::SupportMotion
      settlement_function() const
      {
        return [this](const dealii::Point<3> &x, const std::string &label) {
          dealii::Tensor<1, 3> u;
          if (settling_edges.count(label) > 0)
            for (unsigned int d = 0; d < 3; ++d)
              u[d] = settlement.value(x, d);
          return u;
        };
      }

      /** `Check support motion`. */
      bool                      check_support = true;
      std::set<std::string>     settling_edges;
      dealii::FunctionParser<3> settlement{3};
      double                    settlement_scale = 1;
      double                    force_scale      = 1;
    };
  } // namespace analysis
} // namespace masonry

MASONRY_REGISTER_ANALYSIS(
  masonry::analysis::Settlement,
  "settlement",
  "Rigid-block analysis of a vault under support settlements (seed paper, "
  "eqs. 5-8): the vault (`Geometry model`) is cut into blocks in NURBS "
  "parameter space; interfaces carry contact points at intrados and "
  "extrados whose strength is the `Interface model'; supports move by the "
  "prescribed settlement; the LP (`LP solver`) maximises the work of self "
  "weight and dead loads. Status `optimal`, `mechanism` (unbounded: the "
  "vault cannot stand) or `incompatible` (infeasible: the motions cannot be "
  "followed). With `mohr coulomb' joints it maximises the work of the "
  "loads minus the dissipation. Writes summary.json (external_work and "
  "dissipation in J, crack list, support reactions), "
  "interface_forces.csv, blocks.vtu, interfaces.vtu, vault.pvd and "
  "vault.png.")
