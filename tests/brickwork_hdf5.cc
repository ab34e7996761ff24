/**
 * `Output format = hdf5` on two MPI ranks: an elastic stack-bonded prism
 * compressed in two steps writes solution.xdmf with the three output steps
 * (times = the strains 0, 5e-4, 1e-3) and one HDF5 file per step; the last
 * file, read back with deal.II's HDF5 wrapper, holds the prescribed platen
 * displacement −ε H at every node of the top face and zero at the bottom
 * (1e-7 of the platen displacement: DataOut stores its patches, and so the
 * HDF5 fields, in single precision, as in the VTU files). The joints follow:
 * interfaces.xdmf lists the three steps, and in interfaces_0002.h5 the bed
 * faces' mean normal opening times the joint's normal stiffness (2.5e11 Pa/m,
 * the elastic law's default) is the applied stress: the bed joint is the
 * only path of the platen force F, its traction is k_n times the opening,
 * and over a face of equal faces the opening at the centre is the mean of
 * the bilinear opening, so k_n mean(opening) = -F / A (1e-6: the Newton
 * tolerance).
 */
#include <deal.II/base/hdf5.h>

#include <fstream>
#include <regex>

#include "brickwork_tests.h"

using namespace brickwork_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const double       strain = 1e-3, H = 3 * (0.065 + 0.010);
  std::ostringstream w;
  w << "set Courses = 3\nset Length in bricks = 1\n"
    << "set Target strain = " << strain << "\nset Number of steps = 2\n"
    << "set Write VTU = true\nset Output format = hdf5\n"
    << "set Output interval = 1\n";
  const masonry::Json s =
    run("hdf5",
        prm(w.str(),
            "subsection Bond\nset Pattern = stack\nend\n"
            "subsection Interface law\nset Law = elastic\nend\n"),
        MPI_COMM_WORLD);
  if (rank != 0)
    return 0;
  check(s.at("status").get<std::string>() == "completed", "the run completes");

  std::ifstream     in("results/hdf5/solution.xdmf");
  std::stringstream text;
  text << in.rdbuf();
  const std::string   xdmf = text.str();
  std::vector<double> times;
  const std::regex    time("<Time Value=\"([^\"]+)\"");
  for (auto m = std::sregex_iterator(xdmf.begin(), xdmf.end(), time);
       m != std::sregex_iterator();
       ++m)
    times.push_back(std::stod((*m)[1]));
  check(times.size() == 3 && std::abs(times[0]) < 1e-15 &&
          relative(times[1], strain / 2) < 1e-12 &&
          relative(times[2], strain) < 1e-12,
        "solution.xdmf lists three steps at the strains 0, 5e-4, 1e-3");
  check(xdmf.find("solution_0002.h5:/displacement") != std::string::npos,
        "the last step's displacement is in solution_0002.h5");

  dealii::HDF5::File file("results/hdf5/solution_0002.h5",
                          dealii::HDF5::File::FileAccessMode::open);
  const auto         nodes =
    file.open_dataset("nodes").read<dealii::FullMatrix<double>>();
  const auto u =
    file.open_dataset("displacement").read<dealii::FullMatrix<double>>();
  {
    std::ifstream     joints_in("results/hdf5/interfaces.xdmf");
    std::stringstream joints_text;
    joints_text << joints_in.rdbuf();
    const std::string joints  = joints_text.str();
    unsigned int      n_steps = 0;
    for (auto m = std::sregex_iterator(joints.begin(), joints.end(), time);
         m != std::sregex_iterator();
         ++m)
      ++n_steps;
    check(n_steps == 3 && joints.find("interfaces_0002.h5:/normal_opening") !=
                            std::string::npos,
          "interfaces.xdmf lists three steps, the last in interfaces_0002.h5");
    dealii::HDF5::File joint_file("results/hdf5/interfaces_0002.h5",
                                  dealii::HDF5::File::FileAccessMode::open);
    const auto         opening =
      joint_file.open_dataset("normal_opening").read<std::vector<double>>();
    const auto type = joint_file.open_dataset("joint_type_bed0_head1_collar2")
                        .read<std::vector<double>>();
    double       sum = 0;
    unsigned int n   = 0;
    for (unsigned int i = 0; i < opening.size(); ++i)
      if (type[i] == 0)
        {
          sum += opening[i];
          ++n;
        }
    const double stress = s.at("peak_stress").get<double>();
    check(n > 0 && n == type.size() &&
            relative(-2.5e11 * sum / n, stress) < 1e-6,
          "HDF5 joints: k_n x mean bed opening = -applied stress (1e-6)");
  }
  const double platen = -strain * H;
  unsigned int n_top = 0, n_bottom = 0;
  double       error = 0;
  for (unsigned int i = 0; i < nodes.m(); ++i)
    if (std::abs(nodes(i, 2) - H) < 1e-9)
      {
        ++n_top;
        error = std::max(error, std::abs(u(i, 2) - platen));
      }
    else if (std::abs(nodes(i, 2)) < 1e-9)
      {
        ++n_bottom;
        error = std::max(error, std::abs(u(i, 2)));
      }
  check(nodes.m() == u.m() && u.n() == 3 && n_top > 0 && n_bottom > 0 &&
          error < 1e-7 * std::abs(platen),
        "HDF5 displacement: -strain x height on the top face, 0 on the "
        "bottom (to single precision, 1e-7)");
}
