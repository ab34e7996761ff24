/**
 * @file
 * Element deletion.
 */
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include "deletion.h"

#include <algorithm>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using namespace dealii;

      std::vector<types::global_dof_index>
      orphan_dofs(const System &system, const Specimen &specimen)
      {
        std::vector<char> used(system.dof_handler.n_dofs(), 0);
        std::vector<types::global_dof_index> dofs(24);
        for (const auto &cell : system.dof_handler.active_cell_iterators())
          if (!specimen.deleted[cell->active_cell_index()])
            {
              cell->get_dof_indices(dofs);
              for (const auto i : dofs)
                used[i] = 1;
            }
        std::vector<types::global_dof_index> orphans;
        for (types::global_dof_index i = 0; i < used.size(); ++i)
          if (!used[i])
            orphans.push_back(i);
        return orphans;
      }

      unsigned int
      delete_cells(const SpecimenSettings &settings,
                   const Joints           &joints,
                   System                 &system,
                   Specimen               &specimen)
      {
        if (settings.deletion_strain <= 0)
          return 0;
        // maximum principal strain of the cell-averaged strain
        system.ghosted = system.u;
        QGauss<3>                                    quadrature(2);
        FEValues<3>                                  fe_values(system.fe,
                              quadrature,
                              update_gradients | update_JxW_values);
        std::vector<SymmetricTensor<2, 3>>           eps(8);
        const FEValuesExtractors::Vector             displacement(0);
        std::vector<std::pair<double, unsigned int>> candidates;
        for (const auto &cell : system.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() &&
              !specimen.deleted[cell->active_cell_index()])
            {
              fe_values.reinit(cell);
              fe_values[displacement].get_function_symmetric_gradients(
                system.ghosted, eps);
              SymmetricTensor<2, 3> mean;
              double                volume = 0;
              for (unsigned int q = 0; q < 8; ++q)
                {
                  mean += eps[q] * fe_values.JxW(q);
                  volume += fe_values.JxW(q);
                }
              mean /= volume;
              const double e1 = eigenvalues(mean)[0];
              if (e1 > settings.deletion_strain)
                candidates.emplace_back(e1, cell->active_cell_index());
            }
        // the same decision on every rank: largest strains first, capped
        std::vector<std::pair<double, unsigned int>> all;
        for (const auto &part :
             Utilities::MPI::all_gather(system.comm, candidates))
          all.insert(all.end(), part.begin(), part.end());
        std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
          return a.first > b.first ||
                 (a.first == b.first && a.second < b.second);
        });
        if (all.size() > settings.max_deletions)
          all.resize(settings.max_deletions);
        if (all.empty())
          return 0;
        for (const auto &c : all)
          specimen.deleted[c.second] = 1;
        specimen.n_deleted += all.size();
        // joints at a deleted cell go with it
        for (unsigned int i = 0; i < joints.faces.size(); ++i)
          if (specimen.deleted[joints.faces[i].cell_a] ||
              specimen.deleted[joints.faces[i].cell_b])
            specimen.face_deleted[i] = 1;
        // DOFs that no remaining cell holds stay where they are
        system.orphans = orphan_dofs(system, specimen);
        system.make_constraints();
        return all.size();
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
