#include <masonry/adaptation/optimiser.h>
#include <masonry/core/parameters.h>

#include <chrono>
#include <cmath>
#include <memory>

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
    }

    void
    Optimiser::parse_common_parameters(dealii::ParameterHandler &prm)
    {
      population_size    = prm.get_integer("Population size");
      generations        = prm.get_integer("Generations");
      seed               = prm.get_integer("Seed");
      stall_generations  = prm.get_integer("Stall generations");
      threads            = prm.get_integer("Threads");
      minimum_block_size = prm.get_double("Minimum block size");
      vertex_genes       = prm.get("Mesh genes") == "vertices";
    }

    void
    Optimiser::parse_parameters(dealii::ParameterHandler &)
    {}

    bool
    Optimiser::active() const
    {
      return true;
    }

    namespace
    {
      /** The common loop of the pagmo algorithms. */
      class PagmoOptimiser : public Optimiser
      {
      public:
        Result
        optimise(
          const MPI_Comm                                 comm,
          const std::vector<Fitness>                    &fitness,
          const std::vector<double>                     &x0,
          const std::function<void(const Generation &)> &progress) override
        {
          PagmoSettings settings;
          settings.algorithm         = algorithm();
          settings.population_size   = population_size;
          settings.generations       = generations;
          settings.seed              = seed;
          settings.stall_generations = stall_generations;
          settings.parameter_1       = parameter_1;
          settings.parameter_2       = parameter_2;
          return run_pagmo(comm, settings, fitness, x0, progress);
        }

      protected:
        /** The pagmo algorithm's short name. */
        virtual std::string
        algorithm() const = 0;

        /** Its two parameters. */
        double parameter_1 = 0, parameter_2 = 0;
      };

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

      /** pagmo's simple genetic algorithm (the seed paper's method). */
      class Genetic : public PagmoOptimiser
      {
      public:
        std::string
        algorithm() const override
        {
          return "sga";
        }

        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          prm.declare_entry("Crossover probability",
                            "0.9",
                            dealii::Patterns::Double(0, 1),
                            "Probability of crossover (dimensionless).");
          prm.declare_entry("Mutation probability",
                            "0.1",
                            dealii::Patterns::Double(0, 1),
                            "Probability that a gene mutates "
                            "(dimensionless; polynomial mutation).");
        }

        void
        parse_parameters(dealii::ParameterHandler &prm) override
        {
          parameter_1 = prm.get_double("Crossover probability");
          parameter_2 = prm.get_double("Mutation probability");
        }
      };

      /** pagmo's differential evolution. */
      class DifferentialEvolution : public PagmoOptimiser
      {
      public:
        std::string
        algorithm() const override
        {
          return "de";
        }

        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          prm.declare_entry("Weight",
                            "0.8",
                            dealii::Patterns::Double(0, 2),
                            "Differential weight F (dimensionless).");
          prm.declare_entry("Crossover probability",
                            "0.9",
                            dealii::Patterns::Double(0, 1),
                            "Crossover probability CR (dimensionless).");
        }

        void
        parse_parameters(dealii::ParameterHandler &prm) override
        {
          parameter_1 = prm.get_double("Weight");
          parameter_2 = prm.get_double("Crossover probability");
        }
      };

      /** pagmo's covariance matrix adaptation evolution strategy. */
      class Cmaes : public PagmoOptimiser
      {
      public:
        std::string
        algorithm() const override
        {
          return "cmaes";
        }

        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          prm.declare_entry("Initial step",
                            "0.2",
                            dealii::Patterns::Double(0, 1),
                            "Initial step size σ₀ in gene space "
                            "(dimensionless, genes lie in [0, 1]).");
        }

        void
        parse_parameters(dealii::ParameterHandler &prm) override
        {
          parameter_1 = prm.get_double("Initial step");
        }
      };

      /** pagmo's particle swarm optimisation. */
      class ParticleSwarm : public PagmoOptimiser
      {
      public:
        std::string
        algorithm() const override
        {
          return "pso";
        }

        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          prm.declare_entry("Inertia",
                            "0.7298",
                            dealii::Patterns::Double(0, 1),
                            "Inertia weight ω (dimensionless).");
        }

        void
        parse_parameters(dealii::ParameterHandler &prm) override
        {
          parameter_1 = prm.get_double("Inertia");
        }
      };
    } // namespace
  }   // namespace adaptation
} // namespace masonry

MASONRY_REGISTER_OPTIMISER(masonry::adaptation::None,
                           "none",
                           "No adaptation: the uniform mesh of the analysis.")
MASONRY_REGISTER_OPTIMISER(
  masonry::adaptation::Genetic,
  "genetic",
  "pagmo's simple genetic algorithm (sga: exponential crossover, "
  "polynomial mutation, tournament selection), the seed paper's method.")
MASONRY_REGISTER_OPTIMISER(masonry::adaptation::DifferentialEvolution,
                           "differential evolution",
                           "pagmo's differential evolution (de, variant "
                           "rand/1/exp).")
MASONRY_REGISTER_OPTIMISER(masonry::adaptation::Cmaes,
                           "cmaes",
                           "pagmo's covariance matrix adaptation evolution "
                           "strategy (cmaes, bounds enforced).")
MASONRY_REGISTER_OPTIMISER(masonry::adaptation::ParticleSwarm,
                           "particle swarm",
                           "pagmo's particle swarm optimisation (pso, "
                           "constriction variant).")
