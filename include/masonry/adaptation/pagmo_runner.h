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

namespace pagmo
{
  class algorithm;
}

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

    struct PagmoSettings;

    /** Builds a pagmo algorithm from the settings of a run (or island). */
    using PagmoFactory = pagmo::algorithm (*)(const PagmoSettings &);

    /** Settings of a pagmo run. */
    struct PagmoSettings
    {
      /** Builds the algorithm (one generation per evolve() call). */
      PagmoFactory create = nullptr;
      /** Population size. */
      unsigned int population_size;
      /** Largest number of generations. */
      unsigned int generations;
      /** Seed. */
      unsigned int seed;
      /** Generations without improvement before stopping (0: never). */
      unsigned int stall_generations;
      /**
       * Values of the algorithm's own entries, in the order of
       * PagmoAlgorithm::entries.
       */
      std::vector<double> parameters;
    };

    /** A number entry of a pagmo algorithm's parameter subsection. */
    struct PagmoEntry
    {
      /** Entry name. */
      std::string name;
      /** Default value as written in the parameter file. */
      std::string default_value;
      /** Range of valid values. */
      double min, max;
      /** Help text (with the unit). */
      std::string documentation;
    };

    /**
     * A pagmo algorithm offered as an `Optimiser` plugin. Each algorithm
     * is one file in source/adaptation/pagmo/ (or in a user's shared
     * library) that includes pagmo but no deal.II header, defines its
     * factory and calls MASONRY_REGISTER_PAGMO_ALGORITHM.
     */
    struct PagmoAlgorithm
    {
      /** Plugin name (`set Optimiser = ...`). */
      std::string name;
      /** Its description in the selection's help text. */
      std::string description;
      /** Its own entries, declared in `subsection Adaptation/<Name>`. */
      std::vector<PagmoEntry> entries;
      /** Builds the algorithm (settings.parameters follow entries). */
      PagmoFactory create;
    };

    /**
     * Add @p algorithm to the `Optimiser` plugins (implemented with the
     * plugin registry in optimiser.cc). Returns true.
     */
    bool
    register_pagmo_algorithm(const PagmoAlgorithm &algorithm);

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

#define MASONRY_PAGMO_CONCAT_(a, b) a##b
#define MASONRY_PAGMO_CONCAT(a, b) MASONRY_PAGMO_CONCAT_(a, b)

/**
 * Register a pagmo algorithm as an `Optimiser` plugin: the arguments
 * initialise a masonry::adaptation::PagmoAlgorithm (name, description,
 * entries, factory). Use once, at namespace scope, in the algorithm's file.
 */
#define MASONRY_REGISTER_PAGMO_ALGORITHM(...)                              \
  namespace                                                                \
  {                                                                        \
    const bool MASONRY_PAGMO_CONCAT(masonry_pagmo_registered_, __LINE__) = \
      masonry::adaptation::register_pagmo_algorithm(                       \
        masonry::adaptation::PagmoAlgorithm{__VA_ARGS__});                 \
  }

#endif
