/**
 * @file
 * The rigid-block analyses' common part (RigidBlockAnalysis): parameters,
 * set-up, the block model and its loads, the LP solve. Their output is in
 * rigid_block_output.cc, the mesh adaptation by an optimiser in
 * rigid_block_adaptation.cc.
 */
#include <masonry/adaptation/crack_refinement.h>
#include <masonry/adaptation/optimiser.h>
#include <masonry/analysis/rigid_block_analysis.h>
#include <masonry/core/parameters.h>
#include <masonry/geometry/interface.h>
#include <masonry/rigid_blocks/interface_model.h>
#include <masonry/rigid_blocks/postprocess/interface.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <iomanip>
#include <sstream>
#include <time.h>

namespace masonry
{
  namespace analysis
  {
    double
    RigidBlockAnalysis::thread_cpu_seconds()
    {
      timespec t;
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
      return t.tv_sec + 1e-9 * t.tv_nsec;
    }

    std::set<std::string>
    RigidBlockAnalysis::split_labels(const std::string &text)
    {
      std::set<std::string> labels;
      for (const auto &l : dealii::Utilities::split_string_list(text, ','))
        if (!l.empty())
          labels.insert(l);
      return labels;
    }

    rigid_blocks::SupportMotion
    RigidBlockAnalysis::prescribed_support_motion() const
    {
      return [](const dealii::Point<3> &, const std::string &) {
        return dealii::Tensor<1, 3>();
      };
    }

    RigidBlockAnalysis::RigidBlockAnalysis() = default;

    RigidBlockAnalysis::~RigidBlockAnalysis() = default;

