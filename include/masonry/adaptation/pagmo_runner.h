/**
 * @file
 * The pagmo2 side of the optimisers, kept apart from deal.II headers (their
 * boost serialisation of std::tuple clashes with pagmo's s11n.hpp).
 */
#ifndef masonry_adaptation_pagmo_runner_h
#define masonry_adaptation_pagmo_runner_h

#include <functional>
#include <mpi.h>
#include <string>
#include <vector>

namespace masonry
{
  namespace adaptation
  {
    /** One line of the convergence history. */
    struct Generation
    {
      /** Generation number (0: the initial population). */
      unsigned int generation;
      /** Fitness evaluations so far. */
      unsigned long evaluations;
      /** Best fitness so far (the quantity maximised). */
      double best;
      /** Mean fitness of the population (finite members only). */
      double mean;
      /** Seconds since the start. */
      double seconds;
    };

    /** The outcome of an optimisation. */
    struct Result
    {
      /** The best genes. */
      std::vector<double> best_genes;
      /** Their fitness. */
      double best_fitness = 0;
      /** History, one line per generation. */
      std::vector<Generation> history;
      /** Number of fitness evaluations. */
      unsigned long evaluations = 0;
    };

    /** Settings of a pagmo run. */
    struct PagmoSettings
    {
      /** "sga", "de", "cmaes" or "pso". */
      std::string algorithm;
      /** Population size. */
      unsigned int population_size;
      /** Largest number of generations. */
      unsigned int generations;
      /** Seed. */
      unsigned int seed;
      /** Generations without improvement before stopping (0: never). */
      unsigned int stall_generations;
      /** Two algorithm parameters (see the plugins). */
      double parameter_1, parameter_2;
    };

    /** A fitness function (the quantity maximised). */
    using Fitness = std::function<double(const std::vector<double> &)>;

    /**
     * Maximise the fitness over [0, 1]^n (n = x0.size()) with a pagmo
     * algorithm, evolving one generation at a time from populations that
     * contain @p x0; non-finite fitness values count as the worst. Every
     * rank holds @p fitness.size() islands, evolved in parallel threads,
     * island t calling fitness[t] only (so the functions need not be
     * thread-safe with themselves); after every generation the best mesh
     * of all islands of all ranks migrates to every island. A fixed seed
     * gives the same result for the same numbers of ranks and threads.
     */
    Result
    run_pagmo(const MPI_Comm                                 comm,
              const PagmoSettings                           &settings,
              const std::vector<Fitness>                    &fitness,
              const std::vector<double>                     &x0,
              const std::function<void(const Generation &)> &progress);
  } // namespace adaptation
} // namespace masonry

#endif
