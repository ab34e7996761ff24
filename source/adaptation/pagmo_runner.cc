// libmasonry_pagmo.so: run_pagmo()'s island loop and the registry of the
// built-in algorithms' factories (see pagmo_runner.h). pagmo only: no deal.II
// header may be included here.
#include <masonry/adaptation/pagmo_runner.h>

#include <pagmo/algorithm.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <memory>
#include <stdexcept>
#include <thread>

namespace masonry
{
  namespace adaptation
  {
    namespace
    {
      /** The fitness as a pagmo problem (minimisation of −fitness). */
      struct Problem
      {
        std::shared_ptr<const Fitness> function;
        std::shared_ptr<unsigned long> counter;
        unsigned int                   dimension = 1;

        pagmo::vector_double
        fitness(const pagmo::vector_double &x) const
        {
          ++*counter;
          const double f = (*function)(x);
          return {std::isfinite(f) ? -f : 1e300};
        }

        std::pair<pagmo::vector_double, pagmo::vector_double>
        get_bounds() const
        {
          return {pagmo::vector_double(dimension, 0.),
                  pagmo::vector_double(dimension, 1.)};
        }
      };

      /** The built-in algorithms' factories by plugin name. */
      std::map<std::string, PagmoFactory> &
      factories()
      {
        static std::map<std::string, PagmoFactory> map;
        return map;
      }

      /**
       * The factory of @p settings' algorithm: its own if it has one,
       * else the one registered under its name. Throws if there is none.
       */
      PagmoFactory
      factory_of(const PagmoSettings &settings)
      {
        PagmoFactory create = settings.create;
        if (create == nullptr)
          {
            const auto f = factories().find(settings.algorithm);
            if (f == factories().end())
              throw std::runtime_error(
                "the pagmo algorithm '" + settings.algorithm +
                "' has no factory: neither its plugin nor libmasonry_pagmo.so "
                "registers one");
            create = f->second;
          }
        return create;
      }

      /**
       * body(t) for t = 0, ..., @p n_threads - 1, each in its own thread
       * (in this one if there is only one); an exception in any is
       * rethrown here once all have ended.
       */
      void
      in_threads(const unsigned int                       n_threads,
                 const std::function<void(unsigned int)> &body)
      {
        if (n_threads == 1)
          return body(0);
        std::vector<std::exception_ptr> errors(n_threads);
        std::vector<std::thread>        threads;
        for (unsigned int t = 0; t < n_threads; ++t)
          threads.emplace_back([&, t]() {
            try
              {
                body(t);
              }
            catch (...)
              {
                errors[t] = std::current_exception();
              }
          });
        for (auto &thread : threads)
          thread.join();
        for (const auto &e : errors)
          if (e)
            std::rethrow_exception(e);
      }

