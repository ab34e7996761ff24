/**
 * @file
 * The settlement analysis: rigid blocks and linear programming (seed paper
 * eqs. 5–8).
 */
#include <masonry/analysis/interface.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/parameters.h>
#include <masonry/geometry/interface.h>
#include <masonry/lp/interface.h>
#include <masonry/lp/linear_program.h>
#include <masonry/rigid_blocks/block_model.h>
#include <masonry/rigid_blocks/output.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>

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

      std::set<std::string>
      split_labels(const std::string &text)
      {
        std::set<std::string> labels;
        for (const auto &l : dealii::Utilities::split_string_list(text, ','))
          if (!l.empty())
            labels.insert(l);
        return labels;
      }
    } // namespace

    /**
     * A vault of rigid blocks whose supports move: the mechanism that
     * maximises the work of the loads subject to no interpenetration, no
     * sliding and the prescribed support motion.
     */
    class Settlement : public Interface
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        prm.declare_entry("Blocks along u",
                          "3",
                          dealii::Patterns::Integer(1, 4096),
                          "Number of blocks along the first parameter "
                          "direction u of every NURBS patch (the geometry "
                          "model's documentation says which way u runs).");
        prm.declare_entry("Blocks along v",
                          "4",
                          dealii::Patterns::Integer(1, 4096),
                          "Number of blocks along the second parameter "
                          "direction v of every patch.");
        prm.declare_entry("Stations per edge",
                          "3",
                          dealii::Patterns::Integer(2, 64),
                          "Points along every interface edge (ends included) "
                          "where contact conditions are written, each at the "
                          "intrados and at the extrados.");
        prm.declare_entry("Quadrature points",
                          "6",
                          dealii::Patterns::Integer(1, 32),
                          "Gauss points per parameter direction for block "
                          "volumes, centroids and loads (two Gauss points "
                          "across the thickness integrate exactly).");
        prm.declare_entry("Supported edges",
                          "springing left, springing right",
                          dealii::Patterns::Anything(),
                          "Comma-separated labels of the patch edges that "
                          "rest on supports (labels are listed in each "
                          "geometry model's documentation). Other free edges "
                          "are unsupported.");
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
        prm.declare_entry("Support contact",
                          "unilateral",
                          dealii::Patterns::Selection("unilateral|bonded"),
                          "`unilateral`: a block may lift off its support "
                          "but not penetrate or slide on it; `bonded`: the "
                          "block follows the support motion exactly (seed "
                          "eq. 8).");
        prm.declare_entry("Surface load",
                          "0",
                          dealii::Patterns::Anything(),
                          "Extra vertical dead load per unit area of the "
                          "middle surface, Pa (N/m², positive downwards), as "
                          "a function of x, y, z; e.g. a roof resting on the "
                          "vault.");
        prm.declare_entry("Displacement amplification",
                          "0",
                          dealii::Patterns::Double(0),
                          "Factor on displacements in the deformed VTU and "
                          "picture; 0 chooses one that makes the largest "
                          "displacement 5 % of the vault's size.");
        prm.declare_entry("Output subdivisions",
                          "4",
                          dealii::Patterns::Integer(1, 32),
                          "Subdivisions per block and parameter direction in "
                          "the VTU output (the blocks are curved).");
        prm.declare_entry("Write picture",
                          "true",
                          dealii::Patterns::Bool(),
                          "Render the deformed vault to vault.png with "
                          "matplotlib (/usr/bin/python3).");
      }

      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        options.n_u             = prm.get_integer("Blocks along u");
        options.n_v             = prm.get_integer("Blocks along v");
        options.n_stations      = prm.get_integer("Stations per edge");
        options.n_quadrature    = prm.get_integer("Quadrature points");
        options.supported_edges = split_labels(prm.get("Supported edges"));
        settling_edges          = split_labels(prm.get("Settling edges"));
        for (const auto &e : settling_edges)
          AssertThrow(options.supported_edges.count(e) > 0,
                      ExcParameter("Settling edges",
                                   "'" + e +
                                     "' is not among the Supported edges"));
        bonded = prm.get("Support contact") == "bonded";
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
        try
          {
            surface_load.initialize("x,y,z", prm.get("Surface load"), {});
          }
        catch (...)
          {
            AssertThrow(false,
                        ExcParameter("Surface load",
                                     "not a function of x, y, z: '" +
                                       prm.get("Surface load") + "'"));
          }
        output_options.amplification =
          prm.get_double("Displacement amplification");
        output_options.subdivisions  = prm.get_integer("Output subdivisions");
        output_options.write_picture = prm.get_bool("Write picture");
        section                      = "Settlement";
      }

      void
      setup(dealii::ParameterHandler &prm) override
      {
        geometry    = plugins::Registry<geometry::Interface>::create(prm);
        solver      = plugins::Registry<lp::Interface>::create(prm);
        solver_name = plugins::Registry<lp::Interface>::selected(prm);
        // build once here so that --validate finds bad labels and geometry
        plugins::ParsePathScope scope(section);
        model = std::make_unique<rigid_blocks::BlockModel>(*geometry, options);
      }

      void
      run(RunContext &context) override
      {
        auto &pcout = context.pcout;
        auto  start = Clock::now();
        model = std::make_unique<rigid_blocks::BlockModel>(*geometry, options);
        add_surface_loads();
        const double seconds_geometry = seconds_since(start);
        const auto  &blocks           = model->blocks();
        const auto  &interfaces       = model->interfaces();
        pcout << "Blocks: " << blocks.size()
              << ", interfaces: " << interfaces.size()
              << ", contact points: " << model->n_contact_points() << "\n";

        start = Clock::now();
        assemble();
        const double seconds_assembly = seconds_since(start);
        pcout << "Linear program: " << lp.n_rows() << " rows, "
              << lp.n_columns() << " columns, " << lp.n_nonzeros()
              << " non-zeros\n";
        if (solver->export_mps() && dealii::Utilities::MPI::this_mpi_process(
                                      context.mpi_communicator) == 0)
          lp.write_mps(context.output.file("lp.mps"));

        start                            = Clock::now();
        const lp::Solution solution      = solver->solve(lp);
        const double       seconds_solve = seconds_since(start);

        Json &summary               = context.summary;
        summary["n_blocks"]         = blocks.size();
        summary["n_interfaces"]     = interfaces.size();
        summary["n_contact_points"] = model->n_contact_points();
        summary["lp_rows"]          = lp.n_rows();
        summary["lp_columns"]       = lp.n_columns();
        summary["lp_nonzeros"]      = lp.n_nonzeros();
        summary["lp_solver"]        = solver_name;
        summary["lp_iterations"]    = solution.iterations;
        summary["seconds_geometry"] = seconds_geometry;
        summary["seconds_assembly"] = seconds_assembly;
        summary["seconds_solve"]    = seconds_solve;
        summary["total_weight"]     = total_weight;
        summary["max_settlement"]   = settlement_scale;

        if (solution.status == lp::Status::unbounded)
          {
            summary["status"] = "mechanism";
            summary["explanation"] =
              "The linear program is unbounded: a mechanism exists whose "
              "loads do positive work without any support motion, so the "
              "vault cannot stand under its own weight on these supports "
              "(too thin, or a support is missing).";
            pcout << "Result: mechanism — "
                  << summary.at("explanation").as_string() << "\n";
            return;
          }
        if (solution.status == lp::Status::infeasible)
          {
            summary["status"] = "incompatible";
            summary["explanation"] =
              "The linear program is infeasible: the prescribed support "
              "motions cannot be followed by rigid blocks without "
              "interpenetration or sliding (e.g. bonded supports moving "
              "apart).";
            pcout << "Result: incompatible — "
                  << summary.at("explanation").as_string() << "\n";
            return;
          }
        AssertThrow(solution.status == lp::Status::optimal,
                    dealii::ExcMessage("the LP solver failed: " +
                                       solution.message));

        // the solver's answer, checked: largest violation of a row bound in
        // the scaled LP (rows are O(1): unit normals, unit settlement)
        {
          const auto activity  = lp.row_activities(solution.x);
          double     violation = 0;
          for (unsigned int r = 0; r < activity.size(); ++r)
            violation = std::max({violation,
                                  lp.row_lower()[r] - activity[r],
                                  activity[r] - lp.row_upper()[r]});
          summary["lp_max_violation"] = violation;
          if (violation > 1e-6)
            pcout << "Warning: the LP solution violates a constraint by "
                  << violation << " (relative to the settlement)\n";
        }

        // undo the scaling: unit settlement, unit weight, rotations × length
        const double         length = model->length_scale();
        rigid_blocks::Motion motion(blocks.size());
        for (unsigned int b = 0; b < blocks.size(); ++b)
          for (unsigned int d = 0; d < 3; ++d)
            {
              motion.translation[b][d] =
                solution.x[6 * b + d] * settlement_scale;
              motion.rotation[b][d] =
                solution.x[6 * b + 3 + d] * settlement_scale / length;
            }
        const double work =
          solution.objective * total_weight * settlement_scale;
        summary["status"]        = "optimal";
        summary["external_work"] = work;
        pcout << "Result: optimal, external work = " << std::setprecision(6)
              << work << " J, " << solution.iterations << " LP iterations\n";

        // interface forces from the duals (rows of each point: normal,
        // across, along), N; compression positive
        std::vector<std::array<double, 3>> forces;
        for (unsigned int r = 0; r + 2 < solution.row_duals.size(); r += 3)
          forces.push_back({-solution.row_duals[r] * total_weight,
                            -solution.row_duals[r + 1] * total_weight,
                            -solution.row_duals[r + 2] * total_weight});

        rigid_blocks::write_results(*model,
                                    motion,
                                    settlement_function(),
                                    forces,
                                    output_options,
                                    context);
      }

    private:
      /** Settlement at a support point, m (zero on fixed supports). */
      std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &,
                                         const std::string &)>
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

      /** Resultants of the surface load on every block. */
      void
      add_surface_loads()
      {
        extra_force.assign(model->blocks().size(), dealii::Tensor<1, 3>());
        extra_moment.assign(model->blocks().size(), dealii::Tensor<1, 3>());
        rigid_blocks::integrate_surface_load(*model,
                                             surface_load,
                                             extra_force,
                                             extra_moment);
      }

      /** The LP of seed eqs. 5–8, scaled (see the class documentation). */
      void
      assemble()
      {
        const auto  &blocks     = model->blocks();
        const auto  &interfaces = model->interfaces();
        const double length     = model->length_scale();
        const auto   u0         = settlement_function();

        total_weight = 0;
        for (unsigned int b = 0; b < blocks.size(); ++b)
          total_weight += blocks[b].weight + std::abs(extra_force[b][2]);
        settlement_scale = 0;
        for (const auto &i : interfaces)
          if (i.second == rigid_blocks::Interface::support)
            for (const auto &c : i.points)
              settlement_scale =
                std::max(settlement_scale,
                         u0(c.position, i.support_label).norm());
        if (settlement_scale == 0)
          settlement_scale = 1;

        lp               = lp::LinearProgram();
        lp.maximize      = true;
        const double inf = std::numeric_limits<double>::infinity();
        // columns: translation (m / scale) and rotation × length (/ scale)
        for (unsigned int b = 0; b < blocks.size(); ++b)
          {
            dealii::Tensor<1, 3> force = extra_force[b];
            force[2] -= blocks[b].weight;
            for (unsigned int d = 0; d < 3; ++d)
              lp.add_column(force[d] / total_weight, -inf, inf);
            for (unsigned int d = 0; d < 3; ++d)
              lp.add_column(extra_moment[b][d] / (total_weight * length),
                            -inf,
                            inf);
          }

        // m·v_b(x) for the rigid motion of block b, in scaled columns
        auto add_velocity = [&](const unsigned int          row,
                                const unsigned int          b,
                                const dealii::Tensor<1, 3> &m,
                                const dealii::Point<3>     &x,
                                const double                sign) {
          const dealii::Tensor<1, 3> r = x - blocks[b].centroid;
          const dealii::Tensor<1, 3> rm =
            dealii::cross_product_3d(r, m) / length;
          // entries are O(1); drop the round-off of unit vectors (1e-17),
          // which would otherwise wreck the solvers' scaling
          for (unsigned int d = 0; d < 3; ++d)
            {
              if (std::abs(m[d]) > 1e-13)
                lp.add_entry(row, 6 * b + d, sign * m[d]);
              if (std::abs(rm[d]) > 1e-13)
                lp.add_entry(row, 6 * b + 3 + d, sign * rm[d]);
            }
        };

        // rows: for every contact point, normal (≥) then the two tangents
        for (const auto &i : interfaces)
          for (const auto &c : i.points)
            {
              const std::array<dealii::Tensor<1, 3>, 3> frame = {c.normal,
                                                                 c.across,
                                                                 c.along};
              if (i.second != rigid_blocks::Interface::support)
                {
                  // jump = v_second − v_first: opening ≥ 0, no sliding
                  for (unsigned int k = 0; k < 3; ++k)
                    {
                      const unsigned int row = lp.add_row(0, k == 0 ? inf : 0);
                      add_velocity(row, i.second, frame[k], c.position, 1);
                      add_velocity(row, i.first, frame[k], c.position, -1);
                    }
                }
              else
                {
                  // jump = u0 − v_first: −m·v ≥ −m·u0 (normal, unilateral)
                  // or −m·v = −m·u0 (tangents; all three when bonded)
                  const dealii::Tensor<1, 3> u =
                    u0(c.position, i.support_label) / settlement_scale;
                  for (unsigned int k = 0; k < 3; ++k)
                    {
                      const double       rhs = -(frame[k] * u);
                      const unsigned int row =
                        lp.add_row(rhs, (k == 0 && !bonded) ? inf : rhs);
                      add_velocity(row, i.first, frame[k], c.position, -1);
                    }
                }
            }
      }

      rigid_blocks::Discretisation              options;
      std::set<std::string>                     settling_edges;
      bool                                      bonded = false;
      dealii::FunctionParser<3>                 settlement{3};
      dealii::FunctionParser<3>                 surface_load{1};
      rigid_blocks::OutputOptions               output_options;
      std::string                               section;
      std::string                               solver_name;
      std::unique_ptr<geometry::Interface>      geometry;
      std::unique_ptr<lp::Interface>            solver;
      std::unique_ptr<rigid_blocks::BlockModel> model;
      std::vector<dealii::Tensor<1, 3>>         extra_force, extra_moment;
      lp::LinearProgram                         lp;
      double                                    total_weight     = 1;
      double                                    settlement_scale = 1;
    };
  } // namespace analysis
} // namespace masonry

MASONRY_REGISTER_ANALYSIS(
  masonry::analysis::Settlement,
  "settlement",
  "Rigid-block analysis of a vault under support settlements (seed paper, "
  "eqs. 5-8): the vault (`Geometry model`) is cut into blocks in NURBS "
  "parameter space; interfaces carry contact points at intrados and "
  "extrados with no interpenetration and no sliding; supports move by the "
  "prescribed settlement; the LP (`LP solver`) maximises the work of self "
  "weight and dead loads. Status `optimal`, `mechanism` (unbounded: the "
  "vault cannot stand) or `incompatible` (infeasible: the motions cannot be "
  "followed). Writes summary.json (external_work in J, crack list), "
  "interface_forces.csv, blocks.vtu, interfaces.vtu, vault.pvd and "
  "vault.png.")
