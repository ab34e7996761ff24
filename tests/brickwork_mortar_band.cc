/**
 * The crack band of the detailed model's mortar cells (doc/brickwork.md,
 * `Crack band'): a mortar cell's characteristic length is its size across
 * its layer, not the cube root of its volume (which for the flat cells of a
 * 10 mm layer is about 30 mm and shrinks as the plan size of the cells
 * does).
 *
 * (a) Geometry. The meshes of the examples (stretcher bond, single leaf;
 *     English bond, double leaf; units 215 x 102.5 x 65 mm, h_m = 10 mm,
 *     split units) at 4 x 2 x 2 and 8 x 4 x 4 cells per enlarged unit. A
 *     mortar cell lies in a bed joint when its centre is between the
 *     courses, k H - h_m < z < k H (H = 75 mm, from the inputs): the bed
 *     joints are one cell high, so its band length must be h_m, the input
 *     joint thickness. The other mortar cells are in head or collar joints:
 *     their band length must be their size across the joint, the smaller
 *     horizontal side, which is h_m or h_m / 2 (where the split plane of a
 *     unit in the next course halves the joint). Unit cells keep the cube
 *     root of their volume.
 * (b) Energy. A point of the `mortar' law with compressive softening
 *     (G_c = 17.06 kJ/m^2, the examples' value for f_m = 5 MPa) in
 *     uniaxial compression (the lateral stresses held at 0 by Newton on
 *     the lateral strains), with the band length of a bed-joint cell of
 *     each mesh: the work of the stress past the peak, integral of sigma
 *     de from eps_c over ten decay lengths, times the layer thickness, the
 *     crushing energy dissipated per unit area of a bed joint crushed
 *     through, must be G_c (1 %) on both meshes: the envelope's softening
 *     f_m exp(-(e - eps_c) f_m l / G_c) integrates to G_c / l. The law is
 *     run with `Plastic Poisson's ratio = elastic', with which its uniaxial
 *     path is exactly the input curve; with the mortar's default isochoric
 *     flow (0.5) the axial strain grows faster than the envelope strain
 *     past the peak and the work is about 1.17 G_c / l (a property of the
 *     law, not of the band). With the cube root of the volume the layer
 *     dissipated h_m / l = 0.34 and 0.53 G_c on the two meshes, the mesh
 *     dependence this corrects.
 */
#include <masonry/brickwork/bond.h>
#include <masonry/brickwork/brick_material.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "../source/brickwork/specimen/joints.h"
#include "../source/brickwork/specimen/mesh.h"
#include "../source/brickwork/specimen/specimen.h"

using namespace dealii;
using namespace masonry::brickwork;

namespace
{
  const double h_m = 0.010, G_c = 17060;