      Result
      run(const MPI_Comm                                 comm,
          const PagmoSettings                           &settings,
          const std::vector<Fitness>                    &fitness,
          const std::vector<double>                     &x0,
          const std::function<void(const Generation &)> &progress)
      {
        const auto         start  = std::chrono::steady_clock::now();
        const PagmoFactory create = factory_of(settings);
        int                rank = 0, size = 1;
        MPI_Comm_rank(comm, &rank);
        MPI_Comm_size(comm, &size);
        const unsigned int n_threads = fitness.size();
        const unsigned int n_islands = n_threads * size;
        const unsigned int n         = x0.size();

        // run body(t) for every island t of this rank, each in its own
        // thread; an exception in any is rethrown here
        const auto parallel =
          [&](const std::function<void(unsigned int)> &body) {
            in_threads(n_threads, body);
          };

        // island i = rank * n_threads + t has the seed settings.seed + 1000 i
        std::vector<std::shared_ptr<unsigned long>> counters(n_threads);
        std::vector<pagmo::population>              populations(n_threads);
        std::vector<pagmo::algorithm>               algorithms;
        for (unsigned int t = 0; t < n_threads; ++t)
          {
            PagmoSettings island = settings;
            island.seed = settings.seed + 1000u * (rank * n_threads + t);
            algorithms.push_back(create(island));
            counters[t] = std::make_shared<unsigned long>(0);
          }
        parallel([&](const unsigned int t) {
          Problem udp;
          udp.function  = std::make_shared<const Fitness>(fitness[t]);
          udp.counter   = counters[t];
          udp.dimension = n;
          populations[t] =
            pagmo::population{pagmo::problem{udp},
                              settings.population_size - 1,
                              settings.seed + 1000u * (rank * n_threads + t)};
          populations[t].push_back(x0);
        });

        // the best mesh of all islands (ties: the lowest island), on every
        // rank; it replaces the worst member of every island that is worse
        std::vector<double> best_x;
        double              best_f  = 0;
        auto                migrate = [&]() {
          std::vector<double> mine(n_threads), all_f(n_islands);
          for (unsigned int t = 0; t < n_threads; ++t)
            mine[t] = populations[t].champion_f()[0];
          MPI_Allgather(mine.data(),
                        n_threads,
                        MPI_DOUBLE,
                        all_f.data(),
                        n_threads,
                        MPI_DOUBLE,
                        comm);
          unsigned int winner = 0;
          for (unsigned int i = 1; i < n_islands; ++i)
            if (all_f[i] < all_f[winner])
              winner = i;
          std::vector<double> x(n);
          if (int(winner / n_threads) == rank)
            x = populations[winner % n_threads].champion_x();
          MPI_Bcast(x.data(), n, MPI_DOUBLE, winner / n_threads, comm);
          if (all_f[winner] < best_f || best_x.empty())
            {
              best_f = all_f[winner];
              best_x = x;
            }
          if (n_islands > 1)
            for (unsigned int t = 0; t < n_threads; ++t)
              if (all_f[winner] < mine[t])
                populations[t].set_xf(populations[t].worst_idx(),
                                      x,
                                      {all_f[winner]});
        };

        Result result;
        auto   record = [&](const unsigned int g) {
          Generation line;
          line.generation = g;
          migrate();
          double local[3] = {0., 0., 0.}, global[3];
          for (unsigned int t = 0; t < n_threads; ++t)
            {
              local[0] += double(*counters[t]);
              for (const auto &f : populations[t].get_f())
                if (f[0] < 1e299)
                  {
                    local[1] -= f[0];
                    local[2] += 1;
                  }
            }
          MPI_Allreduce(local, global, 3, MPI_DOUBLE, MPI_SUM, comm);
          line.evaluations = static_cast<unsigned long>(global[0]);
          line.best        = -best_f;
          line.mean        = global[2] > 0 ? global[1] / global[2] : -1e300;
          line.seconds     = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start)
                           .count();
          result.history.push_back(line);
          progress(line);
        };
        record(0);
        unsigned int stalled = 0;
        for (unsigned int g = 1; g <= settings.generations; ++g)
          {
            // after a migration every island's champion is the global best
            const double before = best_f;
            parallel([&](const unsigned int t) {
              populations[t] = algorithms[t].evolve(populations[t]);
            });
            record(g);
            stalled = best_f < before ? 0 : stalled + 1;
            if (settings.stall_generations > 0 &&
                stalled >= settings.stall_generations)
              break;
          }
        result.best_genes   = best_x;
        result.best_fitness = -best_f;
        result.evaluations  = result.history.back().evaluations;
        return result;
      }
    } // namespace

    bool
    register_pagmo_factory(const char *name, const PagmoFactory create)
    {
      factories()[name] = create;
      return true;
    }
  } // namespace adaptation
} // namespace masonry

/**
 * The entry point that libmasonry's run_pagmo() looks up after loading this
 * library (C linkage: an unmangled name for dlsym). An exception is passed
 * back through @p error, not thrown across the boundary.
 */
extern "C" void
masonry_pagmo_run(
  const MPI_Comm                                                      comm,
  const masonry::adaptation::PagmoSettings                           &settings,
  const std::vector<masonry::adaptation::Fitness>                    &fitness,
  const std::vector<double>                                          &x0,
  const std::function<void(const masonry::adaptation::Generation &)> &progress,
  masonry::adaptation::Result                                        &result,
  std::exception_ptr                                                 &error)
{
  try
    {
      result = masonry::adaptation::run(comm, settings, fitness, x0, progress);
    }
  catch (...)
    {
      error = std::current_exception();
    }
}
