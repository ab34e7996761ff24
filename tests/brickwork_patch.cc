/**
 * Patch test of the wallette on distorted meshes (`Mesh distortion`).
 * Uniform compression between frictionless platens has a uniform stress
 * state as its exact solution whatever the bond: uniaxial stress in the
 * bricks, a uniform opening sigma / k_n of every bed joint, no jump across
 * head and collar joints. Trilinear hexahedra represent the linear
 * displacement field exactly on any mesh, so a distorted mesh must give
 *   E_app = H / (H / E + (courses - 1) / k_n)      (elastic joints)
 *   E_app = E                                       (Joints = bonded)
 * to 1e-8. With interfaces the vertices inside each brick move (joint faces
 * stay flat); bonded, a global map moves every vertex but the wallette's
 * faces, and the nodal displacements must be the linear field
 *   u_x = nu eps x, u_y = nu eps y, u_z = -eps z
 * (eps = platen displacement / H; the pins at x = y = z = 0 fix the rigid
 * motions) to 1e-8 of eps H at every node.
 */
#include "brickwork_tests.h"

using namespace brickwork_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const double E = 12e9, nu = 0.2, k_n = 2.5e11, k_s = 1e11;
  const double h_b = 0.065 + 0.010, courses = 3, strain = 0.002;
  const double H = courses * h_b;

  std::ostringstream material;
  material << "subsection Brick material\nsubsection Elastic\n"
           << "set Young's modulus = " << E << "\n"
           << "set Poisson's ratio = " << nu << "\nend\nend\n"
           << "subsection Interface law\nset Law = elastic\n"
           << "set Normal stiffness = " << k_n << "\n"
           << "set Shear stiffness = " << k_s << "\nend\n";
  auto wallette = [&](const std::string &extra) {
    std::ostringstream w;
    w << "set Courses = " << courses << "\nset Length in bricks = 2\n"
      << "set Platen lateral restraint = free\n"
      << "set Target strain = " << strain << "\nset Number of steps = 2\n"
      << "set Mesh distortion = 0.2\n"
      << "set Gauge length = " << H << "\n"
      << extra;
    return w.str();
  };

  // --- elastic joints: series formula ------------------------------------
  struct Case
  {
    std::string name, wallette, bond;
  };
  const std::vector<Case> cases = {
    {"patch_stretcher_lobatto",
     "set Elements along the width = 3\nset Elements along the height = 3\n",
     "set Pattern = stretcher\n"},
    {"patch_stretcher_gauss",
     "set Elements along the width = 3\nset Elements along the height = 3\n"
     "set Interface integration = gauss\n",
     "set Pattern = stretcher\n"},
    {"patch_english_double",
     "set Elements along the height = 3\n",
     "set Pattern = english\nsubsection English\nset Thickness = double\n"
     "end\n"}};
  const double expected = H / (H / E + (courses - 1) / k_n);
  for (const auto &c : cases)
    {
      const masonry::Json s =
        run(c.name,
            prm(wallette(c.wallette),
                "subsection Bond\n" + c.bond + "end\n" + material.str()));
      check(relative(s.at("initial_modulus").get<double>(), expected) < 1e-8 &&
              relative(s.at("initial_modulus_gauge").get<double>(), expected) <
                1e-8 &&
              relative(s.at("final_stress").get<double>(), expected * strain) <
                1e-8,
            c.name + ": distorted bricks, modulus (height and gauge) and final "
                     "stress = series formula to 1e-8");
    }

  // --- bonded: modulus E and the linear displacement field --------------
  {
    const std::string   name = "patch_bonded";
    const masonry::Json s    = run(
      name,
      prm(wallette("set Elements along the width = 3\n"
                      "set Elements along the height = 3\n"
                      "set Joints = bonded\nset Write CalculiX input = true\n"),
          "subsection Bond\nset Pattern = stretcher\nend\n" + material.str()));
    check(relative(s.at("initial_modulus").get<double>(), E) < 1e-8 &&
            relative(s.at("final_stress").get<double>(), E * strain) < 1e-8,
          name + ": modulus and final stress = E to 1e-8");

    // the mesh spacing of the parameters: 225/4 x 112.5/3 x 75/3 mm
    const double  h[3] = {0.225 / 4, 0.1125 / 3, h_b / 3};
    std::ifstream in("results/" + name + "/nodal_displacements.csv");
    std::string   line;
    std::getline(in, line);
    double       offset = 0, error = 0;
    unsigned int n = 0;
    while (std::getline(in, line))
      {
        std::vector<double> r;
        std::stringstream   row(line);
        std::string         cell;
        while (std::getline(row, cell, ','))
          r.push_back(std::stod(cell));
        const double x[3] = {r[1], r[2], r[3]};
        for (unsigned int d = 0; d < 3; ++d)
          offset =
            std::max(offset, std::abs(x[d] / h[d] - std::round(x[d] / h[d])));
        const double exact[3] = {nu * strain * x[0],
                                 nu * strain * x[1],
                                 -strain * x[2]};
        for (unsigned int d = 0; d < 3; ++d)
          error = std::max(error, std::abs(r[4 + d] - exact[d]));
        ++n;
      }
    check(n > 0 && offset > 0.05,
          name + ": the vertices are off the regular grid by more than 5 % "
                 "of the mesh spacing");
    check(n > 0 && error < 1e-8 * strain * H,
          name + ": nodal displacements = the uniform-strain field to 1e-8 "
                 "of the platen displacement");
  }
}
