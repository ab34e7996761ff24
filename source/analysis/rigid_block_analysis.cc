#include <masonry/adaptation/crack_refinement.h>
#include <masonry/adaptation/optimiser.h>
#include <masonry/analysis/rigid_block_analysis.h>
#include <masonry/core/json.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/core/parameters.h>
#include <masonry/core/scripts.h>
#include <masonry/geometry/interface.h>
#include <masonry/rigid_blocks/interface_model.h>
#include <masonry/rigid_blocks/postprocess/interface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>
#include <time.h>

namespace masonry
{
  namespace analysis
  {
    namespace
    {
      using Clock = std::chrono::steady_clock;

      /** Seconds since @p start. */
      double
      seconds_since(const Clock::time_point &start)
      {
        return std::chrono::duration<double>(Clock::now() - start).count();
      }
    } // namespace

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

    void
    RigidBlockAnalysis::report(RunContext        &context,
                               const std::string &status,
                               const std::string &explanation) const
    {
      context.summary["status"]      = status;
      context.summary["explanation"] = explanation;
      context.pcout << "Result: " << status << " — " << explanation << "\n";
      if (quiet || !model)
        return;
      // no solution: the blocks at rest, no contact forces; the outputs
      // that can say something without one (the report page) run
      const auto                               start = Clock::now();
      const rigid_blocks::Motion               rest(model->blocks().size());
      const std::vector<std::array<double, 3>> no_forces;
      const rigid_blocks::SupportMotion ground = prescribed_support_motion();
      bool                              moves  = false;
      for (const auto &i : model->interfaces())
        if (i.second == rigid_blocks::Interface::support)
          for (const auto &c : i.points)
            moves = moves || ground(c.position, i.support_label).norm() > 0;
      const rigid_blocks::postprocess::Result result(*model,
                                                     rest,
                                                     ground,
                                                     no_forces,
                                                     output_options,
                                                     moves,
                                                     context.mpi_communicator,
                                                     false);
      bool                                    any = false;
      for (const auto &[name, postprocessor] : postprocessors)
        if (postprocessor->writes_without_solution())
          {
            postprocessor->execute(result, context);
            any = true;
          }
      if (any)
        {
          result.render_pictures();
          context.summary["seconds_output"] = seconds_since(start);
        }
    }

    rigid_blocks::SupportMotion
    RigidBlockAnalysis::prescribed_support_motion() const
    {
      return [](const dealii::Point<3> &, const std::string &) {
        return dealii::Tensor<1, 3>();
      };
    }

    double
    RigidBlockAnalysis::centimetre_scale(const std::vector<double> &x) const
    {
      double largest = 0;
      for (unsigned int b = 0; b < model->blocks().size(); ++b)
        for (unsigned int d = 0; d < 3; ++d)
          largest = std::max(largest, std::abs(x[6 * b + d]));
      return largest > 0 ? 0.01 / largest : 1.;
    }

    void
    RigidBlockAnalysis::write_results(
      const rigid_blocks::Motion               &motion,
      const rigid_blocks::SupportMotion        &support_motion,
      const bool                                supports_move,
      const std::vector<std::array<double, 3>> &forces,
      RunContext                               &context) const
    {
      const auto                              start = Clock::now();
      const rigid_blocks::postprocess::Result result(*model,
                                                     motion,
                                                     support_motion,
                                                     forces,
                                                     output_options,
                                                     supports_move,
                                                     context.mpi_communicator);
      for (const auto &[name, postprocessor] : postprocessors)
        postprocessor->execute(result, context);
      // the pictures the postprocessors queued, in one Python process
      const double seconds_picture = result.render_pictures();
      if (seconds_picture > 0)
        context.summary["seconds_picture"] = seconds_picture;
      // what writing the results costs (not part of the analysis' timings)
      context.summary["seconds_output"] = seconds_since(start);
    }

