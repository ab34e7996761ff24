/**
 * A circular barrel vault under a uniform vertical settlement of one
 * springing along its whole length behaves like the arch of the same cross
 * section: the work per unit length equals the arch's work per unit depth
 * (the gables are free, every cross-section moves alike). Blocks: 8 per
 * half across the span, 3 along the length.
 */
#include <deal.II/base/mpi.h>

#include "vault_tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  using namespace vault_tests;
  const double R = 3, t = 0.5, L = 4;
  const double arch = run("arch", arch_prm(R, t, 8, "0; 0; -0.01"))
                        .at("external_work")
                        .get<double>();
  std::ostringstream prm;
  prm << "set Analysis = settlement\n"
      << "subsection Geometry model\n  set Model name = barrel vault\n"
      << "  set Thickness = " << t << "\n  set Density = 2000\n"
      << "  subsection Barrel vault\n    set Shape = circular\n    set Span = "
      << 2 * R << "\n    set Rise = " << R << "\n    set Length = " << L
      << "\n  end\nend\n"
      << "subsection Settlement\n  set Blocks along u = 8\n"
      << "  set Blocks along v = 3\n  set Stations per edge = 2\n"
      << "  set Supported edges = springing left, springing right\n"
      << "  set Settling edges = springing right\n"
      << "  set Settlement = 0; 0; -0.01\n  set Write picture = false\nend\n";
  const masonry::Json barrel = run("barrel", prm.str());
  check(barrel.at("status").get<std::string>() == "optimal",
        "barrel vault: optimal");
  check(relative(barrel.at("external_work").get<double>() / L, arch) < 1e-8,
        "barrel work per unit length = arch work per unit depth (1e-8)");
}
