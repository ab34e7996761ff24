/**
 * The detailed model's compressive strength of a single-leaf wallette
 * against the two published formulas for the mean strength of clay-brick
 * masonry from the unit strength f_b and the mortar strength f_m (MPa):
 *  - Kaushik, Rai & Jain (2007): f'_m = 0.63 f_b^0.49 f_m^0.32;
 *  - Eurocode 6 (EN 1996-1-1, general-purpose mortar): characteristic
 *    f_k = K f_b^0.7 f_m^0.3, K = 0.55 (clay, Group 1), mean 1.2 f_k;
 * the band of issue 16: 0.85 x Kaushik to 1.15 x the EC6 mean. The
 * formulas and the status of K and 1.2 (recalled, not confirmed in the
 * standard) are in doc/references-brickwork-strength.md.
 *
 * The wallette is one pair of the study sweep, f_b = 20 MPa, f_m = 2 MPa:
 * a weak mortar under a typical unit. Before the mortar's compressive
 * softening (runs of 2026-11-24) this pair never reached a peak: the
 * confined mortar flowed at f_m + k p with k p rising, and the stress
 * still rose at strain 0.016 (6.77 MPa), so the check "past its peak at
 * the end" failed; with the softening of the mortar's cohesive part
 * (crushing energy 15 + 0.43 f_m - 0.0036 f_m^2 N/mm) it peaked at about
 * 5.2 MPa with the mortar cells' crack band the cube root of their volume,
 * and peaks at 6.1 MPa (the same within 0.1 % at 4 x 2 x 2 cells) with
 * the band across the layer, h_m (tests/brickwork_mortar_band), inside the
 * band 2.9-7.6 MPa. Inputs as a laboratory
 * gives them: the study sweep's former parameter file (contrib/study/
 * sweep-detailed.prm, replaced on 2026-11-24 by the single-leaf monotonic
 * example; no splitting interfaces, no deletion) with the unit and mortar
 * values from f_b and f_m by the relations of contrib/study/study.py,
 * sweep_inputs() (unit `Compressive strength' = f_b with `Compressive
 * strength definition' = normalised, from which the law derives its
 * uniaxial strength 0.8 f_b, checked here in summary.json; E_b = 400 f_b;
 * mortar E_m = 200 f_m), on the coarsest mesh (2 x 1 x 1 cells per unit)
 * with a nominal step of 2e-4 to strain 0.026: 7 courses
 * x 2 stretchers, units 215 x 102.5 x 65 mm, 10 mm mortar layers of the
 * `mortar' law, composite bond with Coulomb friction, rigid platens with
 * full friction, monotonic compression past the peak (IMPL-EX).
 *
 * The run goes to 0.026, twice the strain at the peak (0.0127), where the
 * envelope of issue 16, s / s_m = (e / e_m) exp(1 - e / e_m), is at 0.74 of
 * the peak: the sweep's 0.016 (1.26 e_m, envelope 0.97) ended below 0.8 of
 * the peak only through a drop from 5.99 to 3.55 MPa between strains
 * 0.0151 and 0.0155 that came with a mortar cell strained from 0.98 to 3.3
 * in those steps, the IMPL-EX loop of the cracks' extrapolated opening
 * (doc/notes/implex-step-control.md); with `IMPL-EX crack opening = frozen'
 * the wallette is at 5.97 MPa (0.975 of the peak) at 0.0157 and at 3.86 MPa
 * (0.63) at 0.026.
 *
 * The check can fail, and did for other inputs: without the mortar's
 * softening this pair does not peak (above); the seed paper's
 * `simplified' model (enlarged units, cohesive joints) peaks at 0.8 f_b
 * whatever f_m (contrib/study/results-2026-11-24, sweep.csv: 16.0 MPa for
 * f_b = 20 MPa), twice the upper end.
 */
#include <iomanip>

#include "brickwork_tests.h"

using namespace brickwork_tests;

namespace
{
  // the sweep pair (MPa)
  const double f_b = 20, f_m = 2;