    void
    RigidBlockAnalysis::write_mechanism(
      const rigid_blocks::Motion               &motion,
      const std::vector<std::array<double, 3>> &forces,
      RunContext                               &context) const
    {
      write_results(
        motion,
        [](const dealii::Point<3> &, const std::string &) {
          return dealii::Tensor<1, 3>();
        },
        false,
        forces,
        context);
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
      prm.declare_entry("Displacement amplification",
                        "0",
                        dealii::Patterns::Double(0),
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

    std::vector<double>
    RigidBlockAnalysis::uniform_genes() const
    {
      std::vector<double> genes;
      for (unsigned int p = 0; p < geometry->patches().size(); ++p)
        for (unsigned int k = 1; k < options.n_u; ++k)
          genes.push_back(double(k) / options.n_u);
      for (unsigned int k = 1; k < options.n_v; ++k)
        genes.push_back(double(k) / options.n_v);
      // `vertices': two offsets per interior vertex, 1/2 = no offset
      if (optimiser->vertex_genes)
        genes.resize(genes.size() + 2 * geometry->patches().size() *
                                      (options.n_u - 1) * (options.n_v - 1),
                     0.5);
      return genes;
    }

    std::vector<std::vector<dealii::Point<2>>>
    RigidBlockAnalysis::vertices_from_genes(
      const std::vector<double> &genes) const
    {
      const unsigned int n_patches = geometry->patches().size();
      const unsigned int nu = options.n_u, nv = options.n_v;
      const double       h       = optimiser->minimum_block_size;
      const unsigned int n_lines = n_patches * (nu - 1) + (nv - 1);
      AssertThrow(genes.size() ==
                    n_lines + (optimiser->vertex_genes ?
                                 2 * n_patches * (nu - 1) * (nv - 1) :
                                 0),
                  dealii::ExcMessage("wrong number of mesh genes"));
      auto positions = [&](const unsigned int first, const unsigned int n) {
        std::vector<double> q(genes.begin() + first,
                              genes.begin() + first + (n - 1));
        std::sort(q.begin(), q.end());
        std::vector<double> p(n + 1, 0.);
        p[n] = 1;
        for (unsigned int k = 1; k < n; ++k)
          p[k] = k * h + std::clamp(q[k - 1], 0., 1.) * (1 - n * h);
        return p;
      };
      const std::vector<double> v = positions(n_patches * (nu - 1), nv);
      std::vector<std::vector<dealii::Point<2>>> vertices(n_patches);
      for (unsigned int p = 0; p < n_patches; ++p)
        {
          const std::vector<double> u = positions(p * (nu - 1), nu);
          for (unsigned int j = 0; j <= nv; ++j)
            for (unsigned int i = 0; i <= nu; ++i)
              vertices[p].emplace_back(u[i], v[j]);
          if (!optimiser->vertex_genes)
            continue;
          // interior vertices move off the line intersections by at most
          // 30 % of the gap to the neighbouring line on either side, so
          // that neighbouring vertices cannot cross and cells stay valid
          for (unsigned int j = 1; j < nv; ++j)
            for (unsigned int i = 1; i < nu; ++i)
              {
                const unsigned int g =
                  n_lines +
                  2 * (p * (nu - 1) * (nv - 1) + (j - 1) * (nu - 1) + (i - 1));
                const double du = 2 * std::clamp(genes[g], 0., 1.) - 1;
                const double dv = 2 * std::clamp(genes[g + 1], 0., 1.) - 1;
                auto        &x  = vertices[p][j * (nu + 1) + i];
                x[0] += 0.3 * du * (du < 0 ? u[i] - u[i - 1] : u[i + 1] - u[i]);
                x[1] += 0.3 * dv * (dv < 0 ? v[j] - v[j - 1] : v[j + 1] - v[j]);
              }
        }
      return vertices;
    }

    namespace
    {
      /** adaptation.csv (best and mean fitness per generation) and, with
       * @p picture, adaptation.png. */
      void
      write_adaptation_history(const adaptation::Result &result,
                               const std::string        &fitness,
                               const bool                picture,
                               RunContext               &context)
      {
        {
          OutputFile csv(context.output.file("adaptation.csv"));
          csv << "# convergence of the mesh adaptation: best and mean "
              << fitness << " per generation\n"
              << "generation,evaluations,best,mean,seconds\n"
              << std::setprecision(12);
          for (const auto &g : result.history)
            csv << g.generation << "," << g.evaluations << "," << g.best << ","
                << g.mean << "," << g.seconds << "\n";
          csv.close();
        }
        if (picture)
          {
            const std::string dir = context.output.path();
            const std::string why =
              run_script("adaptation_plot.py",
                         {dir + "adaptation.csv", dir + "adaptation.png"},
                         {dir + "adaptation.png"});
            if (why.empty())
              context.output.file("adaptation.png");
            else
              context.pcout << "Note: adaptation.png not written (" << why
                            << ")\n";
          }
      }
    } // namespace

    void
    RigidBlockAnalysis::adapt(RunContext &context)
    {
      auto              &pcout                = context.pcout;
      const auto         x0                   = uniform_genes();
      const unsigned int n_interfaces_uniform = model->interfaces().size();
      pcout << "Adaptation: " << optimiser_name << ", " << x0.size()
            << " genes, population " << optimiser->population_size
            << ", at most " << optimiser->generations << " generations; "
            << "maximising " << fitness_name() << "\n";
      // one analysis per thread: this one and its workers
      std::vector<RigidBlockAnalysis *> analyses = {this};
      for (const auto &w : workers)
        analyses.push_back(w.get());
      std::vector<unsigned long>       failed(analyses.size(), 0);
      std::vector<adaptation::Fitness> fitness;
      const auto                       start = std::chrono::steady_clock::now();
      // the fitness of every gene vector evaluated so far: optimisers
      // evaluate clones of individuals again (a genetic algorithm's
      // offspring without crossover or mutation: 15 of the first 65
      // evaluations on the Bothwell example), and an evaluation is
      // deterministic, so a clone costs a look-up instead of a mesh and an
      // LP (shared by the threads)
      std::map<std::vector<double>, std::pair<double, bool>> evaluated;
      std::mutex                                             evaluated_mutex;
      unsigned long                                          n_repeated = 0;
      for (unsigned int t = 0; t < analyses.size(); ++t)
        {
          analyses[t]->quiet = true;
          fitness.emplace_back([&, t](const std::vector<double> &genes) {
            if (reuse_evaluations())
              {
                std::lock_guard<std::mutex> lock(evaluated_mutex);
                const auto                  known = evaluated.find(genes);
                if (known != evaluated.end())
                  {
                    ++n_repeated;
                    if (known->second.second)
                      ++failed[t];
                    return known->second.first;
                  }
              }
            RigidBlockAnalysis &a = *analyses[t];
            double              f = -std::numeric_limits<double>::infinity();
            bool                failure = true;
            try
              {
                a.mesh_vertices = a.vertices_from_genes(genes);
                f               = a.evaluate(context);
                // patches glued along moved lines must stay glued
                failure = a.model->interfaces().size() != n_interfaces_uniform;
                if (failure)
                  f = -std::numeric_limits<double>::infinity();
              }
            catch (const std::exception &)
              {
                f = -std::numeric_limits<double>::infinity();
              }
            if (failure)
              ++failed[t];
            std::lock_guard<std::mutex> lock(evaluated_mutex);
            evaluated.emplace(genes, std::make_pair(f, failure));
            return f;
          });
        }
      const auto   first   = std::chrono::steady_clock::now();
      const double uniform = fitness[0](x0);
      // the state of the final analysis, after the evaluations
      const auto finish = [&](const std::vector<double> &genes) {
        quiet            = false;
        mesh_vertices    = vertices_from_genes(genes);
        seconds_geometry = seconds_assembly = seconds_solve = 0;
        cpu_seconds_solve                                   = 0;
        // the other threads' copies are not needed for the final analysis
        workers.clear();
        n_solves = n_iterations = 0;
      };
      // (decided on all ranks alike: the island optimiser communicates)
      if (dealii::Utilities::MPI::min(std::isfinite(uniform) ? 1u : 0u,
                                      context.mpi_communicator) == 0)
        {
          // an incompatible (or failed) uniform mesh: every optimiser
          // compares finite fitnesses, so nothing would steer it; the
          // uniform mesh is analysed and its result says why
          finish(x0);
          Json a           = Json::object();
          a["optimiser"]   = optimiser_name;
          a["fitness"]     = fitness_name();
          a["genes"]       = x0.size();
          a["evaluations"] = 1;
          a["stopped"] = "the uniform mesh gives no finite " + fitness_name();
          context.summary["adaptation"] = a;
          pcout << "Adaptation: stopped: the uniform mesh gives no finite "
                << fitness_name() << " (the result below says why)\n";
          return;
        }
      {
        // what a generation will cost, before the first one (silent)
        // starts: every thread evolves an island of the whole population
        // size, and the threads share the cores
        const double one = std::chrono::duration<double>(
                             std::chrono::steady_clock::now() - first)
                             .count();
        const double threads = analyses.size();
        const double cores =
          std::max(1u,
                   std::min(std::thread::hardware_concurrency(),
                            static_cast<unsigned int>(analyses.size())));
        const double generation =
          one * optimiser->population_size * threads / cores;
        if (generation > 10)
          {
            std::ostringstream line;
            line << "Adaptation: one evaluation takes " << std::setprecision(3)
                 << one << " s; a generation (" << analyses.size()
                 << " island(s) of " << optimiser->population_size
                 << " evaluations, on " << cores << " core(s)) about "
                 << generation << " s\n";
            pcout << line.str();
          }
      }
      const auto result =
        optimiser->optimise(context.mpi_communicator,
                            fitness,
                            x0,
                            [&](const adaptation::Generation &g) {
                              pcout << "  generation " << g.generation
                                    << ": best " << std::setprecision(8)
                                    << g.best << ", mean " << g.mean << ", "
                                    << g.evaluations << " evaluations, "
                                    << std::setprecision(3) << g.seconds
                                    << " s\n";
                            });
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      unsigned long n_failed = 0;
      for (const auto f : failed)
        n_failed += f;
      const unsigned int n_threads = analyses.size();
      // the uniform mesh unless the optimiser found a mesh at least as good
      const bool   improved     = result.best_fitness >= uniform;
      const auto  &best         = improved ? result.best_genes : x0;
      const double best_fitness = improved ? result.best_fitness : uniform;
      finish(best);

      Json a               = Json::object();
      a["optimiser"]       = optimiser_name;
      a["fitness"]         = fitness_name();
      a["genes"]           = x0.size();
      a["population_size"] = optimiser->population_size;
      a["generations"] =
        result.history.empty() ? 0 : result.history.back().generation;
      a["evaluations"] = result.evaluations + 1;
      a["threads"]     = n_threads;
      a["islands"] =
        dealii::Utilities::MPI::n_mpi_processes(context.mpi_communicator) *
        n_threads;
      a["failed_evaluations"]     = n_failed;
      a["seconds"]                = seconds;
      a["evaluations_per_second"] = (result.evaluations + 1) / seconds;
      a["repeated_evaluations"]   = n_repeated;
      a["uniform_fitness"]        = uniform;
      a["best_fitness"]           = best_fitness;
      Json genes                  = Json::array();
      for (const double g : best)
        genes.push_back(g);
      a["best_genes"]               = genes;
      context.summary["adaptation"] = a;
      pcout << "Adaptation: best " << fitness_name() << " "
            << std::setprecision(8) << best_fitness << " (uniform mesh "
            << uniform << "), " << result.evaluations + 1 << " evaluations in "
            << std::setprecision(3) << seconds << " s\n";

      if (dealii::Utilities::MPI::this_mpi_process(context.mpi_communicator) ==
          0)
        write_adaptation_history(result,
                                 fitness_name(),
                                 output_options.write_picture,
                                 context);
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

    bool
    RigidBlockAnalysis::reuse_evaluations() const
    {
      return !optimiser || optimiser->reuse_evaluations;
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

    void
    RigidBlockAnalysis::export_lp(const lp::LinearProgram &lp,
                                  RunContext              &context,
                                  const std::string       &mps_name) const
    {
      if (!quiet && solver->export_mps() &&
          dealii::Utilities::MPI::this_mpi_process(context.mpi_communicator) ==
            0)
        lp.write_mps(context.output.file(mps_name));
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

    void
    RigidBlockAnalysis::check_solution(const lp::Solution &solution,
                                       RunContext         &context) const
    {
      const lp::PairCheck &c       = solution.check;
      Json                &summary = context.summary;
      summary["lp_max_violation"]  = c.primal_residual;
      summary["lp_dual_violation"] = c.dual_residual;
      summary["lp_relative_gap"]   = c.relative_gap();
      const bool passed            = c.within(solver->check_tolerance());
      summary["lp_check"]          = passed ? "passed" : "failed";
      if (!passed)
        {
          std::ostringstream line;
          line << std::setprecision(3)
               << "Warning: the LP solver's optimum fails the check on the "
                  "LP (tolerance "
               << solver->check_tolerance() << ", LP units): bound violation "
               << c.primal_residual << ", dual sign violation "
               << c.dual_residual << ", relative duality gap "
               << c.relative_gap()
               << "; the results are uncertain by about that much\n";
          context.pcout << line.str();
        }
    }

    void
    RigidBlockAnalysis::record_model(RunContext              &context,
                                     const lp::LinearProgram *lp) const
    {
      Json &summary               = context.summary;
      summary["n_blocks"]         = model->blocks().size();
      summary["n_interfaces"]     = model->interfaces().size();
      summary["n_contact_points"] = model->n_contact_points();
      summary["interface_model"]  = joints_name;
      if (lp)
        {
          summary["lp_rows"]     = lp->n_rows();
          summary["lp_columns"]  = lp->n_columns();
          summary["lp_nonzeros"] = lp->n_nonzeros();
        }
      summary["lp_solver"]         = solver_name;
      summary["lp_solves"]         = n_solves;
      summary["lp_iterations"]     = n_iterations;
      summary["seconds_geometry"]  = seconds_geometry;
      summary["seconds_assembly"]  = seconds_assembly;
      summary["seconds_solve"]     = seconds_solve;
      summary["cpu_seconds_solve"] = cpu_seconds_solve;
    }

    void
    RigidBlockAnalysis::record(const lp::LinearProgram &lp,
                               const lp::Solution      &solution,
                               RunContext              &context) const
    {
      record_model(context, &lp);
      Json &summary         = context.summary;
      summary["lp_message"] = solution.message;
      if (solution.status == lp::Status::optimal)
        check_solution(solution, context);
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
