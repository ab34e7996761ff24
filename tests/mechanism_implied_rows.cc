/**
 * Leaving out the contact rows that follow from the others
 * (`Implied contact rows = leave out', the default) must not change the
 * optimum: every case is solved twice, with every row (`keep', the
 * reference: the LP as written before the reduction) and with the reduced
 * LP, and the optima must agree to 1e-8 relative while the reduced LP has
 * fewer rows. Cases: no tension no sliding with two and three stations per
 * edge (an arch under a settlement, a barrel vault's limit load), and
 * bonded supports under Mohr-Coulomb joints (the rows of a bonded support
 * carry the support motion on their right-hand side).
 */
#include <deal.II/base/mpi.h>

#include "vault_tests.h"

using namespace vault_tests;

namespace
{
  std::string
  with_rows(const std::string &prm,
            const std::string &section,
            const std::string &rows)
  {
    return prm + "subsection " + section +
           "\n  set Implied contact rows = " + rows + "\nend\n";
  }

  void
  compare(const std::string &name,
          const std::string &prm,
          const std::string &section,
          const std::string &key)
  {
    const masonry::Json full =
      run(name + "_keep", with_rows(prm, section, "keep"));
    const masonry::Json lean =
      run(name + "_leave_out", with_rows(prm, section, "leave out"));
    const bool optimal = full.at("status").get<std::string>() == "optimal" &&
                         lean.at("status").get<std::string>() == "optimal";
    const double a         = optimal ? full.at(key).get<double>() : 0,
                 b         = optimal ? lean.at(key).get<double>() : 1;
    const double rows_full = full.at("lp_rows").get<double>(),
                 rows_lean = lean.at("lp_rows").get<double>();
    check(optimal && std::abs(a - b) <= 1e-8 * std::max(std::abs(a), 1e-6),
          name + ": same " + key + " with and without the implied rows");
    check(rows_lean < rows_full, name + ": fewer LP rows");
  }

  std::string
  limit_load(const std::string &geometry,
             const std::string &joints,
             const std::string &blocks,
             const std::string &supports,
             const std::string &acceleration,
             const std::string &contact = "unilateral")
  {
    return "set Analysis = limit load\nsubsection Geometry model\n" + geometry +
           "end\nsubsection Interface model\n" + joints +
           "end\nsubsection Limit load\n" + blocks +
           "  set Supported edges = " + supports +
           "\n  set Live acceleration = " + acceleration +
           "\n  set Support contact = " + contact +
           "\n  set Write picture = false\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const std::string ntns   = "  set Model = no tension no sliding\n";
  const std::string mc     = "  set Model = mohr coulomb\n"
                             "  subsection Mohr coulomb\n"
                             "    set Cohesion = 0.02e6\n"
                             "    set Friction coefficient = 0.5\n"
                             "    set Tensile strength = 0.03e6\n"
                             "    set Compressive strength = 2.6e6\n  end\n";
  const std::string barrel = "  set Model name = barrel vault\n"
                             "  set Thickness = 0.36\n  set Density = 520\n"
                             "  subsection Barrel vault\n"
                             "    set Shape = pointed\n    set Span = 6.1\n"
                             "    set Rise = 3.8\n    set Length = 16.8\n"
                             "  end\n";

  // arch, settlement of one springing: two and three stations per edge
  const std::string arch = arch_prm(5, 1, 8, "0; 0; -0.01");
  compare("arch_2_stations", arch, "Settlement", "objective");
  std::string arch3 = arch;
  arch3.replace(arch3.find("Stations per edge = 2"),
                21,
                "Stations per edge = 3");
  compare("arch_3_stations", arch3, "Settlement", "objective");

  // barrel vault, horizontal acceleration across the span
  compare("barrel_vault",
          limit_load(barrel,
                     ntns,
                     "  set Blocks along u = 3\n  set Blocks along v = 4\n"
                     "  set Stations per edge = 3\n",
                     "springing left, springing right",
                     "1; 0; 0"),
          "Limit load",
          "load_multiplier");

  // bonded supports under a settlement (support motion on the rows)
  std::string bonded = arch_prm(5, 1, 8, "0; 0; -0.01", "bonded");
  bonded.replace(bonded.find("subsection Settlement"),
                 21,
                 "subsection Interface model\n" + mc +
                   "end\nsubsection Settlement");
  compare("arch_bonded_mohr_coulomb", bonded, "Settlement", "objective");
  compare("barrel_vault_bonded_mohr_coulomb",
          limit_load(barrel,
                     mc,
                     "  set Blocks along u = 3\n  set Blocks along v = 4\n"
                     "  set Stations per edge = 3\n",
                     "springing left, springing right",
                     "1; 0; 0",
                     "bonded"),
          "Limit load",
          "load_multiplier");
}
