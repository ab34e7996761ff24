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
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            s.cell_length[cell->active_cell_index()] =
              std::cbrt(cell->measure());
            s.cell_factor[cell->active_cell_index()] =
              brick_factor[cell->material_id()];
          }
        return s;
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
