#include <masonry/adaptation/optimiser.h>
#include <masonry/core/parameters.h>

#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <utility>

namespace masonry
{
  namespace adaptation
  {
    const char *
    Optimiser::default_plugin()
    {
      return "none";
    }

    std::string
    Optimiser::selection_documentation()
    {
      return "Adaptation of the block mesh (seed paper, section 3): the "
             "interior parameter lines of every patch (and with `Mesh genes "
             "= vertices' every interior vertex) move until the rigid-block "
             "analysis finds its best answer: the largest work of the loads "
             "minus dissipation (`settlement'), the smallest load "
             "multiplier (`limit load') or the largest minimum thickness "
             "(`minimum thickness'). The initial population contains the "
             "uniform mesh, so the result is never worse than it. The best "
             "mesh is then analysed and written as usual, with "
             "adaptation.csv (history) and adaptation.png.";
    }

    void
    Optimiser::declare_common_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        "Mesh genes",
        "lines",
        dealii::Patterns::Selection("lines|vertices"),
        "What moves: `lines' moves whole parameter lines (n_u − 1 genes per "
        "patch for the lines u = const, n_v − 1 shared by all patches for "
        "the lines v = const); `vertices' in addition moves every interior "
        "vertex of every patch in (u, v), by at most 30 % of the gap to the "
        "neighbouring lines (two more genes per interior vertex), while the "
        "boundary vertices slide along the boundary with the lines, so "
        "glued patches stay compatible.");
      prm.declare_entry("Population size",
                        "16",
                        dealii::Patterns::Integer(5, 10000),
                        "Number of meshes per generation (dimensionless).");
      prm.declare_entry("Generations",
                        "20",
                        dealii::Patterns::Integer(1, 100000),
                        "Largest number of generations (dimensionless).");
      prm.declare_entry("Seed",
                        "1",
                        dealii::Patterns::Integer(0),
                        "Seed of the random numbers: a fixed seed gives the "
                        "same result on the same number of ranks.");
      prm.declare_entry("Stall generations",
                        "5",
                        dealii::Patterns::Integer(0),
                        "Stop after this many generations without "
                        "improvement of the best fitness (0: never stop "
                        "early).");
      prm.declare_entry(
        "Threads",
        "1",
        dealii::Patterns::Integer(1, 256),
        "Islands evolved in parallel threads on each MPI rank "
        "(dimensionless): every rank holds this many populations of "
        "`Population size' meshes, each evolved one generation at a time "
        "in its own thread with its own copy of the analysis (geometry, "
        "blocks, LP solver), and after every generation the best mesh of "
        "all islands of all ranks replaces the worst member of every island "
        "that is worse. Islands = ranks x threads; a fixed seed gives the "
        "same result for the same numbers of ranks and threads. Use the "
        "cores of a node: e.g. 2 threads on one rank or 1 thread on each "
        "of 2 ranks on 2 cores.");
      prm.declare_entry("Minimum block size",
                        "0.02",
                        dealii::Patterns::Double(0, 0.5),
                        "Smallest size of a block along a parameter "
                        "direction, as a fraction of the patch's parameter "
                        "range (dimensionless); must be below 1/n for n "
                        "blocks along that direction.");
      prm.declare_entry(
        "Reuse evaluations",
        "true",
        dealii::Patterns::Bool(),
        "Whether the adaptation reuses work: the fitness of a gene vector "
        "evaluated before is looked up (an evaluation is deterministic), and "
        "a `minimum thickness' evaluation computes the blocks once and "
        "rescales them for every thickness factor. false: every evaluation "
        "and every factor from scratch, for checks and timing (the same "
        "result, bit for bit). Unitless flag.");
    }

    void
    Optimiser::parse_common_parameters(dealii::ParameterHandler &prm)
    {
      reuse_evaluations  = prm.get_bool("Reuse evaluations");
      population_size    = prm.get_integer("Population size");
      generations        = prm.get_integer("Generations");
      seed               = prm.get_integer("Seed");
      stall_generations  = prm.get_integer("Stall generations");
      threads            = prm.get_integer("Threads");
      minimum_block_size = prm.get_double("Minimum block size");
      vertex_genes       = prm.get("Mesh genes") == "vertices";
    }


    bool
    Optimiser::active() const
    {
      return true;
    }

    namespace
    {
      /** No adaptation. */
      class None : public Optimiser
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &)
        {}

        bool
        active() const override
        {
          return false;
        }

        Result
        optimise(const MPI_Comm,
                 const std::vector<Fitness> &,
                 const std::vector<double> &x0,
                 const std::function<void(const Generation &)> &) override
        {
          Result r;
          r.best_genes = x0;
          return r;
        }
      };

      /** The registered pagmo algorithms, in the order of registration. */
      std::vector<PagmoAlgorithm> &
      pagmo_algorithms()
      {
        static std::vector<PagmoAlgorithm> list;
        return list;
      }

      /** The `Optimiser` plugin of a pagmo algorithm. */
      class PagmoOptimiser : public Optimiser
      {
      public:
        explicit PagmoOptimiser(const PagmoAlgorithm &algorithm)
          : algorithm(algorithm)
        {}

        /** Declare the algorithm's own entries. */
        static void
        declare(const PagmoAlgorithm &algorithm, dealii::ParameterHandler &prm)
        {
          for (const auto &e : algorithm.entries)
            prm.declare_entry(e.name,
                              e.default_value,
                              dealii::Patterns::Double(e.min, e.max),
                              e.documentation);
        }

        void
        parse_parameters(dealii::ParameterHandler &prm) override
        {
          parameters.clear();
          for (const auto &e : algorithm.entries)
            parameters.push_back(prm.get_double(e.name));
        }

        Result
        optimise(
          const MPI_Comm                                 comm,
          const std::vector<Fitness>                    &fitness,
          const std::vector<double>                     &x0,
          const std::function<void(const Generation &)> &progress) override
        {
          PagmoSettings settings;
          settings.create            = algorithm.create;
          settings.algorithm         = algorithm.name;
          settings.population_size   = population_size;
          settings.generations       = generations;
          settings.seed              = seed;
          settings.stall_generations = stall_generations;
          settings.parameters        = parameters;
          return run_pagmo(comm, settings, fitness, x0, progress);
        }

      private:
        const PagmoAlgorithm algorithm;
        std::vector<double>  parameters;
      };

      // The registry takes plain function pointers: one pair per slot,
      // slot i serving the i-th registered pagmo algorithm.
      constexpr unsigned int max_pagmo_algorithms = 32;

      template <unsigned int i>
      void
      declare_slot(dealii::ParameterHandler &prm)
      {
        PagmoOptimiser::declare(pagmo_algorithms()[i], prm);
      }

      template <unsigned int i>
      std::unique_ptr<Optimiser>
      create_slot()
      {
        return std::make_unique<PagmoOptimiser>(pagmo_algorithms()[i]);
      }

      template <unsigned int... i>
      constexpr std::array<std::pair<plugins::Registry<Optimiser>::Declare,
                                     plugins::Registry<Optimiser>::Factory>,
                           sizeof...(i)>
      make_slots(std::integer_sequence<unsigned int, i...>)
      {
        return {{{&declare_slot<i>, &create_slot<i>}...}};
      }
    } // namespace

    bool
    register_pagmo_algorithm(const PagmoAlgorithm &algorithm)
    {
      static constexpr auto slots = make_slots(
        std::make_integer_sequence<unsigned int, max_pagmo_algorithms>());
      auto &list = pagmo_algorithms();
      AssertThrow(list.size() < max_pagmo_algorithms,
                  dealii::ExcMessage("more than " +
                                     std::to_string(max_pagmo_algorithms) +
                                     " pagmo algorithms registered"));
      // the slots refer to the list by index: never reallocate it
      list.reserve(max_pagmo_algorithms);
      list.push_back(algorithm);
      const auto &slot = slots[list.size() - 1];
      return plugins::Registry<Optimiser>::add(algorithm.name,
                                               algorithm.description,
                                               slot.first,
                                               slot.second);
    }
  } // namespace adaptation
} // namespace masonry

MASONRY_REGISTER_OPTIMISER(masonry::adaptation::None,
                           "none",
                           "No adaptation: the uniform mesh of the analysis.")
