/**
 * @file
 * What an analysis gets from the driver.
 */
#ifndef masonry_core_run_context_h
#define masonry_core_run_context_h

#include <masonry/core/json.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

namespace masonry
{
  class OutputDirectory;

  /**
   * The environment of a run: communicator, screen output (rank 0, also
   * copied to log.txt), the output directory and the summary that becomes
   * summary.json. An analysis adds its results to @p summary with
   * snake_case keys in SI units and sets `status`.
   */
  struct RunContext
  {
    /** The communicator of the run. */
    MPI_Comm mpi_communicator;
    /** Screen output: printed by rank 0 and copied to log.txt. */
    dealii::ConditionalOStream &pcout;
    /** Where files go. */
    OutputDirectory &output;
    /** The contents of summary.json. */
    Json &summary;
  };
} // namespace masonry

#endif
