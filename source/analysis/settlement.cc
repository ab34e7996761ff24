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

#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>

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
      }

      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        parse_block_parameters(prm, "Settlement");
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
        const auto         problem  = assemble();
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
        const auto         problem  = assemble();
        const lp::Solution solution = solve(problem.lp, context);
        activity.assign(model->interfaces().size(), 0.);
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
        const auto  u0      = settlement_function();
        const auto  problem = assemble();
        const auto &lp      = problem.lp;
        pcout << "Linear program: " << lp.n_rows() << " rows, "
              << lp.n_columns() << " columns, " << lp.n_nonzeros()
              << " non-zeros\n";

        const lp::Solution solution = solve(lp, context);
        record(lp, solution, context);
        Json &summary             = context.summary;
        summary["total_weight"]   = force_scale;
        summary["max_settlement"] = settlement_scale;

        if (solution.status == lp::Status::unbounded)
          return report(
            context,
            "mechanism",
            "The linear program is unbounded: a mechanism exists whose "
            "loads do positive work without any support motion, so the "
            "vault cannot stand under its own weight on these supports (too "
            "thin, or a support is missing).");
        if (solution.status == lp::Status::infeasible)
          return report(context,
                        "incompatible",
                        "The linear program is infeasible: the prescribed "
                        "support motions cannot be followed by rigid blocks "
                        "without violating the joints' flow rule (e.g. "
                        "bonded supports moving apart).");

        const double scale = force_scale * settlement_scale;
        const double dissipation =
          rigid_blocks::dissipated(problem, solution.x) * settlement_scale;
        summary["status"]        = "optimal";
        summary["external_work"] = solution.objective * scale + dissipation;
        summary["dissipation"]   = dissipation;
        summary["objective"]     = solution.objective * scale;
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
       * The scaled LP of the current model (sets settlement_scale and
       * force_scale).
       */
      rigid_blocks::MechanismProblem
      assemble()
      {
        const auto start = Clock::now();
        const auto u0    = settlement_function();
        // unit settlement: the largest ground motion at a support point
        settlement_scale = 0;
        for (const auto &i : model->interfaces())
          if (i.second == rigid_blocks::Interface::support)
            for (const auto &c : i.points)
              settlement_scale =
                std::max(settlement_scale,
                         u0(c.position, i.support_label).norm());
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
        problem.lp.maximize = true;
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
