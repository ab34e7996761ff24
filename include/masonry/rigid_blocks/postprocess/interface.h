/**
 * @file
 * Postprocessors of the rigid-block analyses (`settlement`, `limit load`,
 * `minimum thickness`): each output (a CSV table, a VTU file, a picture,
 * summary entries) is one plugin, selected by
 *
 * @code
 * subsection Postprocess
 *   subsection Rigid blocks
 *     set List of postprocessors = cracks, blocks vtu, ...
 *   end
 * end
 * @endcode
 *
 * in the manner of ASPECT's `List of postprocessors`. The default list is
 * every output masonry writes. A postprocessor gets a read-only view of the
 * result (Result: blocks, interfaces, motion, support motion, contact
 * forces) and the RunContext, through which it writes files
 * (`context.output.file(name)`), summary entries and screen lines. A new
 * output is one `.cc` file (in `source/rigid_blocks/postprocess/` or a
 * shared library loaded by `Additional shared libraries`):
 *
 * @code
 * class MyOutput : public masonry::rigid_blocks::postprocess::Interface
 * {
 * public:
 *   static void declare_parameters(dealii::ParameterHandler &) {}
 *   void execute(const Result &result, masonry::RunContext &context) override
 *   {
 *     if (!result.is_root()) return;
 *     // written under a temporary name, renamed by close() when whole
 *     masonry::OutputFile out(context.output.file("my_output.csv"));
 *     ...
 *     out.close(); // throws "cannot write '...': No space left on device"
 *   }
 * };
 * MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(MyOutput, "my output", "...")
 * @endcode
 *
 * Inside such a class `Interface` names the postprocessor base class; the
 * joints between blocks are `masonry::rigid_blocks::Interface`
 * (contrib/examples/postprocessor/ is a complete out-of-tree example).
 */
#ifndef masonry_rigid_blocks_postprocess_interface_h
#define masonry_rigid_blocks_postprocess_interface_h

