/**
 * @file
 * The mesh adaptation of the rigid-block analyses by a gene optimiser
 * (RigidBlockAnalysis::adapt()): the genes of a mesh, the evaluations
 * shared by the threads, the summary and adaptation.csv. Crack refinement
 * is in source/adaptation/crack_refinement.cc.
 */
#include <masonry/adaptation/optimiser.h>
#include <masonry/analysis/rigid_block_analysis.h>
#include <masonry/core/json.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/core/scripts.h>
#include <masonry/geometry/interface.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

namespace masonry
{
  namespace analysis
  {
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

      /**
       * What a generation of the adaptation will cost, said on @p pcout if
       * more than 10 s: one evaluation took @p one (s); every one of the
       * @p n_threads threads evolves an island of the whole population
       * size @p population_size, and the threads share the cores.
       */
      void
      report_generation_cost(dealii::ConditionalOStream &pcout,
                             const double                one,
                             const unsigned int          n_threads,
                             const unsigned int          population_size)
      {
        const double threads = n_threads;
        const double cores =
          std::max(1u,
                   std::min(std::thread::hardware_concurrency(),
                            static_cast<unsigned int>(n_threads)));
        const double generation = one * population_size * threads / cores;
        if (generation > 10)
          {
            std::ostringstream line;
            line << "Adaptation: one evaluation takes " << std::setprecision(3)
                 << one << " s; a generation (" << n_threads << " island(s) of "
                 << population_size << " evaluations, on " << cores
                 << " core(s)) about " << generation << " s\n";
            pcout << line.str();
          }
      }

      /** Generation @p g of the adaptation, on @p pcout. */
      void
      report_generation(dealii::ConditionalOStream   &pcout,
                        const adaptation::Generation &g)
      {
        pcout << "  generation " << g.generation << ": best "
              << std::setprecision(8) << g.best << ", mean " << g.mean << ", "
              << g.evaluations << " evaluations, " << std::setprecision(3)
              << g.seconds << " s\n";
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
      // (decided on all ranks alike: the island optimiser communicates)
      if (dealii::Utilities::MPI::min(std::isfinite(uniform) ? 1u : 0u,
                                      context.mpi_communicator) == 0)
        {
          // an incompatible (or failed) uniform mesh: every optimiser
          // compares finite fitnesses, so nothing would steer it; the
          // uniform mesh is analysed and its result says why
          finish_adaptation(x0);
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
      // what a generation will cost, before the first one (silent)
      // starts: every thread evolves an island of the whole population
      // size, and the threads share the cores
      report_generation_cost(pcout,
                             std::chrono::duration<double>(
                               std::chrono::steady_clock::now() - first)
                               .count(),
                             analyses.size(),
                             optimiser->population_size);
      const auto result =
        optimiser->optimise(context.mpi_communicator,
                            fitness,
                            x0,
                            [&](const adaptation::Generation &g) {
                              report_generation(pcout, g);
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
      finish_adaptation(best);

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

    bool
    RigidBlockAnalysis::reuse_evaluations() const
    {
      return !optimiser || optimiser->reuse_evaluations;
    }

    void
    RigidBlockAnalysis::finish_adaptation(const std::vector<double> &genes)
    {
      // the state of the final analysis, after the evaluations
      quiet            = false;
      mesh_vertices    = vertices_from_genes(genes);
      seconds_geometry = seconds_assembly = seconds_solve = 0;
      cpu_seconds_solve                                   = 0;
      // the other threads' copies are not needed for the final analysis
      workers.clear();
      n_solves = n_iterations = 0;
    }
  } // namespace analysis
} // namespace masonry
