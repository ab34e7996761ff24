/**
 * @file
 * The limit-load analysis: the kinematic upper bound of the collapse load
 * multiplier of a rigid-block vault as a linear program.
 */
#include <masonry/analysis/rigid_block_analysis.h>
#include <masonry/core/json.h>
#include <masonry/core/parameters.h>
#include <masonry/geometry/interface.h>
#include <masonry/rigid_blocks/interface_model.h>
#include <masonry/rigid_blocks/mechanism.h>

#include <deal.II/base/utilities.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>

namespace masonry
{
  namespace analysis
  {
    /**
     * Collapse load multiplier: minimise λ = D(d) − q_D·d subject to the
     * flow rule of the interface model and q_L·d = 1 (normalised live
     * load), with fixed supports. The dual gives contact forces in
     * equilibrium with q_D + λ q_L.
     */
    class LimitLoad : public RigidBlockAnalysis
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        declare_block_parameters(prm);
        declare_ranged_list(
          prm,
          "Live acceleration",
          "1; 0; 0",
          {-100, 100, "g per unit multiplier"},
          3,
          ";",
          "Acceleration of the live load per unit multiplier, in units of g "
          "(dimensionless), as `ax; ay; az': the live load on a block of "
          "weight W is λ W (ax, ay, az). `1; 0; 0' is the seismic case "
          "(horizontal acceleration λ g along x); `0; 0; -1' a multiplier "
          "on self weight; `0; 0; 0' for point or line loads only.");
        prm.declare_entry(
          "Point loads",
          "",
          dealii::Patterns::Anything(),
          "Live point loads, `;'-separated, each `patch, u, v, Fx, Fy, Fz': "
          "a force (Fx, Fy, Fz) in N per unit multiplier applied at the "
          "point of the middle surface at parameters (u, v) ∈ [0, 1]² of "
          "the patch with that index (0-based, in the geometry model's "
          "order); e.g. `0, 1, 0.5, 0, 0, -1000'.");
        prm.declare_entry(
          "Line loads",
          "",
          dealii::Patterns::Anything(),
          "Live line loads, `;'-separated, each `patch, u0, v0, u1, v1, qx, "
          "qy, qz': a force (qx, qy, qz) in N/m per unit multiplier, per "
          "unit length of the curve of the middle surface that is the image "
          "of the straight parameter segment (u0, v0)–(u1, v1) of the patch "
          "(integrated with 256 midpoint pieces, each given to the block "
          "that contains it); e.g. `0, 1, 0, 1, 1, 0, 0, -2000' along the "
          "edge u = 1.");
      }

      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        parse_block_parameters(prm, "Limit load");
        const auto a =
          dealii::Utilities::split_string_list(prm.get("Live acceleration"),
                                               ';');
        for (unsigned int d = 0; d < 3; ++d)
          acceleration[d] = dealii::Utilities::string_to_double(a[d]);
        // `;'-separated lists of n numbers each
        auto numbers = [&](const std::string &entry,
                           const unsigned int n,
                           const std::string &format) {
          std::vector<std::vector<double>> list;
          for (const auto &item :
               dealii::Utilities::split_string_list(prm.get(entry), ';'))
            {
              if (item.empty())
                continue;
              const auto v = dealii::Utilities::split_string_list(item, ',');
              AssertThrow(
                v.size() == n,
                ExcParameter(entry, "'" + item + "' is not `" + format + "'"));
              std::vector<double> x;
              try
                {
                  for (const auto &t : v)
                    x.push_back(dealii::Utilities::string_to_double(t));
                }
              catch (...)
                {
                  AssertThrow(false,
                              ExcParameter(entry,
                                           "'" + item + "' has a bad number"));
                }
              AssertThrow(x[0] >= 0 && x[0] == std::floor(x[0]),
                          ExcParameter(entry,
                                       "'" + item +
                                         "': the patch index must be a "
                                         "non-negative integer"));
              for (unsigned int k = 1; k <= (n == 6 ? 2u : 4u); ++k)
                AssertThrow(x[k] >= 0 && x[k] <= 1,
                            ExcParameter(entry,
                                         "'" + item +
                                           "': u and v must lie in [0, 1]"));
              list.push_back(x);
            }
          return list;
        };
        point_loads.clear();
        for (const auto &x :
             numbers("Point loads", 6, "patch, u, v, Fx, Fy, Fz"))
          point_loads.push_back({static_cast<unsigned int>(x[0]),
                                 dealii::Point<2>(x[1], x[2]),
                                 dealii::Tensor<1, 3>({x[3], x[4], x[5]})});
        line_loads =
          numbers("Line loads", 8, "patch, u0, v0, u1, v1, qx, qy, qz");
      }

      void
      setup(dealii::ParameterHandler &prm) override
      {
        RigidBlockAnalysis::setup(prm);
        plugins::ParsePathScope scope(section);
        for (const auto &x : line_loads)
          AssertThrow(x[0] < geometry->patches().size(),
                      ExcParameter("Line loads",
                                   "patch " + std::to_string(int(x[0])) +
                                     " does not exist"));
        // a line load becomes point loads at the midpoints of 256 pieces
        all_point_loads = point_loads;
        for (const auto &x : line_loads)
          {
            const auto        &patch = geometry->patches()[int(x[0])];
            const unsigned int n     = 256;
            for (unsigned int k = 0; k < n; ++k)
              {
                auto at = [&](const double s) {
                  return dealii::Point<2>(x[1] + s * (x[3] - x[1]),
                                          x[2] + s * (x[4] - x[2]));
                };
                const double length =
                  patch.point(at(double(k + 1) / n))
                    .distance(patch.point(at(double(k) / n)));
                all_point_loads.push_back(
                  {static_cast<unsigned int>(x[0]),
                   at((k + 0.5) / n),
                   length * dealii::Tensor<1, 3>({x[5], x[6], x[7]})});
              }
          }
        for (const auto &p : point_loads)
          AssertThrow(
            p.patch < geometry->patches().size(),
            ExcParameter("Point loads",
                         "patch " + std::to_string(p.patch) +
                           " does not exist (the geometry has " +
                           std::to_string(geometry->patches().size()) + ")"));
        AssertThrow(acceleration.norm() > 0 || !all_point_loads.empty(),
                    ExcParameter("Live acceleration",
                                 "there is no live load: set a non-zero "
                                 "acceleration, Point loads or Line "
                                 "loads"));
      }

      std::string
      fitness_name() const override
      {
        return "minus the load multiplier";
      }

      double
      evaluate(RunContext &context) override
      {
        build_model();
        const auto         problem  = assemble();
        const lp::Solution solution = solve(problem.lp, context);
        if (solution.status != lp::Status::optimal)
          return -std::numeric_limits<double>::infinity();
        return -solution.objective;
      }

      void
      analyse(RunContext &context) override
      {
        auto &pcout = context.pcout;
        build_model();
        const auto &blocks = model->blocks();
        pcout << "Blocks: " << blocks.size()
              << ", interfaces: " << model->interfaces().size()
              << ", contact points: " << model->n_contact_points() << "\n";
        const auto  problem = assemble();
        const auto &lp      = problem.lp;
        pcout << "Linear program: " << lp.n_rows() << " rows, "
              << lp.n_columns() << " columns, " << lp.n_nonzeros()
              << " non-zeros\n";

        const lp::Solution solution = solve(lp, context);
        record(lp, solution, context);
        Json &summary                  = context.summary;
        summary["live_load_magnitude"] = live_scale;
        summary["dead_load_magnitude"] = dead_load_magnitude();
        if (solution.status == lp::Status::unbounded)
          return report(context,
                        "mechanism",
                        "The linear program is unbounded: the dead loads "
                        "alone do positive work on a mechanism without "
                        "dissipation, so the vault cannot stand even "
                        "without live load.");
        if (solution.status == lp::Status::infeasible)
          return report(context,
                        "no_collapse",
                        "The linear program is infeasible: no admissible "
                        "mechanism lets the live load do positive work, so "
                        "no multiple of it causes collapse (the load "
                        "multiplier is infinite).");

        const double lambda        = solution.objective;
        summary["status"]          = "optimal";
        summary["load_multiplier"] = lambda;
        pcout << "Result: load multiplier = " << std::setprecision(8) << lambda
              << ", " << solution.iterations << " LP iterations\n";
        if (lambda < 0)
          pcout << "Warning: the load multiplier is negative: the dead loads "
                   "alone need a reversed live load to stand.\n";

        // the mechanism, scaled to 1 cm (its magnitude is arbitrary)
        const double scale         = centimetre_scale(solution.x);
        summary["mechanism_scale"] = scale;
        write_mechanism(
          rigid_blocks::motion_from_solution(problem, solution.x, scale),
          rigid_blocks::contact_forces(problem, solution, live_scale, false),
          context);
      }

    private:
      /** The LP of the current model (sets live_scale). */
      rigid_blocks::MechanismProblem
      assemble()
      {
        const auto  start  = std::chrono::steady_clock::now();
        const auto &blocks = model->blocks();
        // live loads on the blocks
        std::vector<dealii::Tensor<1, 3>> live_force(blocks.size()),
          live_moment(blocks.size());
        for (unsigned int b = 0; b < blocks.size(); ++b)
          live_force[b] = blocks[b].weight * acceleration;
        for (const auto &p : all_point_loads)
          {
            const unsigned int     b = locate_block(p.patch, p.uv);
            const dealii::Point<3> x = geometry->patches()[p.patch].point(p.uv);
            live_force[b] += p.force;
            live_moment[b] +=
              dealii::cross_product_3d(x - blocks[b].centroid, p.force);
          }
        live_scale = 0;
        for (const auto &f : live_force)
          live_scale += f.norm();
        AssertThrow(live_scale > 0,
                    dealii::ExcMessage("the live load is zero"));

        auto problem = rigid_blocks::build_mechanism_problem(
          *model, *joints, nullptr, bonded_supports, leave_out_implied_rows);
        auto &lp        = problem.lp;
        lp.maximize     = false;
        const auto dead = rigid_blocks::load_work(dead_force,
                                                  dead_moment,
                                                  problem.length,
                                                  live_scale);
        const auto live = rigid_blocks::load_work(live_force,
                                                  live_moment,
                                                  problem.length,
                                                  live_scale);
        for (unsigned int c = 0; c < dead.size(); ++c)
          lp.set_cost(c, -dead[c]);
        for (unsigned int c = problem.n_block_columns; c < lp.n_columns(); ++c)
          lp.set_cost(c, problem.dissipation[c] / live_scale);
        // normalisation, the last row: q_L·d = 1 (m)
        const unsigned int row = lp.add_row(1, 1);
        for (unsigned int c = 0; c < live.size(); ++c)
          if (live[c] != 0)
            lp.add_entry(row, c, live[c]);
        seconds_assembly += std::chrono::duration<double>(
                              std::chrono::steady_clock::now() - start)
                              .count();
        return problem;
      }

      double live_scale = 1;

      struct PointLoad
      {
        unsigned int         patch;
        dealii::Point<2>     uv;
        dealii::Tensor<1, 3> force;
      };

      dealii::Tensor<1, 3>             acceleration;
      std::vector<PointLoad>           point_loads, all_point_loads;
      std::vector<std::vector<double>> line_loads;
    };
  } // namespace analysis
} // namespace masonry

MASONRY_REGISTER_ANALYSIS(
  masonry::analysis::LimitLoad,
  "limit load",
  "Collapse load multiplier of a rigid-block vault (kinematic upper bound "
  "as a linear program): dead loads (self weight, `Surface load') and live "
  "loads (an acceleration λ g in a given direction, the seismic case, and "
  "point loads); minimises λ = D − q_D·d subject to the flow rule of the "
  "`Interface model' with the live-load work normalised to 1. Supports are "
  "fixed. Writes load_multiplier, the hinges (crack list) and the support "
  "reactions to summary.json, the contact forces of the dual (static) "
  "problem to interface_forces.csv, the line of thrust (centre of "
  "pressure of every joint) to thrust_line.csv, and the mechanism as in "
  "`settlement'. Status `optimal', `mechanism' (the dead loads alone "
  "cause collapse) or `no_collapse' (no multiple of the live load causes "
  "collapse).")
