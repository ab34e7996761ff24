/**
 * @file
 * Checkpoint files.
 */
#include <masonry/core/output_directory.h>
#include <masonry/core/output_file.h>
#include <masonry/core/parameters.h>

#include "checkpoint.h"
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <filesystem>
#include <fstream>
#include <new>

#include "solution/deletion.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using namespace dealii;

      void
      CheckpointSettings::declare_parameters(ParameterHandler &prm)
      {
        using Patterns::Bool;
        using Patterns::Integer;
        prm.declare_entry(
          "Checkpoint interval",
          "0",
          Integer(0),
          "Write the state (displacements, brick and joint histories, "
          "deleted cells, protocol position, curve) to checkpoint.RANK in "
          "the output directory every this many converged steps (0: only "
          "when the run stops early: no convergence or `Maximum steps').");
        prm.declare_entry(
          "Resume",
          "false",
          Bool(),
          "Continue from the checkpoint in the output directory (written "
          "by an earlier run of the same parameter file with the same "
          "number of MPI ranks) instead of starting from zero; the curve "
          "and results continue as if the run had not stopped.");
      }

      void
      CheckpointSettings::parse_parameters(ParameterHandler &prm)
      {
        checkpoint_interval = prm.get_integer("Checkpoint interval");
        resume              = prm.get_bool("Resume");
      }

      namespace
      {
        /** The first entry of a checkpoint: the layout of what follows
         * (one state array per law of the law set), so that a checkpoint
         * of another layout is told apart before its parts are read (one
         * written before had the number of ranks there, a small number). */
        constexpr unsigned int checkpoint_format = 0x4d575632u;

        /** Every part in one order, for writing and reading. */
        template <class Archive>
        void
        serialize_parts(Archive &ar, const CheckpointParts &parts)
        {
          ar &parts.controller &parts.curve &parts.statistics &parts.specimen;
          ar                                                  &parts.states;
          ar &parts.solver &parts.postprocessors;
        }

        std::string
        file_name(RunContext &context)
        {
          return context.output.path() + "checkpoint." +
                 std::to_string(
                   Utilities::MPI::this_mpi_process(context.mpi_communicator));
        }

        /** The error of a missing checkpoint @p name. */
        dealii::ExcMessage
        no_checkpoint(const std::string &name)
        {
          return ExcParameter("Resume",
                              "no checkpoint " + name +
                                " (run with `Checkpoint interval' or "
                                "`Maximum steps' first, with the same "
                                "output directory and number of ranks)");
        }

        /** Checkpoint @p name starts with this version's format tag. */
        void
        check_format(const unsigned int format, const std::string &name)
        {
          AssertThrow(format == checkpoint_format,
                      ExcParameter("Resume",
                                   "the checkpoint " + name +
                                     " was written by another version of "
                                     "masonry (another layout); run from "
                                     "the start"));
        }
      } // namespace

      void
      check_checkpoint(const std::string &directory, const MPI_Comm comm)
      {
        // `masonry --validate' checks without starting MPI: one rank
        const bool         mpi = Utilities::MPI::job_supports_mpi();
        const unsigned int rank =
                             mpi ? Utilities::MPI::this_mpi_process(comm) : 0,
                           n_ranks_now =
                             mpi ? Utilities::MPI::n_mpi_processes(comm) : 1;
        const std::string name = directory +
                                 (directory.back() == '/' ? "" : "/") +
                                 "checkpoint." + std::to_string(rank);
        std::string error;
        try
          {
            std::ifstream in(name, std::ios::binary);
            AssertThrow(in, no_checkpoint(name));
            try
              {
                boost::archive::binary_iarchive ar(in);
                unsigned int                    format = 0, n_ranks = 0;
                ar                             &format;
                check_format(format, name);
                ar &n_ranks;
                AssertThrow(n_ranks == n_ranks_now,
                            ExcParameter("Resume",
                                         "the checkpoint was written by a "
                                         "run with " +
                                           std::to_string(n_ranks) +
                                           " ranks; resume with as many"));
              }
            catch (const boost::archive::archive_exception &e)
              {
                AssertThrow(false,
                            ExcParameter("Resume",
                                         "the checkpoint " + name +
                                           " cannot be read (" + e.what() +
                                           ")"));
              }
          }
        catch (const std::exception &exc)
          {
            error = one_line_message(exc);
          }
        if (mpi)
          throw_if_any_rank_failed(error, comm);
        else
          AssertThrow(error.empty(), dealii::ExcMessage(error));
      }

      void
      save_checkpoint(const CheckpointParts &parts,
                      const std::string     &status,
                      RunContext            &context)
      {
        const MPI_Comm    comm = context.mpi_communicator;
        const std::string name = file_name(context);
        // written under a temporary name and renamed when whole: a run
        // killed while writing keeps its previous checkpoint; a rank that
        // cannot write stops every rank
        std::string error;
        try
          {
            OutputFile out(name);
            {
              boost::archive::binary_oarchive ar(out);
              unsigned int                    format = checkpoint_format;
              ar                             &format;
              unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
              types::global_dof_index n_dofs =
                parts.system.dof_handler.n_dofs();
              ar &n_ranks &n_dofs;
              serialize_parts(ar, parts);
              std::vector<std::pair<types::global_dof_index, double>> values;
              std::vector<double> increments;
              for (const auto i : parts.system.owned)
                {
                  values.emplace_back(i, parts.system.u[i]);
                  increments.push_back(parts.system.last_increment[i]);
                }
              std::string             s = status;
              ar &values &increments &s;
            }
            out.close();
          }
        catch (const std::exception &exc)
          {
            error = one_line_message(exc);
          }
        throw_if_any_rank_failed(error, comm);
        context.output.file(
          "checkpoint." +
          std::to_string(Utilities::MPI::this_mpi_process(comm)));
      }

      dealii::ExcMessage
      other_postprocessors(const std::string &reason)
      {
        return ExcParameter("Resume",
                            "the checkpoint was written by a run with "
                            "another `List of postprocessors' (subsection "
                            "Postprocess/Wallette); resume with the same "
                            "list, in the same order" +
                              (reason.empty() ? "" : " (" + reason + ")"));
      }

      void
      load_checkpoint(CheckpointParts   &parts,
                      RunContext        &context,
                      const unsigned int n_postprocessors)
      {
        const MPI_Comm    comm = context.mpi_communicator;
        const std::string name = file_name(context);
        std::ifstream     in(name, std::ios::binary);
        AssertThrow(in, no_checkpoint(name));
        try
          {
            boost::archive::binary_iarchive ar(in);
            unsigned int                    format = 0;
            ar                             &format;
            check_format(format, name);
            unsigned int            n_ranks;
            types::global_dof_index n_dofs;
            ar &n_ranks            &n_dofs;
            AssertThrow(n_ranks == Utilities::MPI::n_mpi_processes(comm) &&
                          n_dofs == parts.system.dof_handler.n_dofs(),
                        ExcParameter("Resume",
                                     "the checkpoint was written by a run "
                                     "with " +
                                       std::to_string(n_ranks) + " ranks and " +
                                       std::to_string(n_dofs) +
                                       " DOFs; resume with the same "
                                       "parameters and number of ranks"));
            serialize_parts(ar, parts);
            AssertThrow(parts.postprocessors.size() == n_postprocessors,
                        other_postprocessors(""));
            std::vector<std::pair<types::global_dof_index, double>> values;
            std::vector<double>                                     increments;
            std::string                                             status;
            ar &values &increments                                 &status;
            AssertThrow(increments.size() == values.size(),
                        ExcParameter("Resume",
                                     "the checkpoint " + name +
                                       " is damaged (sizes differ)"));
            for (unsigned int k = 0; k < values.size(); ++k)
              {
                parts.system.u[values[k].first]              = values[k].second;
                parts.system.last_increment[values[k].first] = increments[k];
              }
            parts.system.u.compress(VectorOperation::insert);
            parts.system.last_increment.compress(VectorOperation::insert);
          }
        catch (const boost::archive::archive_exception &e)
          {
            AssertThrow(false,
                        ExcParameter("Resume",
                                     "the checkpoint " + name +
                                       " cannot be read (" + e.what() + ")"));
          }
        catch (const std::bad_alloc &)
          {
            // a size read from a damaged file
            AssertThrow(false,
                        ExcParameter("Resume",
                                     "the checkpoint " + name +
                                       " cannot be read (damaged)"));
          }
        parts.system.orphans = orphan_dofs(parts.system, parts.specimen);
        parts.system.make_constraints();
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
