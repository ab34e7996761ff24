/**
 * @file
 * The `masonry` executable: a thin wrapper around masonry::run_application().
 */
#include <masonry/core/application.h>

#include <deal.II/base/mpi.h>

#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  const std::vector<std::string>           arguments(argv + 1, argv + argc);
  return masonry::run_application(arguments, MPI_COMM_WORLD);
}
