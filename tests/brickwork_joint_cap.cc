/**
 * `Maximum damage' of the bilinear joint: a joint opened and slid far past
 * its final separation (damage 1) keeps (1 - cap) of its penalties in
 * opening and shear, and the full normal penalty in contact; with the
 * default cap 1 it carries nothing in opening and shear. Closed forms:
 * t_n = (1 - cap) k_n delta_n, t_s = (1 - cap) k_s delta_s, tangent
 * diag((1 - cap) k); in contact t_n = k_n delta_n. The damage itself stays
 * 1. Implicit and IMPL-EX evaluations agree.
 */
#include <masonry/brickwork/interface_law.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <string>

#include "vault_tests.h"

using namespace dealii;
using namespace masonry::brickwork;

namespace
{
  std::unique_ptr<InterfaceLaw>
  law(const std::string &cap)
  {
    ParameterHandler prm;
    masonry::plugins::Registry<InterfaceLaw>::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Interface law\nset Law = bilinear\n"
      "set Normal stiffness = 2.5e11\nset Shear stiffness = 1e11\n"
      "subsection Bilinear\n" +
      (cap.empty() ? std::string() : "set Maximum damage = " + cap + "\n") +
      "end\nend\n");
    return masonry::plugins::Registry<InterfaceLaw>::create(prm);
  }

  /** Largest relative error of traction and tangent against the closed
   * form for residual fraction @p r, implicit and IMPL-EX. */
  double
  error(const InterfaceLaw &l, const double r, const Local3 &jump)
  {
    const double   k[3] = {2.5e11, 1e11, 1e11};
    InterfacePoint point;
    // the law's own state layout; its damage is the reported damage
    const unsigned int n =
      masonry::brickwork::n_state_values(l.state_variables());
    std::vector<double> old(n, 0.), updated(n, 0.), older(n, 0.), damage(1);
    Local3              t;
    Local33             D;
    double              e = 0;
    for (unsigned int pass = 0; pass < 2; ++pass)
      {
        if (pass == 0)
          l.evaluate(jump, old, point, updated, t, D);
        else
          {
            old = older = updated; // damage 1, no growth to extrapolate
            l.evaluate_extrapolated(jump, old, older, 1., point, t, D);
          }
        l.damages(updated, damage);
        if (pass == 0 && damage[0] != 1)
          return 1e300;
        for (unsigned int i = 0; i < 3; ++i)
          {
            const double f     = (i == 0 && jump[0] < 0) ? 1. : r;
            const double scale = k[i] * std::abs(jump[i]) + 1;
            e = std::max(e, std::abs(t[i] - f * k[i] * jump[i]) / scale);
            e = std::max(e, std::abs(D[i][i] - f * k[i]) / k[i]);
          }
      }
    return e;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // 1 mm opening and 2 mm slip: far past the final separation (0.15 mm)
  const Local3 open{{1e-3, 2e-3, -1e-3}}, closed{{-1e-5, 2e-3, 1e-3}};
  const auto   capped = law("0.9999"), plain = law("");
  vault_tests::check(error(*capped, 1e-4, open) < 1e-10 &&
                       error(*capped, 1e-4, closed) < 1e-10,
                     "cap 0.9999: debonded joint keeps 1e-4 of k in "
                     "opening and shear, full k_n in contact");
  vault_tests::check(error(*plain, 0, open) < 1e-10 &&
                       error(*plain, 0, closed) < 1e-10,
                     "default cap 1: nothing in opening and shear, full k_n "
                     "in contact");
}
