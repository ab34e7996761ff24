/**
 * Elastic brickwork: the generator's joint counts against counts made by
 * hand, and the apparent modulus of a stack-bonded prism of elastic bricks
 * and elastic joints between frictionless platens, which is uniaxial:
 *   E_app = H / (sum over bricks h_b / E_b + sum over bed joints 1 / k_n),
 * with the strain over the height and over a gauge as long as the height.
 * Perfectly bonded (`Joints = bonded`), the prism has the bricks' modulus.
 * The Lourenco-Rots helper gives k_n = 2.5e11 Pa/m for E_u = 10 GPa,
 * E_m = 2 GPa, h_m = 10 mm (REFERENCES.md part B).
 */
#include <masonry/brickwork/interface_law.h>

#include "brickwork_tests.h"

using namespace brickwork_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // --- joint counts (2 bricks long, 4 courses), counted by hand --------
  struct Case
  {
    std::string  name, bond;
    unsigned int bricks, bed, head, collar;
  };
  // stretcher: courses of 2 and of 1 + 2 half bats; each of the 3 bed
  //   joints touches 4 brick pairs; 1 + 2 head joints per pair of courses.
  // english double: stretcher courses 2 x 2, header courses closer + 3
  //   headers + closer; a header course touches 2 + 2 + 4 + 2 + 2 bricks.
  // english triple: 7 bricks a course; per course 1 + 4 head joints and
  //   3 + 3 collar pairs; per bed 6 + 5 + 6 brick pairs.
  const std::vector<Case> cases = {
    {"count_stretcher", "set Pattern = stretcher\n", 10, 12, 6, 0},
    {"count_double",
     "set Pattern = english\nsubsection English\nset Thickness = double\nend\n",
     18,
     36,
     12,
     4},
    {"count_triple",
     "set Pattern = english\nsubsection English\nset Thickness = triple\nend\n",
     28,
     51,
     20,
     24},
    {"count_stack", "set Pattern = stack\n", 8, 6, 4, 0}};
  for (const auto &c : cases)
    {
      const masonry::Json s =
        run(c.name,
            prm("set Courses = 4\nset Length in bricks = 2\n"
                "set Number of steps = 1\nset Target strain = 1e-5\n",
                "subsection Bond\n" + c.bond +
                  "end\nsubsection Interface law\nset Law = elastic\nend\n"));
      check(s.at("n_bricks").get<double>() == c.bricks &&
              s.at("n_bed_joints").get<double>() == c.bed &&
              s.at("n_head_joints").get<double>() == c.head &&
              s.at("n_collar_joints").get<double>() == c.collar,
            c.bond.substr(14, c.bond.find('\n') - 14) +
              (c.name == "count_double" ? " double" :
               c.name == "count_triple" ? " triple" :
                                          "") +
              ": bricks " + std::to_string(c.bricks) + ", bed " +
              std::to_string(c.bed) + ", head " + std::to_string(c.head) +
              ", collar " + std::to_string(c.collar));
    }

  // --- series formula --------------------------------------------------
  const double E = 12e9, nu = 0.2, k_n = 2.5e11, k_s = 1e11;
  const double h_b = 0.065 + 0.010;
  for (const std::string integration : {"lobatto", "gauss"})
    for (const unsigned int courses : {1u, 3u, 6u})
      for (const unsigned int n_long : {1u, 2u})
        {
          const std::string name = "stack_" + integration + "_" +
                                   std::to_string(courses) + "_" +
                                   std::to_string(n_long);
          std::ostringstream w, p;
          w << "set Courses = " << courses << "\n"
            << "set Length in bricks = " << n_long << "\n"
            << "set Platen lateral restraint = free\n"
            << "set Target strain = 0.002\nset Number of steps = 2\n"
            << "set Interface integration = " << integration << "\n"
            << "set Elements along the length = 2\n"
            << "set Elements along the height = " << (courses % 2 + 1) << "\n"
            << "set Gauge length = " << courses * h_b << "\n";
          p << "subsection Bond\nset Pattern = stack\nend\n"
            << "subsection Brick material\nsubsection Elastic\n"
            << "set Young's modulus = " << E << "\n"
            << "set Poisson's ratio = " << nu << "\nend\nend\n"
            << "subsection Interface law\nset Law = elastic\n"
            << "set Normal stiffness = " << k_n << "\n"
            << "set Shear stiffness = " << k_s << "\nend\n";
          const masonry::Json s = run(name, prm(w.str(), p.str()));
          const double        H = courses * h_b;
          const double expected = H / (courses * h_b / E + (courses - 1) / k_n);
          const double error =
            relative(s.at("initial_modulus").get<double>(), expected);
          const double error_peak =
            relative(s.at("peak_stress").get<double>(), expected * 0.002);
          const double error_gauge =
            relative(s.at("initial_modulus_gauge").get<double>(), expected);
          check(error < 1e-8 && error_peak < 1e-8 && error_gauge < 1e-8,
                name + ": modulus (height and full-height gauge) and final "
                       "stress = series formula to 1e-8");
        }

  // the same prism with bilinear (damaging) joints: in uniform compression
  // no joint opens or slips, so the response is the elastic one and every
  // interface evaluation takes the cached elastic matrix (the law is never
  // called)
  {
    std::ostringstream p;
    p << "subsection Bond\nset Pattern = stack\nend\n"
      << "subsection Brick material\nsubsection Elastic\n"
      << "set Young's modulus = " << E << "\n"
      << "set Poisson's ratio = " << nu << "\nend\nend\n"
      << "subsection Interface law\nset Law = bilinear\n"
      << "set Normal stiffness = " << k_n << "\n"
      << "set Shear stiffness = " << k_s << "\nend\n";
    const masonry::Json s =
      run("stack_bilinear",
          prm("set Courses = 3\nset Length in bricks = 2\n"
              "set Platen lateral restraint = free\n"
              "set Target strain = 0.002\nset Number of steps = 2\n"
              "set Elements along the length = 2\n",
              p.str()));
    const double H = 3 * h_b, expected = H / (3 * h_b / E + 2 / k_n);
    check(relative(s.at("initial_modulus").get<double>(), expected) < 1e-8 &&
            s.at("interface_evaluations_elastic_fraction").get<double>() == 1,
          "stack prism, bilinear joints in compression: series modulus to "
          "1e-8, every interface evaluation skipped (elastic fraction 1)");
  }

  // perfectly bonded: no interfaces, the modulus of the bricks
  {
    std::ostringstream p;
    p << "subsection Bond\nset Pattern = stretcher\nend\n"
      << "subsection Brick material\nsubsection Elastic\n"
      << "set Young's modulus = " << E << "\n"
      << "set Poisson's ratio = " << nu << "\nend\nend\n";
    const masonry::Json s =
      run("bonded",
          prm("set Courses = 3\nset Length in bricks = 2\n"
              "set Platen lateral restraint = free\nset Joints = bonded\n"
              "set Target strain = 0.001\nset Number of steps = 1\n",
              p.str()));
    check(relative(s.at("initial_modulus").get<double>(), E) < 1e-8 &&
            s.at("n_bed_interface_faces").get<double>() == 0 &&
            s.at("n_head_interface_faces").get<double>() == 0,
          "bonded stretcher prism: no interfaces, modulus = E to 1e-8");
  }
  check(relative(masonry::brickwork::lourenco_rots_stiffness(10e9, 2e9, 0.01),
                 2.5e11) < 1e-14,
        "Lourenco-Rots stiffness: 2.5e11 Pa/m");
}