  void
  check(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "OK " : "FAILED ") << what << '\n';
    if (!ok)
      std::exit(1);
  }

  std::unique_ptr<Bond>
  bond(const std::string &pattern)
  {
    ParameterHandler prm;
    masonry::plugins::Registry<Bond>::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Bond\nset Pattern = " + pattern +
      (pattern == "english" ?
         "\nsubsection English\nset Thickness = double\nend\n" :
         "\n") +
      "end\n");
    return masonry::plugins::Registry<Bond>::create(prm);
  }

  /** Band length and cube root of the volume of a bed-joint cell of the
   * mesh; checks (a). */
  std::pair<double, double>
  band_lengths(const std::string &pattern, const unsigned int n)
  {
    MeshSettings s;
    s.size.length          = 0.215 + h_m;
    s.size.width           = 0.1025 + h_m;
    s.size.height          = 0.065 + h_m;
    s.size.courses         = 7;
    s.size.bricks_long     = 2;
    s.n_l                  = 2 * n;
    s.n_w                  = n;
    s.n_h                  = n;
    s.detailed             = true;
    s.split_units          = true;
    s.mortar_thickness     = h_m;
    const auto       boxes = bond(pattern)->layout(s.size);
    Triangulation<3> triangulation;
    const auto   geometry = model::make_detailed_mesh(boxes, s, triangulation);
    const auto   specimen = model::make_specimen(triangulation,
                                               geometry.n_bricks,
                                               model::Joints(),
                                               model::SpecimenSettings());
    unsigned int n_bed = 0, n_vertical = 0, n_unit = 0, bad_bed = 0,
                 bad_vertical = 0, bad_unit = 0;
    double bed = 0, bed_band = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        const double l   = specimen.cell_length[cell->active_cell_index()];
        const auto   box = cell->bounding_box();
        if (cell->material_id() == geometry.n_bricks)
          {
            // a bed joint: between the courses, k H - h_m < z < k H
            const double z = cell->center()[2], H = s.size.height;
            const double k = std::round(z / H);
            if (z > k * H - h_m && z < k * H)
              {
                ++n_bed;
                bad_bed += std::abs(l - h_m) > 1e-12;
                if (box.side_length(0) > 2 * h_m)
                  {
                    bed      = std::cbrt(cell->measure());
                    bed_band = l;
                  }
              }
            else
              {
                // a head or collar joint: one cell across (h_m) or, where
                // the next course's split plane halves it, two (h_m / 2)
                ++n_vertical;
                const double across =
                  std::min(box.side_length(0), box.side_length(1));
                bad_vertical +=
                  std::abs(l - across) > 1e-12 ||
                  (std::abs(l - h_m) > 1e-12 && std::abs(l - h_m / 2) > 1e-12);
              }
          }
        else
          {
            ++n_unit;
            bad_unit +=
              std::abs(l - std::cbrt(box.side_length(0) * box.side_length(1) *
                                     box.side_length(2))) > 1e-12;
          }
      }
    std::cout << pattern << ", " << s.n_l << " x " << s.n_w << " x " << s.n_h
              << " cells: " << n_bed << " bed-joint cells, " << n_vertical
              << " head/collar-joint cells, " << n_unit
              << " unit cells; cube root of a bed-joint cell " << bed * 1e3
              << " mm\n";
    check(n_bed > 0 && bad_bed == 0,
          "every bed-joint cell's band length is h_m = 10 mm");
    check(n_vertical > 0 && bad_vertical == 0,
          "every head/collar-joint cell's band length is its size across "
          "the joint, h_m or h_m / 2");
    check(n_unit > 0 && bad_unit == 0,
          "every unit cell's band length is the cube root of its volume, "
          "as before");
    return {bed_band, bed};
  }

  /** Area under the softening branch of uniaxial compression times h_m. */
  double
  crushing_energy_per_area(const double l)
  {
    ParameterHandler prm;
    masonry::plugins::Registry<BrickMaterial>::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Brick material\nset Model = mortar\nsubsection Mortar\n"
      "set Compressive softening = true\n"
      "set Plastic Poisson's ratio = elastic\n"
      "set Compressive fracture energy = " +
      std::to_string(G_c) + "\nend\nend\n");
    const auto   law = masonry::plugins::Registry<BrickMaterial>::create(prm);
    unsigned int n   = 0;
    for (const auto &v : law->state_variables())
      n += v.n_components;
    std::vector<double> state(n, 0.), updated(n);
    BrickPoint          point;
    point.characteristic_length = l;
    // the `mortar' law's defaults
    const double f_m = 5e6, eps_c = 0.01;
    // to the peak strain, then 10 decay lengths G_c / (f_m l) of the
    // softening branch (the energy left, exp(-10) = 5e-5 of it, is not
    // counted)
    const double          end   = eps_c + 10 * G_c / (f_m * l);
    const unsigned int    steps = 20000;
    SymmetricTensor<2, 3> strain, stress;
    SymmetricTensor<4, 3> C;
    double                energy = 0, last = 0, last_e = 0;
    for (unsigned int i = 1; i <= steps; ++i)
      {
        strain[2][2] = -end * i / steps;
        for (unsigned int it = 0;; ++it)
          {
            law->evaluate(strain, state, point, updated, stress, C);
            if (std::abs(stress[0][0]) + std::abs(stress[1][1]) <
                1e-4 * std::abs(stress[2][2]))
              break;
            AssertThrow(it < 500,
                        ExcMessage("no uniaxial stress state at strain " +
                                   std::to_string(strain[2][2])));
            // Newton on the lateral strains with the law's tangent
            const double J00 = C[0][0][0][0], J01 = C[0][0][1][1],
                         J10 = C[1][1][0][0], J11 = C[1][1][1][1];
            const double det = J00 * J11 - J01 * J10;
            const double r0 = stress[0][0], r1 = stress[1][1];
            strain[0][0] -= (J11 * r0 - J01 * r1) / det;
            strain[1][1] -= (-J10 * r0 + J00 * r1) / det;
          }
        state          = updated;
        const double e = -strain[2][2], s = -stress[2][2];

        // the softening branch: from the peak strain on
        if (e > eps_c)
          {
            const double a = std::max(last_e, eps_c);
            const double sa =
              last_e >= eps_c ?
                last :
                last + (s - last) * (eps_c - last_e) / (e - last_e);
            energy += 0.5 * (sa + s) * (e - a);
          }
        last   = s;
        last_e = e;
      }
    return energy * h_m;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(4);
  for (const std::string pattern : {"stretcher", "english"})
    for (const unsigned int n : {2u, 4u})
      {
        const auto [band, cube_root] = band_lengths(pattern, n);
        if (pattern != "stretcher")
          continue;
        const double W = crushing_energy_per_area(band);
        std::cout << "crushing energy per unit area of a layer: " << W
                  << " J/m^2 (G_c " << G_c << " J/m^2; with the cube root "
                  << cube_root * 1e3 << " mm it would be " << h_m / cube_root
                  << " G_c)\n";
        check(std::abs(W - G_c) <= 0.01 * G_c,
              "the layer dissipates G_c per unit area (1 %)");
      }
}
