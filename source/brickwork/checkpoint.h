/**
 * @file
 * Checkpoints of a wallette run: one file per rank (checkpoint.RANK in the
 * output directory) to which every part writes its own state (serialize()
 * of the protocol position, the curve, the counters, the deletions, the
 * point states, the solver, the step control and the postprocessors).
 */
#ifndef masonry_brickwork_model_checkpoint_h
#define masonry_brickwork_model_checkpoint_h

#include <masonry/brickwork/curve.h>
#include <masonry/brickwork/linear_solver.h>
#include <masonry/core/parameters.h>
#include <masonry/core/run_context.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

#include "assembly/point_states.h"
#include "assembly/system.h"
#include "solution/step_controller.h"
#include "specimen/specimen.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** Checkpoints (`Checkpoint interval', `Resume'). */
      struct CheckpointSettings
      {
        /** Write a checkpoint every this many converged steps (0: only when
         * the run stops early). */
        unsigned int checkpoint_interval = 0;
        /** Continue from the checkpoint in the output directory. */
        bool resume = false;
        /** The entries of the parameter file, each with its full path,
         * except those a resumed run may set otherwise (resume_may_change()):
         * a checkpoint holds those of its run, and a resume must repeat
         * them. */
        std::vector<std::pair<std::string, std::string>> inputs;

        /** Declare the entries in the present subsection. */
        static void
        declare_parameters(dealii::ParameterHandler &prm);
        /** Read them, and the whole file's entries into #inputs. */
        void
        parse_parameters(dealii::ParameterHandler &prm);

        /** Whether a resumed run may give the entry @p path another value
         * than the run that wrote the checkpoint: `Resume', `Maximum
         * steps', `Checkpoint interval', `Assembly threads' (it changes no
         * number) and `Output directory' (the same directory, spelled
         * otherwise). */
        static bool
        resume_may_change(const std::string &path);
      };

      /** Counters of the step loop. */
      struct RunStatistics
      {
        unsigned int total_newton = 0;
        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          ar &total_newton;
        }
      };

      /** The parts that go into a checkpoint. */
      struct CheckpointParts
      {
        StepController          &controller;
        std::vector<CurvePoint> &curve;
        RunStatistics           &statistics;
        Specimen                &specimen;
        /** The point states of every law. */
        LawStates    &states;
        LinearSolver &solver;
        System       &system;
        /** What each postprocessor saves, in their order. */
        std::vector<std::string> &postprocessors;
        /** The run's entries that a resume must repeat. */
        const std::vector<std::pair<std::string, std::string>> &inputs;
      };

      /** Before anything is written (`Resume = true'): this rank's
       * checkpoint in @p directory exists, has this version's layout, was
       * written by as many ranks and by a run whose entries were @p inputs
       * (CheckpointSettings::inputs); else every rank of @p comm throws the
       * same one-line error naming `Resume' (and the first entry that
       * differs). */
      void
      check_checkpoint(
        const std::string                                      &directory,
        const std::vector<std::pair<std::string, std::string>> &inputs,
        const MPI_Comm                                          comm);

      /** Write this rank's checkpoint (replaces the last one only once
       * complete). */
      void
      save_checkpoint(const CheckpointParts &parts,
                      const std::string     &status,
                      RunContext            &context);

      /** Read this rank's checkpoint; throws naming `Resume' if there is
       * none, it belongs to another run or it holds the data of another
       * number of postprocessors than @p n_postprocessors. */
      void
      load_checkpoint(CheckpointParts   &parts,
                      RunContext        &context,
                      const unsigned int n_postprocessors);

      /** The error of a checkpoint whose postprocessor data the run's
       * postprocessors cannot load (@p reason: why), naming `Resume'. */
      dealii::ExcMessage
      other_postprocessors(const std::string &reason);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
