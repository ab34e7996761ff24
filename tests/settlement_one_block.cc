/**
 * One rigid block on two supports; one support settles vertically by δ.
 *
 * The block is a whole semicircular arch (mean radius R, thickness t, depth
 * D) made of ONE single NURBS patch (two rational quadratic quarter circles),
 * cut into one block. Its springings rest on horizontal supports at z = 0.
 * Theory: with no sliding on the supports and no interpenetration, the work
 * of gravity is largest when the block rotates about the inner edge of the
 * left springing (x_L = −R + t/2) while the outer edge of the right springing
 * (x_R = R + t/2) follows the support down by δ; the centroid (x = 0) then
 * drops by δ (0 − x_L)/(x_R − x_L) = δ (R − t/2)/(2R), so
 *   work = W δ (R − t/2) / (2R),   W = ρ g π R t D
 * (W δ / 2 in the limit of point supports). With bonded supports the left
 * springing fixes the block completely and the right one asks it to move:
 * the LP is infeasible: `incompatible`.
 */
#include <masonry/geometry/interface.h>
#include <masonry/geometry/patch_occt.h>

#include <deal.II/base/mpi.h>

#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "vault_tests.h"

namespace
{
  /** A semicircle x² + z² = R² (y from 0 to D) as one patch (test only). */
  class SinglePatchArch : public masonry::geometry::Interface
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Radius", "2", dealii::Patterns::Double(0), "m");
      prm.declare_entry("Depth", "0.5", dealii::Patterns::Double(0), "m");
    }

    void
    parse_parameters(dealii::ParameterHandler &prm) override
    {
      const double R = prm.get_double("Radius"), D = prm.get_double("Depth");
      TColgp_Array2OfPnt   poles(1, 5, 1, 2);
      TColStd_Array2OfReal weights(1, 5, 1, 2);
      const double         x[5] = {-R, -R, 0, R, R}, z[5] = {0, R, R, R, 0};
      const double         w[5] = {1, std::sqrt(0.5), 1, std::sqrt(0.5), 1};
      for (int i = 1; i <= 5; ++i)
        for (int j = 1; j <= 2; ++j)
          {
            poles(i, j)   = gp_Pnt(x[i - 1], j == 1 ? 0 : D, z[i - 1]);
            weights(i, j) = w[i - 1];
          }
      TColStd_Array1OfReal    uknots(1, 3), vknots(1, 2);
      TColStd_Array1OfInteger umults(1, 3), vmults(1, 2);
      uknots(1) = 0;
      uknots(2) = 0.5;
      uknots(3) = 1;
      umults(1) = umults(3) = 3;
      umults(2)             = 2;
      vknots(1)             = 0;
      vknots(2)             = 1;
      vmults(1) = vmults(2)               = 2;
      Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(
        poles, weights, uknots, vknots, umults, vmults, 2, 1);
      set_patches({masonry::geometry::make_patch(
        surface,
        "arch",
        {"springing left", "springing right", "face front", "face back"})});
    }
  };
} // namespace

MASONRY_REGISTER_GEOMETRY_MODEL(SinglePatchArch,
                                "test arch",
                                "A semicircle as one patch (test).")

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double R = 2, D = 0.5, t = 0.3, rho = 1800, g = 9.81, delta = 0.01;
  const double W        = rho * g * M_PI * R * t * D;
  const double expected = W * delta * (R - t / 2) / (2 * R);
  auto         prm      = [&](const std::string &contact,
                 const std::string &solver,
                 const unsigned int q = 12) {
    std::ostringstream s;
    s << "set Analysis = settlement\n"
      << "subsection Geometry model\n  set Model name = test arch\n"
      << "  set Thickness = " << t << "\n  set Density = " << rho << "\n"
      << "  subsection Test arch\n    set Radius = " << R
      << "\n    set Depth = " << D << "\n  end\nend\n"
      << "subsection Settlement\n  set Blocks along u = 1\n"
      << "  set Blocks along v = 1\n"
      << "  set Quadrature points = " << q << "\n"
      << "  set Supported edges = springing left, springing right\n"
      << "  set Settling edges = springing right\n"
      << "  set Settlement = 0; 0; -" << delta << "\n"
      << "  set Support contact = " << contact << "\n"
      << "  set Write picture = false\nend\n"
      << "subsection LP solver\n  set Solver = " << solver << "\nend\n";
    return s.str();
  };

  // Gauss quadrature of the block (split at the patch's knot at the crown;
  // 2 points across the thickness are exact): the weight converges to
  // W = ρ g π R t D as points are added
  double previous   = 1;
  bool   decreasing = true;
  for (const unsigned int q : {1u, 2u, 4u, 8u, 16u})
    {
      const masonry::Json s =
        vault_tests::run("one_block_q" + std::to_string(q),
                         prm("unilateral", "clp", q));
      const double error =
        vault_tests::relative(s.at("total_weight").get<double>(), W);
      decreasing = decreasing && (error < previous || error < 1e-14);
      previous   = error;
    }
  vault_tests::check(decreasing, "block weight converges with Gauss points");
  vault_tests::check(previous < 1e-10,
                     "block weight exact to 1e-10 with 16 points");

  for (const std::string solver : {"clp", "glpk"})
    {
      const masonry::Json s =
        vault_tests::run("one_block_" + solver, prm("unilateral", solver));
      const double work = s.at("external_work").get<double>();
      vault_tests::check(s.at("status").get<std::string>() == "optimal",
                         solver + ": status optimal");
      vault_tests::check(s.at("n_blocks").get<double>() == 1,
                         solver + ": one block");
      vault_tests::check(vault_tests::relative(work, expected) < 1e-9,
                         solver + ": external work = W delta (R - t/2)/(2R) "
                                  "to 1e-9");

      const masonry::Json b =
        vault_tests::run("one_block_bonded_" + solver, prm("bonded", solver));
      vault_tests::check(b.at("status").get<std::string>() == "incompatible",
                         solver + ": bonded supports -> incompatible");
    }
}