    void
    RigidBlockAnalysis::declare_block_parameters(dealii::ParameterHandler &prm)
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
                        "intrados and at the extrados; every point carries a "
                        "tributary area (trapezoid rule).");
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
      prm.declare_entry("Support contact",
                        "unilateral",
                        dealii::Patterns::Selection("unilateral|bonded"),
                        "`unilateral`: a support joint behaves like the "
                        "joints between blocks (`Interface model`; with "
                        "`no tension no sliding` a block may lift off its "
                        "support but not penetrate or slide on it); "
                        "`bonded`: the block follows the support motion "
                        "exactly (seed eq. 8), a rigid clamp.");
      prm.declare_entry("Implied contact rows",
                        "leave out",
                        dealii::Patterns::Selection("leave out|keep"),
                        "Where the joints have no plastic multipliers (`no "
                        "tension no sliding', bonded supports), the LP rows "
                        "of an interface that follow from its other rows "
                        "(on a plane interface, the tangential jumps beyond "
                        "three; the normal jump at the middle of a straight "
                        "edge) are left out: the same optimum from a smaller "
                        "LP, with the contact forces carried by the points "
                        "kept (the others report zero). `keep' writes every "
                        "row. Unitless choice.");
      prm.declare_entry("Surface load",
                        "0",
                        dealii::Patterns::Anything(),
                        "Extra vertical dead load per unit area of the "
                        "middle surface, Pa (N/m², positive downwards), as "
                        "a function of x, y, z; e.g. a roof resting on the "
                        "vault.");
      declare_ranged_entry(prm,
                           "Displacement amplification",
                           "0",
                           {0, 1e6, "(dimensionless)"},
                           "Factor on displacements in the deformed VTU and "
                           "picture (dimensionless); 0 chooses one that makes "
                           "the larger of the largest block displacement and "
                           "the largest support motion 5 % of the vault's "
                           "size.");
      prm.declare_entry("Output subdivisions",
                        "4",
                        dealii::Patterns::Integer(1, 32),
                        "Subdivisions per block and parameter direction in "
                        "the VTU output (the blocks are curved).");
      prm.declare_entry("Write picture",
                        "true",
                        dealii::Patterns::Bool(),
                        "Render the pictures vault.png (the deformed "
                        "vault) and crack_map.png (the crack map) with "
                        "matplotlib (/usr/bin/python3), in one Python "
                        "process per run; report.html is written either "
                        "way (`List of postprocessors').");
    }

    void
    RigidBlockAnalysis::parse_block_parameters(dealii::ParameterHandler &prm,
                                               const std::string        &name)
    {
      section                 = name;
      options.n_u             = prm.get_integer("Blocks along u");
      options.n_v             = prm.get_integer("Blocks along v");
      options.n_stations      = prm.get_integer("Stations per edge");
      options.n_quadrature    = prm.get_integer("Quadrature points");
      options.supported_edges = split_labels(prm.get("Supported edges"));
      bonded_supports         = prm.get("Support contact") == "bonded";
      leave_out_implied_rows  = prm.get("Implied contact rows") == "leave out";
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
    }

    void
    RigidBlockAnalysis::setup(dealii::ParameterHandler &prm)
    {
      geometry    = plugins::Registry<geometry::Interface>::create(prm);
      solver      = plugins::Registry<lp::Interface>::create(prm);
      solver_name = plugins::Registry<lp::Interface>::selected(prm);
      joints = plugins::Registry<rigid_blocks::InterfaceModel>::create(prm);
      joints_name =
        plugins::Registry<rigid_blocks::InterfaceModel>::selected(prm);
      postprocessors = plugins::Registry<
        rigid_blocks::postprocess::Interface>::create_selected(prm);
      optimiser      = plugins::Registry<adaptation::Optimiser>::create(prm);
      optimiser_name = plugins::Registry<adaptation::Optimiser>::selected(prm);
      // crack refinement moves no line: no minimum block size
      if (optimiser->active() &&
          dynamic_cast<const adaptation::CrackRefinement *>(optimiser.get()) ==
            nullptr)
        {
          plugins::ParsePathScope scope(
            adaptation::Optimiser::registry_section);
          const double h = optimiser->minimum_block_size;
          AssertThrow(h * std::max(options.n_u, options.n_v) < 1,
                      ExcParameter("Minimum block size",
                                   "must be below 1/n for n blocks along a "
                                   "direction (here " +
                                     std::to_string(
                                       std::max(options.n_u, options.n_v)) +
                                     ")"));
          AssertThrow(options.n_u > 1 || options.n_v > 1,
                      ExcParameter("Optimiser",
                                   "one block per patch has no interior "
                                   "line to move"));
        }
      plugins::ParsePathScope scope(section);
      model = std::make_unique<rigid_blocks::BlockModel>(*geometry, options);
      // the other adaptation threads evaluate meshes with copies of their
      // own (made after this set-up succeeded, so errors are reported once)
      if (optimiser->active() && !is_worker)
        for (unsigned int t = 1; t < optimiser->threads; ++t)
          {
            auto  created = plugins::Registry<analysis::Interface>::create(prm);
            auto *worker  = dynamic_cast<RigidBlockAnalysis *>(created.get());
            AssertThrow(worker != nullptr, dealii::ExcInternalError());
            created.release();
            workers.emplace_back(worker);
            worker->is_worker = true;
            worker->setup(prm);
          }
    }

    void
    RigidBlockAnalysis::run(RunContext &context)
    {
      if (optimiser && optimiser->active())
        {
          if (dynamic_cast<const adaptation::CrackRefinement *>(
                optimiser.get()) != nullptr)
            refine_at_cracks(context);
          else
            adapt(context);
        }
      analyse(context);
    }

    void
    RigidBlockAnalysis::build_model()
    {
      const auto start = std::chrono::steady_clock::now();
      model            = mesh_vertices.empty() ?
                           std::make_unique<rigid_blocks::BlockModel>(*geometry, options) :
                           std::make_unique<rigid_blocks::BlockModel>(*geometry,
                                                           options,
                                                           mesh_vertices);
      model_vertices   = mesh_vertices;
      compute_dead_loads();
      seconds_geometry +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    }

    void
    RigidBlockAnalysis::update_thickness()
    {
      if (!model || model_vertices != mesh_vertices)
        return build_model();
      const auto start = std::chrono::steady_clock::now();
      model->update_thickness();
      compute_dead_loads();
      seconds_geometry +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    }

    void
    RigidBlockAnalysis::compute_dead_loads()
    {
      const auto &blocks = model->blocks();
      dead_force.assign(blocks.size(), dealii::Tensor<1, 3>());
      dead_moment.assign(blocks.size(), dealii::Tensor<1, 3>());
      rigid_blocks::integrate_surface_load(*model,
                                           surface_load,
                                           dead_force,
                                           dead_moment);
      for (unsigned int b = 0; b < blocks.size(); ++b)
        dead_force[b][2] -= blocks[b].weight;
    }

    double
    RigidBlockAnalysis::dead_load_magnitude() const
    {
      double total = 0;
      for (const auto &f : dead_force)
        total += f.norm();
      return total;
    }

    lp::Solution
    RigidBlockAnalysis::solve(const lp::LinearProgram &lp,
                              RunContext              &context,
                              const std::string       &mps_name,
                              lp::WarmStart           *warm)
    {
      export_lp(lp, context, mps_name);
      // a large LP can take minutes without a line on the screen
      if (!quiet && lp.n_rows() > 200000)
        {
          std::ostringstream line;
          line << "LP of " << std::setprecision(3) << lp.n_rows() * 1e-6
               << " M rows, " << lp.n_columns() * 1e-6 << " M columns, "
               << lp.n_nonzeros() * 1e-6
               << " M non-zeros: this may take minutes\n";
          context.pcout << line.str();
        }
      const auto   start     = std::chrono::steady_clock::now();
      const double cpu_start = thread_cpu_seconds();
      lp::Solution solution  = warm && solver->warm_starts() ?
                                 solver->solve_warm(lp, *warm) :
                                 solver->solve(lp);
      // every optimum is checked on the LP, also from a back-end that
      // does not check its own (a plugin)
      if (solution.status == lp::Status::optimal && !solution.checked)
        {
          solution.check   = lp::check_pair(lp, solution.x, solution.row_duals);
          solution.checked = true;
        }
      seconds_solve +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      cpu_seconds_solve += thread_cpu_seconds() - cpu_start;
      ++n_solves;
      n_iterations += solution.iterations;
      AssertThrow(solution.status != lp::Status::failed,
                  dealii::ExcMessage("the LP solver (" + solver_name +
                                     ") failed: " + solution.message));
      return solution;
    }

    unsigned int
    RigidBlockAnalysis::locate_block(const unsigned int      patch,
                                     const dealii::Point<2> &uv) const
    {
      const auto &blocks = model->blocks();
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          if (blocks[b].patch != patch)
            continue;
          // deal.II numbers the corners lexicographically: 0, 1, 3, 2 is
          // counter-clockwise
          const auto                       &c      = blocks[b].corners;
          const std::array<unsigned int, 4> ccw    = {{0, 1, 3, 2}};
          bool                              inside = true;
          for (unsigned int k = 0; k < 4 && inside; ++k)
            {
              const dealii::Tensor<1, 2> e = c[ccw[(k + 1) % 4]] - c[ccw[k]];
              const dealii::Tensor<1, 2> r = uv - c[ccw[k]];
              inside = e[0] * r[1] - e[1] * r[0] >= -1e-12 * e.norm();
            }
          if (inside)
            return b;
        }
      AssertThrow(false,
                  dealii::ExcMessage(
                    "no block of patch " + std::to_string(patch) +
                    " contains the parameter point (" + std::to_string(uv[0]) +
                    ", " + std::to_string(uv[1]) + ")"));
      return 0;
    }
  } // namespace analysis
} // namespace masonry
