// pagmo only: no deal.II header may be included here (see pagmo_runner.h)
#include <masonry/adaptation/pagmo_runner.h>

#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/de.hpp>
#include <pagmo/algorithms/pso.hpp>
#include <pagmo/algorithms/sga.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace masonry
{
  namespace adaptation
  {
    namespace
    {
      /** The fitness as a pagmo problem (minimisation of −fitness). */
      struct Problem
      {
        std::shared_ptr<
          const std::function<double(const std::vector<double> &)>>
                                       function;
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

      pagmo::algorithm
      make_algorithm(const PagmoSettings &s)
      {
        if (s.algorithm == "sga")
          return pagmo::algorithm{pagmo::sga(1u,
                                             s.parameter_1,
                                             1.,
                                             s.parameter_2,
                                             1.,
                                             2u,
                                             "exponential",
                                             "polynomial",
                                             "tournament",
                                             s.seed)};
        if (s.algorithm == "de")
          return pagmo::algorithm{
            pagmo::de(1u, s.parameter_1, s.parameter_2, 2u, 0., 0., s.seed)};
        if (s.algorithm == "cmaes")
          return pagmo::algorithm{pagmo::cmaes(
            1u, -1, -1, -1, -1, s.parameter_1, 0., 0., true, true, s.seed)};
        if (s.algorithm == "pso")
          return pagmo::algorithm{pagmo::pso(
            1u, s.parameter_1, 2.05, 2.05, 0.5, 5u, 2u, 4u, true, s.seed)};
        throw std::invalid_argument("unknown pagmo algorithm " + s.algorithm);
      }
    } // namespace

    Result
    run_pagmo(const MPI_Comm       comm,
              const PagmoSettings &settings,
              const std::function<double(const std::vector<double> &)> &fitness,
              const std::vector<double>                                &x0,
              const std::function<void(const Generation &)> &progress)
    {
      const auto start = std::chrono::steady_clock::now();
      int        rank = 0, size = 1;
      MPI_Comm_rank(comm, &rank);
      MPI_Comm_size(comm, &size);
      const unsigned int seed = settings.seed + 1000u * rank;
      Problem            udp;
      udp.function = std::make_shared<
        const std::function<double(const std::vector<double> &)>>(fitness);
      udp.counter               = std::make_shared<unsigned long>(0);
      udp.dimension             = x0.size();
      const auto        counter = udp.counter;
      pagmo::problem    problem{udp};
      pagmo::population population{problem, settings.population_size - 1, seed};
      population.push_back(x0);
      PagmoSettings island         = settings;
      island.seed                  = seed;
      pagmo::algorithm   algorithm = make_algorithm(island);
      const unsigned int n         = x0.size();

      // the best mesh of all islands (ties: the lowest rank), on every rank
      std::vector<double> best_x  = population.champion_x();
      double              best_f  = population.champion_f()[0];
      auto                migrate = [&]() {
        const double        mine = population.champion_f()[0];
        std::vector<double> all_f(size);
        MPI_Allgather(&mine, 1, MPI_DOUBLE, all_f.data(), 1, MPI_DOUBLE, comm);
        int winner = 0;
        for (int r = 1; r < size; ++r)
          if (all_f[r] < all_f[winner])
            winner = r;
        std::vector<double> x = population.champion_x();
        MPI_Bcast(x.data(), n, MPI_DOUBLE, winner, comm);
        if (all_f[winner] < best_f || best_x.empty())
          {
            best_f = all_f[winner];
            best_x = x;
          }
        if (size > 1 && all_f[winner] < mine)
          population.set_xf(population.worst_idx(), x, {all_f[winner]});
      };

      Result result;
      auto   record = [&](const unsigned int g) {
        Generation line;
        line.generation = g;
        migrate();
        double local[3] = {double(*counter), 0., 0.}, global[3];
        for (const auto &f : population.get_f())
          if (f[0] < 1e299)
            {
              local[1] -= f[0];
              local[2] += 1;
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
          const double before = -population.champion_f()[0];
          population          = algorithm.evolve(population);
          record(g);
          stalled = (-population.champion_f()[0] > before) ? 0 : stalled + 1;
          if (settings.stall_generations > 0 &&
              stalled >= settings.stall_generations)
            break;
        }
      result.best_genes   = best_x;
      result.best_fitness = -best_f;
      result.evaluations  = result.history.back().evaluations;
      return result;
    }
  } // namespace adaptation
} // namespace masonry