#include <masonry/core/plugins.h>
#include <masonry/core/run_context.h>
#include <masonry/core/scripts.h>
#include <masonry/rigid_blocks/block_model.h>
#include <masonry/rigid_blocks/output.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace masonry
{
  namespace rigid_blocks
  {
    /** The outputs of the rigid-block analyses. */
    namespace postprocess
    {
      /**
       * A read-only view of the result of a rigid-block analysis, given to
       * every postprocessor. It holds references to the analysis' data (valid
       * while the postprocessors run) and the few derived quantities that
       * several outputs share: the interface openings, the round-off
       * tolerance of the jumps and the displacement amplification.
       */
      class Result
      {
      public:
        /**
         * @p forces: per contact point (in the order of the interfaces and
         * their points) the normal, across and along forces (N, compression
         * positive), possibly fewer than contact points (the rest are
         * zero). @p supports_move: the analysis prescribes a support motion
         * (settlement); otherwise the supports are fixed and @p
         * support_motion is zero.
         */
        Result(const BlockModel                         &model,
               const Motion                             &motion,
               const SupportMotion                      &support_motion,
               const std::vector<std::array<double, 3>> &forces,
               const OutputOptions                      &options,
               const bool                                supports_move,
               const MPI_Comm                            mpi_communicator,
               const bool                                has_solution = true);

        /**
         * Whether the LP had an optimum. Without one (status `mechanism',
         * `incompatible', ...) the blocks are at rest, there are no
         * contact forces, and only the postprocessors that
         * writes_without_solution() run.
         */
        bool
        has_solution() const
        {
          return solution;
        }

        /** The blocks and interfaces. */
        const BlockModel &
        model() const
        {
          return block_model;
        }

        /** The rigid motion of every block (m, rad). */
        const Motion &
        motion() const
        {
          return block_motion;
        }

        /** The motion of the ground at a support point with @p label, m. */
        dealii::Tensor<1, 3>
        support_motion(const dealii::Point<3> &x,
                       const std::string      &label) const
        {
          return ground(x, label);
        }

        /** Whether the supports move (settlement) or are fixed. */
        bool
        supports_move() const
        {
          return moving_supports;
        }

        /**
         * The jump of the motion (second side minus first, m) at contact
         * point @p c of interface @p i; a support's side moves with the
         * ground.
         */
        dealii::Tensor<1, 3>
        jump(const rigid_blocks::Interface &i, const ContactPoint &c) const;

        /** Forces at contact point @p p (numbered over all interfaces), N. */
        std::array<double, 3>
        force(const unsigned int p) const
        {
          return p < contact_forces.size() ? contact_forces[p] :
                                             std::array<double, 3>{{0, 0, 0}};
        }

        /** The number of contact points with a force. */
        unsigned int
        n_forces() const
        {
          return contact_forces.size();
        }

        /** Largest block displacement at a contact point, m. */
        double
        max_displacement() const
        {
          return largest_displacement;
        }

        /** Largest prescribed support motion at a contact point, m. */
        double
        max_support_motion() const
        {
          return largest_support_motion;
        }

        /**
         * Jumps at or below this length (m) are not cracks: 1e-4 of the
         * larger of max_displacement() and max_support_motion(). A vertex of
         * the LP has round-off of about 1e-12 there; an interior point
         * (`Crossover = never`) up to 1.8e-6 (an arch of 400 blocks with no
         * tension no sliding joints, whose hinges open 0.065 to 0.14 of the
         * settlement; tests/lp_no_tension_interior).
         */
        double
        tolerance() const
        {
          return 1e-4 * std::max(largest_displacement, largest_support_motion);
        }

        /** Per interface the largest normal opening of its points, m. */
        const std::vector<double> &
        interface_opening() const
        {
          return opening;
        }

        /**
         * The factor on displacements in the deformed outputs: `Displacement
         * amplification`, or if that is 0 the factor that makes the larger
         * of max_displacement() and max_support_motion() 5 % of the vault's
         * size.
         */
        double
        amplification() const
        {
          return displacement_amplification;
        }

        /**
         * The horizontal direction (unit, or zero) from the vault's centre
         * towards what moves most: the settling supports (weighted by
         * their motion), or without support motion the blocks (weighted by
         * their translation). The pictures look from there, so that the
         * settled side is in view.
         */
        dealii::Tensor<1, 2>
        view_direction() const;

        /** The output entries of the analysis (subdivisions, picture). */
        const OutputOptions &
        options() const
        {
          return output_options;
        }

        /** The communicator of the run. */
        MPI_Comm
        communicator() const
        {
          return mpi_communicator;
        }

        /** Whether this is rank 0, the one that writes files. */
        bool
        is_root() const
        {
          return root;
        }

        /**
         * Queue a picture (rank 0): @p job runs after every postprocessor
         * has run, in one Python process with the other queued pictures
         * (run_scripts(): Python starts and imports matplotlib once per
         * run), and @p done is then called with "" or the one-line reason
         * why the picture was not written. A job with an output writes it
         * under a temporary name, renamed when complete.
         */
        void
        render(const ScriptJob                            &job,
               std::function<void(const std::string &why)> done) const;

        /**
         * Run the queued pictures and call their `done`; the analysis
         * calls it once after the postprocessors. Returns the seconds it
         * took (0 without pictures).
         */
        double
        render_pictures() const;

      private:
        const BlockModel                         &block_model;
        const Motion                             &block_motion;
        const SupportMotion                      &ground;
        const std::vector<std::array<double, 3>> &contact_forces;
        const OutputOptions                      &output_options;
        const bool                                moving_supports;
        const MPI_Comm                            mpi_communicator;
        const bool                                root;
        const bool                                solution;
        double                                    largest_displacement   = 0;
        double                                    largest_support_motion = 0;
        std::vector<double>                       opening;
        double displacement_amplification = 1;
        /** The queued pictures (render()). */
        mutable std::vector<
          std::pair<ScriptJob, std::function<void(const std::string &)>>>
          pictures;
      };

      /**
       * Base class of the postprocessors of the rigid-block analyses. The
       * analysis creates the listed ones when it is set up (so
       * `--validate` checks their parameters) and calls execute() of each,
       * in the order of the list and after the ones it requires, on every
       * MPI rank once the LP has an optimum (and, for those that
       * writes_without_solution(), when it has none).
       */
      class Interface : public plugins::InterfaceBase
      {
      public:
        /** Where the list and the postprocessors' subsections live. */
        static constexpr const char *registry_section =
          "Postprocess/Rigid blocks";
        /** The selection entry: a list. */
        static constexpr const char *registry_entry = "List of postprocessors";
        /** Any number of postprocessors run at once. */
        static constexpr bool multiple_selection = true;
        /** The default list: every output. */
        static const char *
        default_plugin();
        /** Help text of the list. */
        static std::string
        selection_documentation();



        /**
         * Postprocessors that must run before this one (their files are
         * read or referenced by this one); they are run even if not listed.
         */
        virtual std::vector<std::string>
        required_plugins() const;

        /**
         * Whether this output has something to say about a run without an
         * optimum (Result::has_solution() false): the status and
         * explanation of the summary on the blocks at rest. Default:
         * false (the output is not written then).
         */
        virtual bool
        writes_without_solution() const;

        /**
         * Write this output: files through @p context.output (normally on
         * rank 0 only: Result::is_root()), summary entries into
         * @p context.summary, screen lines through @p context.pcout.
         */
        virtual void
        execute(const Result &result, RunContext &context) = 0;
      };
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry

/** Register a postprocessor of the rigid-block analyses (one line). */
#define MASONRY_REGISTER_RIGID_BLOCK_POSTPROCESSOR(classname,            \
                                                   name,                 \
                                                   description)          \
  MASONRY_REGISTER_PLUGIN(masonry::rigid_blocks::postprocess::Interface, \
                          classname,                                     \
                          name,                                          \
                          description)

#endif
