/**
 * The detailed model (`Model = detailed'): a stack-bonded prism of three
 * elastic units (E_b = 10 GPa, nu_b = 0.15, h_b = 65 mm) with two mortar
 * layers meshed as hexahedra (E_m = 1 GPa, nu_m = 0.2, h_m = 10 mm; the
 * design note's example), stiff elastic contact interfaces between units and
 * mortar (k_n = k_s = 1e14 Pa/m), frictionless platens, compressed.
 *
 * Closed form (design note, Hilsdorf's elastic stage): far from the free
 * sides every layer of a bonded stack has the same lateral strain, the
 * lateral stresses are equal in x and y, and the lateral forces balance,
 * n_b h_b sigma_b + n_m h_m sigma_m = 0. Then the units are in lateral
 * tension sigma_b = beta |sigma_z| with
 *   beta = (nu_m/E_m - nu_b/E_b) / ((1 - nu_b)/E_b + r (1 - nu_m)/E_m),
 *   r = n_b h_b / (n_m h_m)
 * (for the interior of a long stack r -> h_b / h_m, the design note's
 * form; three units and two joints give r = 9.75, beta = 0.02346), the
 * mortar in lateral compression sigma_m = -r sigma_b, and the vertical
 * shortening is a series of laterally restrained layers and the four
 * interfaces:
 *   U = |sigma_z| (n_b h_b (1 + 2 nu_b beta)/E_b
 *                  + n_m h_m (1 - 2 nu_m r beta)/E_m + 2 n_m / k_n).
 * The units are 2 m x 2 m in plan (the centre is 4.6 prism heights from
 * the free sides, where the lateral stresses vanish), 16 x 16 cells: the
 * centre cells follow the uniform state (the trilinear hexahedra hold it
 * exactly); what remains is the free sides' effect, measured against a
 * 4 m x 4 m prism when this test was written (see
 * doc/notes/brickwork-failure-mechanism.md).
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/postprocessor.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <fstream>
#include <iomanip>
#include <sstream>

#include "../source/brickwork/assembly/point_states.h"
#include "../source/brickwork/assembly/system.h"
#include "../source/brickwork/specimen/mesh.h"
#include "../source/brickwork/specimen/specimen.h"
#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  using namespace dealii;
  using masonry::brickwork::ConstStateView;

  /**
   * The cell-averaged stress (Pa) of the cells nearest to the centre of the
   * middle unit (material id 1) and of the lower mortar layer (material id
   * 3), into summary.json as centre_unit_stress_xx, ... (one rank).
   */
  class CentreStress : public masonry::brickwork::postprocess::Postprocessor
  {
  public:
    static void
    declare_parameters(ParameterHandler &)
    {}

    void
    finish(const masonry::brickwork::ModelView &view,
           masonry::Json                       &summary) override
    {
      const auto   u              = view.system.ghosted_copy();
      const double x              = view.geometry.length / 2,
                   y              = view.geometry.thickness / 2;
      const unsigned int ids[2]   = {1, 3};
      const char        *names[2] = {"centre_unit", "centre_mortar"};
      QGauss<3>          quadrature(2);
      FEValues<3> fe_values(view.system.fe, quadrature, update_gradients);
      std::vector<SymmetricTensor<2, 3>> eps(8);
      const FEValuesExtractors::Vector   displacement(0);
      for (unsigned int k = 0; k < 2; ++k)
        {
          // the cells of this layer that touch the vertical centre line
          SymmetricTensor<2, 3> mean;
          unsigned int          n = 0;
          for (const auto &cell :
               view.system.dof_handler.active_cell_iterators())
            if (cell->material_id() == ids[k] &&
                std::abs(cell->center()[0] - x) <
                  cell->extent_in_direction(0) &&
                std::abs(cell->center()[1] - y) < cell->extent_in_direction(1))
              {
                fe_values.reinit(cell);
                fe_values[displacement].get_function_symmetric_gradients(u,
                                                                         eps);
                for (unsigned int q = 0; q < 8; ++q)
                  {
                    // the converged state at the converged strain, by the
                    // law of the cell's region
                    const SymmetricTensor<2, 3> s =
                      view.brick_stress(cell->active_cell_index(), q, eps[q]);
                    mean += s;
                    ++n;
                  }
              }
          mean /= n;
          summary[std::string(names[k]) + "_stress_xx"] = mean[0][0];
          summary[std::string(names[k]) + "_stress_yy"] = mean[1][1];
          summary[std::string(names[k]) + "_stress_zz"] = mean[2][2];
        }
    }
  };

  const double Eb = 10e9, nub = 0.15, Em = 1e9, num = 0.2, hb = 0.065,
               hm = 0.010, kn = 1e14;

  /** The laws of the peak (confinement) check. */
  const std::string plastic_laws =
    "subsection Bond\n  set Pattern = stack\nend\n"
    "subsection Brick material\n"
    "  set Model = damage plasticity\n"
    "  subsection Damage plasticity\n"
    "    set Young's modulus = 10e9\n"
    "    set Poisson's ratio = 0.15\n"
    "    set Compressive strength = 20e6\n"
    "    set Tensile strength = 2e6\n"
    "    set Tensile fracture energy = 200\n"
    "    set Tension-compression interaction = true\n"
    "  end\n"
    "end\n"
    "subsection Mortar material\n"
    "  set Model = mortar\n"
    "  subsection Mortar\n"
    "    set Young's modulus = 1e9\n"
    "    set Poisson's ratio = 0.2\n"
    "    set Compressive strength = 5e6\n"
    "    set Tensile fracture energy = 100\n"
    "  end\n"
    "end\n"
    "subsection Interface law\n"
    "  set Law = elastic\n"
    "  set Normal stiffness = 1e14\n"
    "  set Shear stiffness = 1e14\n"
    "end\n"
    "subsection Postprocess\n"
    "  subsection Wallette\n"
    "    set List of postprocessors = curve tables, centre stress\n"
    "  end\n"
    "end\n";

  std::string
  prism(const double plan, const unsigned int cells, const bool vtu)
  {
    std::ostringstream s;
    s << "  set Model = detailed\n"
         "  set Brick length = "
      << plan << "\n  set Brick width = " << plan
      << "\n"
         "  set Brick height = 0.065\n"
         "  set Joint thickness = 0.010\n"
         "  set Courses = 3\n"
         "  set Length in bricks = 1\n"
         "  set Elements along the length = "
      << cells << "\n  set Elements along the width = " << cells
      << "\n"
         "  set Elements along the height = 2\n"
         "  set Platen lateral restraint = free\n"
         "  set Target strain = 0.001\n"
         "  set Number of steps = 2\n"
      << (vtu ? "  set Write VTU = true\n" : "");
    return prm(s.str(),
               "subsection Bond\n  set Pattern = stack\nend\n" +
                 elastic_units_and_mortar("0.15") + elastic_bond +
                 "subsection Postprocess\n"
                 "  subsection Wallette\n"
                 "    set List of postprocessors = curve tables, fields, "
                 "centre stress\n"
                 "  end\n"
                 "end\n");
  }
  /** The wide prism of the peak checks: @p cells x @p cells in plan. */
  std::string
  plastic_prism(const unsigned int cells, const double target)
  {
    std::ostringstream w;
    w << "  set Model = detailed\n"
         "  set Brick length = 2.0\n"
         "  set Brick width = 2.0\n"
         "  set Brick height = 0.065\n"
         "  set Joint thickness = 0.010\n"
         "  set Courses = 3\n"
         "  set Length in bricks = 1\n"
         "  set Elements along the length = "
      << cells << "\n  set Elements along the width = " << cells
      << "\n"
         "  set Elements along the height = 2\n"
         "  set Platen lateral restraint = free\n"
         "  set Target strain = "
      << target << "\n  set Number of steps = " << std::lround(target / 1e-4)
      << "\n  set Damage integration = implex\n";
    return w.str();
  }

  /**
   * The same wide prism with the laws of issue 16: units `damage
   * plasticity' (f_b = 20 MPa, f_bt = 2 MPa, tension-compression
   * interaction), mortar `mortar' (f_m = 5 MPa, E_m = 1 GPa, nu_m = 0.2;
   * its defaults: no compressive softening, isochoric plastic flow, the
   * cone's confinement coefficient k), elastic stiff bond, free platens,
   * IMPL-EX.
   *
   * Peak (design note, Hilsdorf): the mortar flows at its confined strength
   * |sigma_z| = f_m + k p and keeps expanding, the pressure p grows until
   * the unit, in lateral tension t = p / r (r = n_b h_b / (n_m h_m) for
   * this stack, as above), fails on t / f_bt + |sigma_z| / f_b = 1:
   *   f = f_b (f_bt + a f_m) / (f_bt + a f_b), a = 1 / (k r),
   * 13.69 MPa with k = 1.41379 and r = 9.75. Measured on 2 m x 2 m with
   * 4 x 4, 8 x 8 cells in plan: 1.0 %, 1.7 % below (the free sides, where
   * the mortar is not confined, carry less as the mesh resolves them; see
   * doc/notes/brickwork-failure-mechanism.md for the finer runs):
   * tolerance 3 %.
   *
   * Without plastic dilatancy (`Plastic Poisson's ratio = elastic': the
   * plastic strain grows along C0^-1 : s) the mortar's lateral plastic
   * strain vanishes at p = nu_m / (1 - nu_m) |sigma_z|, the pressure stops
   * there, and the prism flows at f_m / (1 - k nu_m / (1 - nu_m)) =
   * 7.733 MPa with intact units, reached from below (0.26 % at strain
   * 0.005 on 4 x 4 cells; lateral pressure 0.37 % from the ratio).
   */
  void
  confinement(const double nb, const double nm, const double r)
  {
    const double fm = 5e6, fb = 20e6, fbt = 2e6;
    {
      auto summary =
        run("hilsdorf", prm(plastic_prism(8, 0.0062), plastic_laws));
      const double k =
        summary["derived_values"]["mortar_material"]["confinement_coefficient"]
          .get<double>();
      const double a = 1 / (k * r), f = fb * (fbt + a * fm) / (fbt + a * fb);
      const double peak = summary["peak_stress"].get<double>();
      std::cout << std::setprecision(4) << "Hilsdorf: k = " << k << ", "
                << f * 1e-6 << " MPa\n";
      check(relative(peak, f) < 0.03,
            "peak = Hilsdorf's prism strength with the laws' k, f_bt, f_b, "
            "f_m (3 %)");
      check(summary["final_stress"].get<double>() < 0.95 * peak,
            "the prism is past its peak at the end");
    }
    {
      std::string laws = plastic_laws;
      laws.replace(laws.find("    set Tensile fracture energy = 100\n"),
                   0,
                   "    set Plastic Poisson's ratio = elastic\n");
      auto         summary = run("plateau", prm(plastic_prism(4, 0.005), laws));
      const double k =
        summary["derived_values"]["mortar_material"]["confinement_coefficient"]
          .get<double>();
      const double ratio = num / (1 - num);
      const double sp    = fm / (1 - k * ratio);
      const double peak  = summary["peak_stress"].get<double>();
      const double sz =
        std::abs(summary["centre_mortar_stress_zz"].get<double>());
      const double p = -summary["centre_mortar_stress_xx"].get<double>();
      const double t = summary["centre_unit_stress_xx"].get<double>();
      std::cout << "non-dilatant mortar: plateau " << sp * 1e-6 << " MPa\n";
      check(peak < sp * (1 + 1e-4) && relative(peak, sp) < 1e-2,
            "non-dilatant mortar: peak tends to f_m / (1 - k nu_m / (1 - "
            "nu_m)) from below (1 % at strain 0.005)");
      check(relative(p / sz, ratio) < 0.01,
            "non-dilatant mortar: lateral pressure at the centre = nu_m / (1 "
            "- nu_m) |sigma_z| (1 %)");
      // measured 1.2 % on 4 x 4 cells (0.19 % on 8 x 8): the centre cells
      // are 0.5 m wide
      check(relative(t, p * nm * hm / (nb * hb)) < 0.02,
            "unit's lateral tension at the centre = p n_m h_m / (n_b h_b) "
            "(2 %)");
      check(summary["max_brick_damage_tension"].get<double>() == 0 &&
              summary["max_brick_damage_compression"].get<double>() < 0.01,
            "non-dilatant mortar: the units stay intact");
    }
  }
} // namespace

