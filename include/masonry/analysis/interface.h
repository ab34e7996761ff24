/**
 * @file
 * Analyses: what a run does (`set Analysis = ...`).
 */
#ifndef masonry_analysis_interface_h
#define masonry_analysis_interface_h

#include <masonry/core/plugins.h>
#include <masonry/core/run_context.h>

namespace masonry
{
  /** What a run does. */
  namespace analysis
  {
    /**
     * Base class of analyses. The driver creates the analysis selected by
     * the top-level entry `Analysis`, lets it parse its own subsection
     * (`subsection <Name>`), then calls setup() with the whole parameter
     * handler (at top level) so that it can create the plugins of other
     * subsystems it needs, then run().
     */
    class Interface : public plugins::InterfaceBase
    {
    public:
      /** Top level: the selection entry is `set Analysis = ...`. */
      static constexpr const char *registry_section = "";
      /** The selection entry. */
      static constexpr const char *registry_entry = "Analysis";
      /** Default selection. */
      static const char *
      default_plugin();
      /** Help text of the selection entry. */
      static std::string
      selection_documentation();



      /**
       * Create and parse the plugins of other subsystems this analysis uses;
       * @p prm is at top level. Called by `--validate` too, so every input
       * error must be found here or in parse_parameters(), not in run().
       */
      virtual void
      setup(dealii::ParameterHandler &prm);

      /**
       * Check, before the driver writes anything into @p directory (the
       * run's output directory; it may not exist yet), that the run can
       * start there: e.g. that a checkpoint to resume from is readable by
       * this version. Throws a one-line error naming the entry; the files of
       * an earlier run in @p directory are then left as they are. Called by
       * every rank of @p comm. Default: nothing to check.
       */
      virtual void
      check_output_directory(const std::string &directory,
                             const MPI_Comm     comm) const;

      /**
       * Do the work: write files through @p context.output, add results to
       * @p context.summary and set its `status`.
       */
      virtual void
      run(RunContext &context) = 0;
    };
  } // namespace analysis
} // namespace masonry

/** Register an analysis (one line in the analysis' .cc file). */
#define MASONRY_REGISTER_ANALYSIS(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::analysis::Interface,         \
                          classname,                            \
                          name,                                 \
                          description)

#endif
