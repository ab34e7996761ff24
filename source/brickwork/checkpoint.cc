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

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
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
          "when the run stops early: no convergence or `Maximum steps'). "
          "With `Newton chord across steps = true' a checkpoint also lets "
          "the kept factorisation go (so that a resumed run repeats the "
          "uninterrupted one), so another interval moves the results by "
          "what `Newton tolerance' lets through, as another tolerance "
          "would.");
        prm.declare_entry(
          "Resume",
          "false",
          Bool(),
          "Continue from the checkpoint in the output directory (written "
          "by an earlier run of the same parameter file with the same "
          "number of MPI ranks) instead of starting from zero; the curve "
          "and results continue as if the run had not stopped. Only "
          "`Maximum steps', `Checkpoint interval', `Assembly threads' and "
          "`Output directory' may differ from the stopped run's file (a "
          "number may be written otherwise: 0.01 or 1e-2): a checkpoint "
          "that is missing, of another version or number of ranks, or of "
          "a run with another value of any other entry is refused with an "
          "error naming that entry, before anything is written.");
      }

      void
      CheckpointSettings::parse_parameters(ParameterHandler &prm)
      {
        checkpoint_interval = prm.get_integer("Checkpoint interval");
        resume              = prm.get_bool("Resume");
        inputs.clear();
        for (auto &entry : parameter_values(prm))
          if (!resume_may_change(entry.first))
            inputs.push_back(std::move(entry));
      }

      bool
      CheckpointSettings::resume_may_change(const std::string &path)
      {
        for (const char *entry : {"Output directory",
                                  "Wallette/Resume",
                                  "Wallette/Maximum steps",
                                  "Wallette/Checkpoint interval",
                                  "Wallette/Assembly threads"})
          if (path == entry)
            return true;
        return false;
      }

      namespace
      {
        /** The first entry of a checkpoint: the layout of what follows
         * (the run's entries in the header; one state array per law of the
         * law set), so that a checkpoint of another layout is told apart
         * before its parts are read (one written before the law set had
         * the number of ranks there, a small number; one written before
         * the entries were in the header had 0x4d575632u). */
        constexpr unsigned int checkpoint_format = 0x4d575633u;

        /** What a checkpoint holds before the parts: who wrote it. */
        struct Header
        {
          unsigned int                                     format  = 0;
          unsigned int                                     n_ranks = 0;
          types::global_dof_index                          n_dofs  = 0;
          std::vector<std::pair<std::string, std::string>> inputs;
        };

        /** Every part in one order, for writing and reading. */
        template <class Archive>
        void
        serialize_parts(Archive &ar, const CheckpointParts &parts)
        {
          ar &parts.controller &parts.curve &parts.statistics &parts.specimen;
          ar                                                  &parts.states;
          ar &parts.solver &parts.postprocessors;
        }

        /** The checkpoint of rank @p rank in @p directory. */
        std::string
        file_name(const std::string &directory, const unsigned int rank)
        {
          return directory +
                 (directory.empty() || directory.back() == '/' ? "" : "/") +
                 "checkpoint." + std::to_string(rank);
        }

        std::string
        file_name(RunContext &context)
        {
          return file_name(context.output.path(),
                           Utilities::MPI::this_mpi_process(
                             context.mpi_communicator));
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

        /** The error of checkpoint @p name that cannot be read (@p why). */
        dealii::ExcMessage
        unreadable(const std::string &name, const std::string &why)
        {
          return ExcParameter("Resume",
                              "the checkpoint " + name + " cannot be read (" +
                                why + ")");
        }

        /** Read the header of checkpoint @p name from @p ar: after the
         * format tag, which must be this version's, the rest. */
        Header
        read_header(boost::archive::binary_iarchive &ar,
                    const std::string               &name)
        {
          Header h;
          ar    &h.format;
          AssertThrow(h.format == checkpoint_format,
                      ExcParameter("Resume",
                                   "the checkpoint " + name +
                                     " was written by another version of "
                                     "masonry (another layout); run from "
                                     "the start"));
          ar &h.n_ranks &h.n_dofs &h.inputs;
          return h;
        }

        /** Whether two values of an entry say the same: equal text, or the
         * same comma-separated items, each equal as text (blanks around it
         * aside) or as a number ("0.01" and "1e-2"). */
        bool
        same_value(const std::string &a, const std::string &b)
        {
          if (a == b)
            return true;
          const auto items_a = Utilities::split_string_list(a, ','),
                     items_b = Utilities::split_string_list(b, ',');
          if (items_a.size() != items_b.size())
            return false;
          const auto number = [](const std::string &text, double &x) {
            char *end = nullptr;
            x         = std::strtod(text.c_str(), &end);
            return !text.empty() && end == text.c_str() + text.size();
          };
          for (std::size_t i = 0; i < items_a.size(); ++i)
            {
              double x = 0, y = 0;
              if (items_a[i] != items_b[i] &&
                  !(number(items_a[i], x) && number(items_b[i], y) && x == y))
                return false;
            }
          return true;
        }

        /** The first entry of @p then (the checkpoint's) to which @p now
         * gives another value, for the error: "`PATH' was `A' in that run,
         * `B' here", and how many more differ; "" if none. */
        std::string
        first_difference(
          const std::vector<std::pair<std::string, std::string>> &then,
          const std::vector<std::pair<std::string, std::string>> &now)
        {
          const auto quoted = [](const std::string &value) {
            return "`" + value + "'";
          };
          std::map<std::string, std::string> values(now.begin(), now.end());
          std::string                        first;
          unsigned int                       n = 0;
          for (const auto &[path, value] : then)
            {
              const auto it    = values.find(path);
              const bool found = it != values.end();
              if (found && !same_value(it->second, value) && n++ == 0)
                first = quoted(path) + " was " + quoted(value) +
                        " in that run, " + quoted(it->second) + " here";
              else if (!found && n++ == 0)
                first = quoted(path) + " was " + quoted(value) +
                        " in that run, not an entry here";
              if (found)
                values.erase(it);
            }
          // entries of this run that the checkpoint's run did not have (a
          // plugin library of its own)
          for (const auto &[path, value] : values)
            if (n++ == 0)
              first = quoted(path) + " is " + quoted(value) +
                      " here, not an entry of that run";
          if (n > 1)
            first += " (and " + std::to_string(n - 1) + " more)";
          return first;
        }
      } // namespace

      void
      check_checkpoint(
        const std::string                                      &directory,
        const std::vector<std::pair<std::string, std::string>> &inputs,
        const MPI_Comm                                          comm)
      {
        // `masonry --validate' checks without starting MPI: one rank
        const bool         mpi = Utilities::MPI::job_supports_mpi();
        const unsigned int rank =
                             mpi ? Utilities::MPI::this_mpi_process(comm) : 0,
                           n_ranks_now =
                             mpi ? Utilities::MPI::n_mpi_processes(comm) : 1;
        const std::string name = file_name(directory, rank);
        std::string       error;
        try
          {
            std::ifstream in(name, std::ios::binary);
            AssertThrow(in, no_checkpoint(name));
            Header header;
            try
              {
                boost::archive::binary_iarchive ar(in);
                header = read_header(ar, name);
              }
            catch (const boost::archive::archive_exception &e)
              {
                AssertThrow(false, unreadable(name, e.what()));
              }
            catch (const std::bad_alloc &)
              {
                AssertThrow(false, unreadable(name, "damaged"));
              }
            AssertThrow(header.n_ranks == n_ranks_now,
                        ExcParameter("Resume",
                                     "the checkpoint was written by a run "
                                     "with " +
                                       std::to_string(header.n_ranks) +
                                       " ranks; resume with as many"));
            const std::string difference =
              first_difference(header.inputs, inputs);
            AssertThrow(difference.empty(),
                        ExcParameter("Resume",
                                     "the checkpoint was written by a run "
                                     "with other parameters: " +
                                       difference +
                                       "; resume with the stopped run's "
                                       "file (only `Maximum steps', "
                                       "`Checkpoint interval', `Assembly "
                                       "threads' and `Output directory' "
                                       "may change)"));
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
              Header                          header;
              header.format  = checkpoint_format;
              header.n_ranks = Utilities::MPI::n_mpi_processes(comm);
              header.n_dofs  = parts.system.dof_handler.n_dofs();
              header.inputs  = parts.inputs;
              ar &header.format &header.n_ranks &header.n_dofs &header.inputs;
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
            // check_checkpoint() has compared the header before anything
            // was written; these are what the parts below rely on
            const Header header = read_header(ar, name);
            AssertThrow(header.n_ranks ==
                            Utilities::MPI::n_mpi_processes(comm) &&
                          header.n_dofs == parts.system.dof_handler.n_dofs(),
                        ExcParameter("Resume",
                                     "the checkpoint was written by a run "
                                     "with " +
                                       std::to_string(header.n_ranks) +
                                       " ranks and " +
                                       std::to_string(header.n_dofs) +
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
            AssertThrow(false, unreadable(name, e.what()));
          }
        catch (const std::bad_alloc &)
          {
            // a size read from a damaged file
            AssertThrow(false, unreadable(name, "damaged"));
          }
        parts.system.orphans = orphan_dofs(parts.system, parts.specimen);
        parts.system.make_constraints();
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
