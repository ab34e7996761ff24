/**
 * @file
 * The pagmo2 side of the optimisers, kept apart from deal.II headers (their
 * boost serialisation of std::tuple clashes with pagmo's s11n.hpp).
 *
 * pagmo lives in its own library, libmasonry_pagmo.so (run_pagmo()'s
 * island loop and the factories of the built-in algorithms), loaded by
 * run_pagmo() on its first call: a run without adaptation, `--validate' and
 * `--print-parameters' never load pagmo (its loading and its static tables
 * cost about 11 ms and 33 MiB a process). libmasonry holds the algorithms'
 * names, descriptions and entries, so the parameters are the same either
 * way. A built-in algorithm's file in source/adaptation/pagmo/ is compiled
 * into both libraries: into libmasonry without MASONRY_PAGMO_FACTORIES (its
 * MASONRY_REGISTER_PAGMO_ALGORITHM with a null factory, no pagmo header),
 * into libmasonry_pagmo.so with it (its factory, registered by name with
 * MASONRY_REGISTER_PAGMO_FACTORY). A plugin of a user's shared library
 * includes pagmo, links Pagmo::pagmo itself and passes its factory to
 * MASONRY_REGISTER_PAGMO_ALGORITHM directly.
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
      /**
       * Builds the algorithm (one generation per evolve() call); nullptr:
       * the factory registered under @p algorithm in libmasonry_pagmo.so.
       */
      PagmoFactory create = nullptr;
      /** The algorithm's plugin name. */
      std::string algorithm;
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
      /**
       * Builds the algorithm (settings.parameters follow entries); nullptr
       * for the built-in algorithms, whose factories are registered by name
       * in libmasonry_pagmo.so (MASONRY_REGISTER_PAGMO_FACTORY).
       */
      PagmoFactory create;
    };

    /**
     * Add @p algorithm to the `Optimiser` plugins (implemented with the
     * plugin registry in optimiser.cc). Returns true.
     */
    bool
    register_pagmo_algorithm(const PagmoAlgorithm &algorithm);

    /**
     * Register the factory of the built-in algorithm @p name (defined in
     * libmasonry_pagmo.so, called by MASONRY_REGISTER_PAGMO_FACTORY in the
     * algorithm's file compiled with MASONRY_PAGMO_FACTORIES). Returns true.
     */
    bool
    register_pagmo_factory(const char *name, PagmoFactory create);

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
     * The first call loads libmasonry_pagmo.so (from the directory of
     * libmasonry.so, else the loader's path); an error names the library
     * and the cause.
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
 * entries, factory; the factory nullptr for a built-in algorithm). Use
 * once, at namespace scope, in the algorithm's file.
 */
#define MASONRY_REGISTER_PAGMO_ALGORITHM(...)                              \
  namespace                                                                \
  {                                                                        \
    const bool MASONRY_PAGMO_CONCAT(masonry_pagmo_registered_, __LINE__) = \
      masonry::adaptation::register_pagmo_algorithm(                       \
        masonry::adaptation::PagmoAlgorithm{__VA_ARGS__});                 \
  }

/**
 * Register the factory of a built-in algorithm by its plugin name (in the
 * part of its file compiled into libmasonry_pagmo.so). Use once, at
 * namespace scope.
 */
#define MASONRY_REGISTER_PAGMO_FACTORY(name, factory)                   \
  namespace                                                             \
  {                                                                     \
    const bool MASONRY_PAGMO_CONCAT(masonry_pagmo_factory_, __LINE__) = \
      masonry::adaptation::register_pagmo_factory(name, factory);       \
  }

#endif
