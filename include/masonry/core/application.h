/**
 * @file
 * The command-line driver of `masonry`, callable from tests.
 */
#ifndef masonry_core_application_h
#define masonry_core_application_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace masonry
{
  /**
   * Run masonry as the command line @p arguments (without the program name)
   * asks: `FILE.prm`, `--validate FILE.prm`, `--print-parameters[=json]`,
   * `--help`, `--version`. Errors are printed as one line on std::cerr by
   * rank 0. Returns the process exit code (0 on success).
   */
  int
  run_application(const std::vector<std::string> &arguments,
                  const MPI_Comm                  comm);

  /**
   * Declare every parameter of the driver and of every registered plugin.
   */
  void
  declare_all_parameters(dealii::ParameterHandler &prm);
} // namespace masonry

#endif
