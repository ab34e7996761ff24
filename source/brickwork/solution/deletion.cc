/**
 * @file
 * Element deletion.
 */
#include <masonry/core/parameters.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include "deletion.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "../assembly/one_thread.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using namespace dealii;

      namespace
      {
        /** The factor of a cell at the end of its fade that waits for its
         * deletion (the cap per step): small, but keeps its nodes held. */
        constexpr double fade_floor = 1e-3;
      } // namespace

      void
      DeletionSettings::declare_parameters(ParameterHandler &prm)
      {
        using Patterns::Double;
        using Patterns::Integer;
        declare_ranged_entry(
          prm,
          "Deletion strain",
          "0",
          {0, 10, "(dimensionless)"},
          "Element deletion: after a converged step, cells whose maximum "
          "principal strain (of the cell-averaged strain, dimensionless) "
          "exceeds this are removed from the model, the largest first, at "
          "most `Maximum deletions per step' at a time; joints at a deleted "
          "cell go with it, and nodes left without a cell are held where "
          "they are. 0: no deletion. Deleted cells are flagged in "
          "solution.pvd (`deleted') and counted in curve.csv.");
        declare_ranged_entry(
          prm,
          "Deletion fade opening",
          "0",
          {0, 1, "m"},
          "Gradual deletion, m (>= 0): a cell past `Deletion strain' fades "
          "out instead of going at once: its stress and stiffness are "
          "scaled by 1 - (e1 - Deletion strain) l / this, with e1 the "
          "largest cell-averaged principal strain it has reached and l its "
          "crack-band length (the cube root of its volume; a mortar cell: "
          "its size across the layer) (crack band: the fade ends at the same "
          "lateral opening whatever the mesh); it is deleted when the "
          "factor reaches 0, then carrying nothing. 0: deleted at once. "
          "The fade of every cell is written to solution.pvd (`fade').");
        declare_ranged_entry(
          prm,
          "Deletion crushing length",
          "0",
          {0, 1, "m"},
          "Crushing of split cells, m (>= 0): a cell past `Deletion "
          "strain' (split) also fades with its shortening since then: its "
          "factor is at most 1 - (s - s_split) l / this, with s the largest "
          "compressive principal strain of the cell, s_split its value when "
          "the cell passed `Deletion strain' and l its crack-band length "
          "(the cube root of its volume; a mortar cell: its size across "
          "the layer) (crack band: the split column crushes over this "
          "shortening whatever the mesh; a cell at stress f fading linearly "
          "dissipates f x this / 2 per unit area, so 2 G_fc / f_b gives the "
          "unit's compressive fracture energy); it is deleted when the "
          "factor reaches 0. 0: no crushing fade.");
        declare_ranged_entry(
          prm,
          "Deletion stress",
          "0",
          {0, 1e10, "Pa"},
          "Deletion only of cells that carry nothing, Pa (>= 0): a cell "
          "past `Deletion strain' (or at the end of its fade) is deleted "
          "only once the largest absolute principal value of its "
          "cell-averaged stress is at most this; until then it stays, "
          "whatever its strain. 0: no such condition (a cell goes when its "
          "strain passes the threshold, whatever it carries).");
        prm.declare_entry("Maximum deletions per step",
                          "10",
                          Integer(1, 100000),
                          "Cap of the cells deleted after one step.");
      }

      void
      DeletionSettings::parse_parameters(ParameterHandler &prm)
      {
        deletion_strain          = prm.get_double("Deletion strain");
        deletion_fade_opening    = prm.get_double("Deletion fade opening");
        deletion_crushing_length = prm.get_double("Deletion crushing length");
        deletion_stress          = prm.get_double("Deletion stress");
        max_deletions = prm.get_integer("Maximum deletions per step");
      }

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

      namespace
      {
        /** The volume average over @p cell of @p f(q, strain at q) at the
         * displacement @p ghosted (@p fe_values: gradients and JxW; @p eps:
         * scratch, one per quadrature point). */
        template <class Function>
        SymmetricTensor<2, 3>
        cell_average(const DoFHandler<3>::active_cell_iterator &cell,
                     const System::Vector                      &ghosted,
                     FEValues<3>                               &fe_values,
                     std::vector<SymmetricTensor<2, 3>>        &eps,
                     const Function                            &f)
        {
          fe_values.reinit(cell);
          fe_values[FEValuesExtractors::Vector(0)]
            .get_function_symmetric_gradients(ghosted, eps);
          SymmetricTensor<2, 3> mean;
          double                volume = 0;
          for (unsigned int q = 0; q < eps.size(); ++q)
            {
              mean += f(q, eps[q]) * fe_values.JxW(q);
              volume += fe_values.JxW(q);
            }
          return mean / volume;
        }

        /** The volume average of the strain over @p cell (cell_average()). */
        SymmetricTensor<2, 3>
        mean_strain(const DoFHandler<3>::active_cell_iterator &cell,
                    const System::Vector                      &ghosted,
                    FEValues<3>                               &fe_values,
                    std::vector<SymmetricTensor<2, 3>>        &eps)
        {
          return cell_average(cell,
                              ghosted,
                              fe_values,
                              eps,
                              [](unsigned int, const SymmetricTensor<2, 3> &e) {
                                return e;
                              });
        }
      } // namespace

      double
      largest_cell_strain(System &system, const Specimen &specimen)
      {
        system.ghosted = system.u;
        FEValues<3>                        fe_values(system.fe,
                              QGauss<3>(2),
                              update_gradients | update_JxW_values);
        std::vector<SymmetricTensor<2, 3>> eps(8);
        double                             largest = 0;
        for (const auto &cell : system.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() &&
              !specimen.deleted[cell->active_cell_index()])
            {
              const auto e =
                eigenvalues(mean_strain(cell, system.ghosted, fe_values, eps));
              largest = std::max({largest, std::abs(e[0]), std::abs(e[2])});
            }
        return Utilities::MPI::max(largest, system.comm);
      }

      std::string
      mechanism_problem(System &system, const Specimen &specimen)
      {
        const double strain = largest_cell_strain(system, specimen);
        if (strain <= mechanism_strain)
          return "";
        std::ostringstream m;
        m << std::fixed << std::setprecision(0)
          << "a remaining cell strained by " << strain * 100 << " % (over "
          << mechanism_strain * 100
          << " %): the damaged wallette is a mechanism";
        return m.str();
      }

      SymmetricTensor<2, 3>
      converged_stress(const LawSet                &laws,
                       const SymmetricTensor<2, 3> &eps,
                       const LawStates             &states,
                       const Specimen              &specimen,
                       const unsigned int           c,
                       const unsigned int           q)
      {
        const unsigned int   region   = specimen.cell_region[c];
        const BrickMaterial &material = laws.brick_law(region);
        const PointStates   &bricks   = states.bricks[region];
        std::vector<double>  initial(bricks.n_values()),
          scratch(bricks.n_values());
        const bool linear = material.is_linear();
        if (linear)
          material.initial_state(initial);
        BrickPoint point;
        point.characteristic_length = specimen.cell_length[c];
        point.strength_factor       = specimen.cell_factor[c];
        // the factors the step evaluated the law with: with the local
        // measures instead, a point that the average keeps inside its
        // envelope would crack or crush here
        specimen.apply_nonlocal_factors(8 * c + q, point);
        SymmetricTensor<2, 3> sigma;
        material.update_state(eps,
                              linear ?
                                ConstStateView(initial.data(), initial.size()) :
                                bricks.old(8 * c + q),
                              point,
                              StateView(scratch.data(), scratch.size()),
                              sigma);
        return sigma;
      }

      SymmetricTensor<2, 3>
      cell_stress(const DoFHandler<3>::active_cell_iterator &cell,
                  const System::Vector                      &ghosted,
                  const LawSet                              &laws,
                  const LawStates                           &states,
                  const Specimen                            &specimen,
                  FEValues<3>                               &fe_values)
      {
        const unsigned int                 c = cell->active_cell_index();
        std::vector<SymmetricTensor<2, 3>> eps(fe_values.n_quadrature_points);
        return specimen.fade[c] *
               cell_average(
                 cell,
                 ghosted,
                 fe_values,
                 eps,
                 [&](const unsigned int q, const SymmetricTensor<2, 3> &e) {
                   return converged_stress(laws, e, states, specimen, c, q);
                 });
      }

      namespace
      {
        /** One rank's findings of delete_cells() among its cells: pairs of
         * a value and an active cell index. */
        struct CellScan
        {
          /** The new fade factors (dimensionless), the shortenings of the
           * cells that split now (their largest shortening so far) and the
           * cells' largest shortenings that grew (compressive principal
           * strains, dimensionless). */
          std::vector<std::pair<double, unsigned int>> fades, splits,
            shortenings;
          /** The cells to delete (before the cap per step). */
          std::vector<DeletedCell> candidates;
        };

        /** The cell as a candidate: what it carries (its cell-averaged
         * stress) with it. @p e1: the largest principal value of its
         * cell-averaged strain (dimensionless); returns the DeletedCell
         * (its stress in Pa, fade included) and the principal values of
         * that stress (Pa). */
        std::pair<DeletedCell, std::array<double, 3>>
        candidate_cell(const DoFHandler<3>::active_cell_iterator &cell,
                       const double                               e1,
                       const System::Vector                      &ghosted,
                       const LawSet                              &laws,
                       const LawStates                           &states,
                       const Specimen                            &specimen,
                       FEValues<3>                               &stress_values)
        {
          const unsigned int          c = cell->active_cell_index();
          const SymmetricTensor<2, 3> sigma =
            cell_stress(cell, ghosted, laws, states, specimen, stress_values);
          DeletedCell d;
          d.cell           = c;
          d.region         = specimen.cell_region[c];
          d.strain         = e1;
          const auto where = cell->center();
          for (unsigned int i = 0; i < 3; ++i)
            d.centre[i] = where[i];
          d.stress = {{sigma[0][0],
                       sigma[1][1],
                       sigma[2][2],
                       sigma[0][1],
                       sigma[1][2],
                       sigma[0][2]}};
          return std::make_pair(d, eigenvalues(sigma));
        }

        /** The fade factor (dimensionless, at most 1; <= 0: faded out) of
         * cell @p c whose cell-averaged strain has the principal values
         * @p e, with `Deletion fade opening' or `Deletion crushing length';
         * @p split: whether the cell has split before. A cell that splits
         * now is added to @p splits with its largest shortening. */
        double
        fade_factor(const DeletionSettings                       &settings,
                    const Specimen                               &specimen,
                    const unsigned int                            c,
                    const std::array<double, 3>                  &e,
                    const bool                                    split,
                    std::vector<std::pair<double, unsigned int>> &splits)
        {
          const double opening  = settings.deletion_fade_opening;
          const double crushing = settings.deletion_crushing_length;
          const double e1       = e[0];
          // the fade: linear in the opening past the threshold (the
          // strain over the crack band of the cell) and in the
          // shortening since the cell split, never back up
          const double l = specimen.cell_length[c];
          double       f = 1;
          if (opening > 0 && e1 > settings.deletion_strain)
            f = 1 - (e1 - settings.deletion_strain) * l / opening;
          if (crushing > 0)
            {
              // the largest shortening (compressive principal strain)
              // the cell has had: a cell that splits while unloaded
              // crushes only past the shortening it has already
              // carried
              const double shortening =
                std::max(-e[2], specimen.max_shortening[c]);
              if (!split)
                splits.emplace_back(shortening, c);
              const double since =
                split ? shortening - specimen.split_shortening[c] : 0.;
              f = std::min(f, 1 - std::max(since, 0.) * l / crushing);
            }
          return f;
        }

        /** One rank's scan of its remaining cells for delete_cells(): the
         * cells past `Deletion strain' (or split) that are to go, the fades
         * and the shortenings (the displacement: system.u). */
        CellScan
        scan_cells(const DeletionSettings &settings,
                   const LawSet           &laws,
                   const LawStates        &states,
                   System                 &system,
                   const Specimen         &specimen)
        {
          const double opening  = settings.deletion_fade_opening;
          const double crushing = settings.deletion_crushing_length;
          // maximum principal strain of the cell-averaged strain
          system.ghosted = system.u;
          QGauss<3>                          quadrature(2);
          FEValues<3>                        fe_values(system.fe,
                                quadrature,
                                update_gradients | update_JxW_values);
          FEValues<3>                        stress_values(system.fe,
                                    quadrature,
                                    update_gradients | update_JxW_values);
          std::vector<SymmetricTensor<2, 3>> eps(8);
          CellScan                           scan;
          for (const auto &cell : system.dof_handler.active_cell_iterators())
            if (cell->is_locally_owned() &&
                !specimen.deleted[cell->active_cell_index()])
              {
                const auto e = eigenvalues(
                  mean_strain(cell, system.ghosted, fe_values, eps));
                const double       e1 = e[0];
                const unsigned int c  = cell->active_cell_index();
                if (crushing > 0 && -e[2] > specimen.max_shortening[c])
                  scan.shortenings.emplace_back(-e[2], c);
                const bool split =
                  crushing > 0 && specimen.split_shortening[c] >= 0;
                if (e1 <= settings.deletion_strain && !split)
                  continue;
                // a cell that still carries more than `Deletion stress'
                // stays (its stress: the largest absolute principal value
                // of the cell average)
                auto consider = [&]() {
                  const auto [d, s] = candidate_cell(cell,
                                                     e1,
                                                     system.ghosted,
                                                     laws,
                                                     states,
                                                     specimen,
                                                     stress_values);
                  if (settings.deletion_stress <= 0 ||
                      std::max(std::abs(s[0]), std::abs(s[2])) <=
                        settings.deletion_stress)
                    {
                      scan.candidates.push_back(d);
                      return true;
                    }
                  return false;
                };
                if (opening <= 0 && crushing <= 0)
                  {
                    consider();
                    continue;
                  }
                const double f =
                  fade_factor(settings, specimen, c, e, split, scan.splits);
                if (f <= 0 && consider())
                  continue;
                // the fade never goes back up
                if (f < specimen.fade[c])
                  scan.fades.emplace_back(f <= 0 ? fade_floor : f, c);
              }
          return scan;
        }

        /** Records the fades and shortenings that the ranks' @p scan found
         * in @p specimen on every rank; @p faded counts the faded cells. */
        void
        share_fades(const CellScan &scan,
                    const System   &system,
                    Specimen       &specimen,
                    unsigned int   &faded)
        {
          for (const auto &part :
               Utilities::MPI::all_gather(system.comm, scan.shortenings))
            for (const auto &[shortening, c] : part)
              specimen.max_shortening[c] = shortening;
          for (const auto &part :
               Utilities::MPI::all_gather(system.comm, scan.splits))
            for (const auto &[shortening, c] : part)
              specimen.split_shortening[c] = std::max(shortening, 0.);
          for (const auto &part :
               Utilities::MPI::all_gather(system.comm, scan.fades))
            for (const auto &[f, c] : part)
              {
                specimen.fade[c] = f;
                ++faded;
              }
        }

        /** The cells to delete, the same on every rank: the ranks'
         * @p candidates, largest strains first, at most `Maximum deletions
         * per step' (those over the cap wait at the fade floor, counted in
         * @p faded). */
        std::vector<DeletedCell>
        choose_cells(const std::vector<DeletedCell> &candidates,
                     const DeletionSettings         &settings,
                     const System                   &system,
                     Specimen                       &specimen,
                     unsigned int                   &faded)
        {
          // the same decision on every rank: largest strains first, capped
          std::vector<DeletedCell> all;
          for (const auto &part :
               Utilities::MPI::all_gather(system.comm, candidates))
            all.insert(all.end(), part.begin(), part.end());
          std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
            return a.strain > b.strain ||
                   (a.strain == b.strain && a.cell < b.cell);
          });
          if (all.size() > settings.max_deletions)
            {
              // faded out but over the cap: nearly nothing until deleted
              for (unsigned int k = settings.max_deletions; k < all.size(); ++k)
                if (specimen.fade[all[k].cell] > fade_floor)
                  {
                    specimen.fade[all[k].cell] = fade_floor;
                    ++faded;
                  }
              all.resize(settings.max_deletions);
            }
          return all;
        }
      } // namespace

      unsigned int
      delete_cells(const DeletionSettings &settings,
                   const Joints           &joints,
                   const LawSet           &laws,
                   const LawStates        &states,
                   System                 &system,
                   Specimen               &specimen,
                   const DeletionStep     &step,
                   unsigned int           &faded)
      {
        faded = 0;
        if (settings.deletion_strain <= 0)
          return 0;
        // the same numbers on one assembly thread as on many (OneThread)
        const OneThread one_thread;
        const CellScan  scan =
          scan_cells(settings, laws, states, system, specimen);
        share_fades(scan, system, specimen, faded);
        std::vector<DeletedCell> all =
          choose_cells(scan.candidates, settings, system, specimen, faded);
        if (all.empty())
          return 0;
        for (auto &d : all)
          {
            specimen.deleted[d.cell] = 1;
            d.step                   = step.number;
            d.cycle                  = step.cycle;
            d.unloading              = step.unloading;
          }
        specimen.n_deleted += all.size();
        specimen.deletions.insert(specimen.deletions.end(),
                                  all.begin(),
                                  all.end());
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
