/**
 * @file
 * Optimisers that move the block boundaries of a rigid-block model in NURBS
 * parameter space (`subsection Adaptation`, `set Optimiser = ...`): the
 * seed paper's genetic algorithm and other population-based methods of
 * pagmo2.
 */
#ifndef masonry_adaptation_optimiser_h
#define masonry_adaptation_optimiser_h

#include <masonry/adaptation/pagmo_runner.h>
#include <masonry/core/plugins.h>

#include <functional>
#include <string>
#include <vector>

namespace masonry
{
  /** Adaptation of block meshes. */
  namespace adaptation
  {
    /**
     * Base class of optimisers. The problem: maximise a fitness over genes
     * in [0, 1]^n; the initial population contains a given point (the
     * uniform mesh), so the result is never worse than it.
     */
    class Optimiser : public plugins::InterfaceBase
    {
    public:
      /** Parameters live in `subsection Adaptation`. */
      static constexpr const char *registry_section = "Adaptation";
      /** The selection entry: `set Optimiser = ...`. */
      static constexpr const char *registry_entry = "Optimiser";
      /** Default selection: "none". */
      static const char *
      default_plugin();
      /** Help text of the selection entry. */
      static std::string
      selection_documentation();
      /**
       * Shared entries: Mesh genes, Population size, Generations, Seed,
       * Stall generations, Minimum block size.
       */
      static void
      declare_common_parameters(dealii::ParameterHandler &prm);

      /** Read the shared entries. */
      void
      parse_common_parameters(dealii::ParameterHandler &prm) override;


      /** Whether this optimiser adapts at all (false for `none`). */
      virtual bool
      active() const;

      /**
       * Maximise the fitness over [0, 1]^n with n = x0.size(), from
       * populations that contain @p x0. @p progress is called after every
       * generation. Non-finite fitness values count as the worst. Every rank
       * of @p comm evolves @p fitness.size() islands (one per thread, `
       * Threads'), island t calling fitness[t] only (see run_pagmo()); the
       * result is the same on all ranks.
       */
      virtual Result
      optimise(const MPI_Comm                                 comm,
               const std::vector<Fitness>                    &fitness,
               const std::vector<double>                     &x0,
               const std::function<void(const Generation &)> &progress) = 0;

      /** Population size. */
      unsigned int population_size = 16;
      /** Largest number of generations. */
      unsigned int generations = 20;
      /** Seed of the random numbers. */
      unsigned int seed = 1;
      /** Stop after this many generations without improvement (0: never). */
      unsigned int stall_generations = 5;
      /** Islands (threads) per MPI rank. */
      unsigned int threads = 1;
      /** Whether interior vertices move too (`Mesh genes = vertices`). */
      bool vertex_genes = false;
      /** Smallest block size, as a fraction of the parameter range. */
      double minimum_block_size = 0.02;
      /** `Reuse evaluations`: fitness look-up of repeated gene vectors and
       * warm starts between evaluations. */
      bool reuse_evaluations = true;
    };
  } // namespace adaptation
} // namespace masonry

/** Register an optimiser (one line in the optimiser's .cc file). */
#define MASONRY_REGISTER_OPTIMISER(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::adaptation::Optimiser,        \
                          classname,                             \
                          name,                                  \
                          description)

#endif
