/**
 * @file
 * Strength scatter and characteristic lengths.
 */
#include "specimen.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      void
      SpecimenSettings::declare_parameters(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Double;
        using dealii::Patterns::Integer;
        prm.declare_entry(
          "Strength scatter",
          "0",
          Double(0, 0.5),
          "Coefficient of variation of the strengths (dimensionless, 0 to "
          "0.5; 0: every brick and joint has the nominal strengths). Each "
          "brick and each joint (pair of bricks) draws a normal factor 1 + "
          "this x N(0, 1), kept within 0.2 to 1.8, on its strengths "
          "(a specimen of a series).");
        prm.declare_entry("Random seed",
                          "1",
                          Integer(0),
                          "Seed of the strength factors: the same seed gives "
                          "the same specimen.");
      }

      void
      SpecimenSettings::parse_parameters(dealii::ParameterHandler &prm)
      {
        strength_scatter = prm.get_double("Strength scatter");
        seed             = prm.get_integer("Random seed");
      }

      Specimen
      make_specimen(const dealii::Triangulation<3> &triangulation,
                    const unsigned int              n_bricks,
                    const Joints                   &joints,
                    const SpecimenSettings         &settings)
      {
        const auto        &faces   = joints.faces;
        const unsigned int n_cells = triangulation.n_active_cells();
        Specimen           s;
        s.cell_length.assign(n_cells, 0);
        s.cell_factor.assign(n_cells, 1);
        s.deleted.assign(n_cells, 0);
        s.fade.assign(n_cells, 1);
        s.split_shortening.assign(n_cells, -1);
        s.max_shortening.assign(n_cells, 0);
        s.face_factor.assign(faces.size(), 1);
        s.face_deleted.assign(faces.size(), 0);
        std::mt19937                     random(settings.seed);
        std::normal_distribution<double> normal(0., 1.);
        const double                     cov  = settings.strength_scatter;
        auto                             draw = [&]() {
          const double x = normal(random);
          return std::clamp(1 + cov * x, 0.2, 1.8);
        };
        std::vector<double> brick_factor(n_bricks, 1);
        for (auto &f : brick_factor)
          f = cov > 0 ? draw() : 1.;
        std::map<std::pair<unsigned int, unsigned int>, double> joint_factor;
        for (const auto &face : faces)
          if (face.type != splitting_type)
            joint_factor[{face.brick_a, face.brick_b}] = 1;
        for (auto &j : joint_factor)
          j.second = cov > 0 ? draw() : 1.;
        // the mortar of the detailed model: one factor, drawn last (the
        // simplified model's specimens stay as they were)
        s.cell_region.assign(n_cells, 0);
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->material_id() == n_bricks)
            s.cell_region[cell->active_cell_index()] = 1;
        if (std::find(s.cell_region.begin(), s.cell_region.end(), 1) !=
            s.cell_region.end())
          brick_factor.push_back(cov > 0 ? draw() : 1.);
        // a splitting interface has the strength factor of its unit
        for (unsigned int i = 0; i < faces.size(); ++i)
          s.face_factor[i] =
            faces[i].type == splitting_type ?
              brick_factor[faces[i].brick_a] :
              joint_factor[{faces[i].brick_a, faces[i].brick_b}];
        // the crack band (doc/brickwork.md, `Crack band'): a unit cell's
        // cube root of its volume; a mortar cell's size across its layer
        // (the detailed mesh is a tensor grid of boxes, its mortar layers
        // one cell thick or a few): a cell of a bed joint, i.e. whose
        // heights no unit cell shares (also where head and collar joints
        // cross the bed joint), its height; a cell of a head or collar
        // joint, the smaller of its horizontal sides
        std::vector<std::pair<double, double>> unit_heights;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (s.cell_region[cell->active_cell_index()] == 0)
            {
              const auto box = cell->bounding_box();
              unit_heights.emplace_back(box.lower_bound(2), box.upper_bound(2));
            }
        std::sort(unit_heights.begin(), unit_heights.end());
        unit_heights.erase(std::unique(unit_heights.begin(),
                                       unit_heights.end(),
                                       [](const auto &a, const auto &b) {
                                         return std::abs(a.first - b.first) +
                                                  std::abs(a.second -
                                                           b.second) <
                                                1e-12;
                                       }),
                           unit_heights.end());
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            double l = std::cbrt(cell->measure());
            if (s.cell_region[cell->active_cell_index()] == 1)
              {
                const auto   box = cell->bounding_box();
                const double z0 = box.lower_bound(2), z1 = box.upper_bound(2);
                const double tol = 1e-6 * (z1 - z0);
                const bool   bed = std::none_of(unit_heights.begin(),
                                              unit_heights.end(),
                                              [&](const auto &h) {
                                                return h.first < z1 - tol &&
                                                       h.second > z0 + tol;
                                              });
                l                = bed ? z1 - z0 :
                                         std::min(box.side_length(0), box.side_length(1));
              }
            s.cell_length[cell->active_cell_index()] = l;
            s.cell_factor[cell->active_cell_index()] =
              brick_factor[cell->material_id()];
          }
        return s;
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