  /** The study's relations (contrib/study/study.py, sweep_inputs()), SI. */
  std::string
  laws()
  {
    std::ostringstream s;
    s.precision(6);
    // compressive fracture energy, J/m^2, of a material of strength f
    // (MPa): contrib/study/study.py, crushing_energy()
    auto G_c = [](const double f) {
      return (15 + 0.43 * f - 0.0036 * f * f) * 1e3;
    };
    s << "subsection Bond\n  set Pattern = stretcher\nend\n"
      << "subsection Brick material\n  set Model = damage plasticity\n"
      << "  subsection Damage plasticity\n"
      << "    set Young's modulus = " << 400 * f_b * 1e6 << "\n"
      << "    set Poisson's ratio = 0.15\n"
      << "    set Compressive strength = " << f_b * 1e6 << "\n"
      << "    set Compressive strength definition = normalised\n"
      << "    set Tensile strength = " << 0.1 * f_b * 1e6 << "\n"
      << "    set Tensile fracture energy = 80\n"
      << "    set Compressive fracture energy = " << G_c(f_b) << "\n"
      << "    set Tension-compression interaction = true\n"
      << "  end\nend\n"
      << "subsection Mortar material\n  set Model = mortar\n"
      << "  subsection Mortar\n"
      << "    set Young's modulus = " << 200 * f_m * 1e6 << "\n"
      << "    set Poisson's ratio = 0.2\n"
      << "    set Compressive strength = " << f_m * 1e6 << "\n"
      << "    set Tensile strength = " << 0.1 * f_m * 1e6 << "\n"
      << "    set Tensile fracture energy = " << 2 * f_m << "\n"
      << "    set Compressive softening = true\n"
      << "    set Compressive fracture energy = " << G_c(f_m) << "\n"
      << "  end\nend\n"
      << "subsection Interface law\n  set Law = composite\n"
      << "  set Normal stiffness = 1e13\n  set Shear stiffness = 1e13\n"
      << "  subsection Composite\n"
      << "    set Tensile strength = 0.2e6\n    set Cohesion = 0.28e6\n"
      << "    set Friction = 0.75\n    set Residual friction = 0.75\n"
      << "    set Mode I fracture energy = 15\n"
      << "    set Mode II fracture energy = 100\n"
      << "    set Cap strength = 200e6\n"
      << "    set Compressive fracture energy = 1e5\n"
      << "  end\nend\n";
    return s.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);

  const double kaushik = 0.63 * std::pow(f_b, 0.49) * std::pow(f_m, 0.32);
  const double f_k     = 0.55 * std::pow(f_b, 0.7) * std::pow(f_m, 0.3);
  const double low = 0.85 * kaushik, high = 1.15 * 1.2 * f_k;
  std::cout << "f_b = " << f_b << " MPa, f_m = " << f_m << " MPa: Kaushik "
            << kaushik << " MPa, EC6 f_k " << f_k << " MPa, mean " << 1.2 * f_k
            << " MPa; band " << low << " to " << high << " MPa\n";

  const std::string wallette =
    "  set Model = detailed\n"
    "  set Brick length = 0.215\n  set Brick width = 0.1025\n"
    "  set Brick height = 0.065\n  set Joint thickness = 0.010\n"
    "  set Courses = 7\n  set Length in bricks = 2\n"
    "  set Elements along the length = 2\n"
    "  set Elements along the width = 1\n"
    "  set Elements along the height = 1\n"
    "  set Platen lateral restraint = fixed\n"
    "  set Platen direction = 0, 0, -1\n"
    "  set Protocol = monotonic\n"
    "  set Target strain = 0.026\n  set Number of steps = 130\n"
    "  set Interface integration = lobatto\n"
    "  set Output interval = 0\n"
    "  set Damage integration = implex\n"
    "  set IMPL-EX damage tolerance = 0.05\n"
    "  set Maximum Newton iterations = 50\n";
  const auto summary = run("band", prm(wallette, laws()));

  const auto   c    = curve("band");
  double       peak = 0, final_stress = c.back()[4];
  unsigned int at = 0;
  for (unsigned int i = 0; i < c.size(); ++i)
    if (c[i][4] > peak)
      {
        peak = c[i][4];
        at   = i;
      }
  peak /= 1e6;
  check(summary.at("model").get<std::string>() == "detailed" &&
          summary.at("status").get<std::string>() == "completed",
        "the detailed model ran to the end");
  check(at + 1 < c.size() && final_stress / 1e6 < 0.8 * peak,
        "the wallette is past its peak at the end (stress below 0.8 x "
        "the peak)");
  const double f_c = summary.at("derived_values")
                       .at("brick_material")
                       .at("uniaxial_compressive_strength")
                       .get<double>();
  check(std::abs(f_c - 0.8 * f_b * 1e6) <= 1e-9 * f_c,
        "the unit law's uniaxial strength is 0.8 f_b (derived, printed)");
  check(peak >= low, "peak above 0.85 x Kaushik's mean");
  check(peak <= high, "peak below 1.15 x EC6's mean 1.2 f_k");
}