MASONRY_REGISTER_WALLETTE_POSTPROCESSOR(
  CentreStress,
  "centre stress",
  "Test: the stresses at the centre of the middle unit and of a mortar "
  "layer.")

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     nb = 3, nm = 2, r = nb * hb / (nm * hm);
  const double                     beta =
    (num / Em - nub / Eb) / ((1 - nub) / Eb + r * (1 - num) / Em);
  const double compliance = nb * hb * (1 + 2 * nub * beta) / Eb +
                            nm * hm * (1 - 2 * num * r * beta) / Em +
                            2 * nm / kn;
  const double H = nb * hb + nm * hm;
  std::cout << "r = " << r << ", beta = " << beta << "\n";

  auto         summary  = run("prism", prism(2.0, 16, true));
  const double sz       = summary["centre_unit_stress_zz"].get<double>();
  const double sxb      = summary["centre_unit_stress_xx"].get<double>(),
               syb      = summary["centre_unit_stress_yy"].get<double>(),
               sxm      = summary["centre_mortar_stress_xx"].get<double>();
  const double e_unit   = std::max(relative(sxb, beta * std::abs(sz)),
                                 relative(syb, beta * std::abs(sz)));
  const double e_mortar = relative(sxm, -r * beta * std::abs(sz));
  std::cout << std::setprecision(4)
            << "lateral stress of the unit / |sigma_z|: " << sxb / std::abs(sz)
            << " (closed form " << beta << ")\n";
  // measured: 1.1e-4 (unit), 2e-6 (mortar), 3e-5 (modulus); on a 4 m x
  // 4 m prism with 32 x 32 cells 5e-5, 6e-7, 1.5e-5: the free sides'
  // effect. A prism of the brick's plan (0.215 x 0.215 m) is 42 % below
  // beta at the centre: the closed form holds for wide layers only.
  check(e_unit < 1e-3,
        "centre of the middle unit: sigma_x = sigma_y = beta |sigma_z| "
        "(0.1 %)");
  check(e_mortar < 1e-3,
        "centre of the mortar layer: sigma_x = -r beta |sigma_z| (0.1 %)");
  const double E = H / compliance;
  check(relative(summary["initial_modulus"].get<double>(), E) < 1e-3,
        "vertical stiffness: series of restrained layers and interfaces "
        "(0.1 %)");
  // the plain series of the layers' moduli (no lateral restraint) is 4.5 %
  // softer: the restraint is measurable
  const double plain = H / (nb * hb / Eb + nm * hm / Em + 2 * nm / kn);
  check(relative(summary["initial_modulus"].get<double>(), plain) > 0.03,
        "vertical stiffness: differs from the unrestrained series by more "
        "than 3 %");
  check(relative(summary["height"].get<double>(), H) < 1e-12 &&
          relative(summary["gross_area"].get<double>(), 4.0) < 1e-12,
        "height 3 h_b + 2 h_m, gross area of the unit");
  check(summary["n_mortar_cells"].get<double>() == 2 * 16 * 16,
        "two mortar layers of one cell");
  check(summary["n_bed_interface_faces"].get<double>() == 4 * 16 * 16,
        "four unit-mortar interfaces");
  auto &d = summary["derived_values"]["detailed_model"];
  check(relative(d["lourenco_rots_normal_stiffness"].get<double>(),
                 Eb * Em / (hm * (Eb - Em))) < 1e-12 &&
          relative(d["contact_compliance_ratio"].get<double>(),
                   (2 / kn) / (hm / Em)) < 1e-12,
        "derived values: Lourenco-Rots stiffness (not used), contact "
        "compliance ratio");
  std::ifstream     vtu("results/prism/solution_0002.pvtu");
  std::stringstream text;
  text << vtu.rdbuf();
  check(text.str().find("Name=\"region\"") != std::string::npos,
        "solution VTU has the region field");

  // the peak with the unit and mortar laws (plastic, confinement)
  confinement(nb, nm, r);
}
