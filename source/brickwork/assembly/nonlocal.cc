/**
 * @file
 * The nonlocal average of the units' measures (see nonlocal.h).
 */
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>

#include "nonlocal.h"

#include <algorithm>
#include <map>

#include "one_thread.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using namespace dealii;

      NonlocalAverage::NonlocalAverage(const std::vector<Point<3>>     &x,
                                       const std::vector<double>       &volume,
                                       const std::vector<unsigned int> &group,
                                       const std::vector<char>         &mine,
                                       const double                     radius)
      {
        AssertThrow(radius > 0,
                    ExcMessage("Brick material: `Nonlocal length' must be "
                               "> 0 for a nonlocal average"));
        const unsigned int n = x.size();
        // the points of each group, so that a point searches its own unit
        std::map<unsigned int, std::vector<unsigned int>> members;
        for (unsigned int p = 0; p < n; ++p)
          if (group[p] != numbers::invalid_unsigned_int)
            members[group[p]].push_back(p);
        offsets.assign(n + 1, 0);
        const double R2 = radius * radius;
        for (unsigned int p = 0; p < n; ++p)
          {
            offsets[p + 1] = offsets[p];
            if (!mine[p] || group[p] == numbers::invalid_unsigned_int)
              continue;
            for (const unsigned int j : members[group[p]])
              {
                const double r2 = x[p].distance_square(x[j]);
                if (r2 >= R2)
                  continue;
                const double b = 1 - r2 / R2;
                neighbours.push_back(j);
                weights.push_back(b * b * volume[j]);
                ++offsets[p + 1];
              }
          }
      }

      double
      NonlocalAverage::average(const unsigned int         p,
                               const std::vector<double> &values,
                               const std::vector<char>   &alive) const
      {
        double sum = 0, weight = 0;
        for (unsigned int k = offsets[p]; k < offsets[p + 1]; ++k)
          if (alive[neighbours[k]])
            {
              sum += weights[k] * values[neighbours[k]];
              weight += weights[k];
            }
        return weight > 0 ? sum / weight : values[p];
      }

      NonlocalAverage
      make_unit_average(const DoFHandler<3> &dof_handler,
                        const Specimen      &specimen,
                        const double         radius)
      {
        const unsigned int n_cells =
          dof_handler.get_triangulation().n_active_cells();
        std::vector<Point<3>>     x(8 * n_cells);
        std::vector<double>       volume(8 * n_cells);
        std::vector<unsigned int> group(8 * n_cells,
                                        numbers::invalid_unsigned_int);
        std::vector<char>         mine(8 * n_cells, 0);
        // the same points on one assembly thread as on many (OneThread)
        const OneThread one_thread;
        FEValues<3>     fe_values(dof_handler.get_fe(),
                              QGauss<3>(2),
                              update_quadrature_points | update_JxW_values);
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            const unsigned int c = cell->active_cell_index();
            if (specimen.cell_region[c] != 0)
              continue;
            fe_values.reinit(cell);
            for (unsigned int q = 0; q < 8; ++q)
              {
                x[8 * c + q]      = fe_values.quadrature_point(q);
                volume[8 * c + q] = fe_values.JxW(q);
                group[8 * c + q]  = cell->material_id();
                mine[8 * c + q]   = cell->is_locally_owned();
              }
          }
        return NonlocalAverage(x, volume, group, mine, radius);
      }

      std::array<std::vector<double>, 2>
      nonlocal_factors(const NonlocalAverage               &average,
                       const NonlocalMeasures              &material,
                       const MaterialStrengths             *strengths,
                       const DoFHandler<3>                 &dof_handler,
                       const TrilinosWrappers::MPI::Vector &ghosted,
                       const PointStates                   &bricks,
                       const Specimen                      &specimen,
                       MPI_Comm                             comm)
      {
        const unsigned int n = bricks.n_points();
        // tau_t of the points, then tau_c
        std::vector<double> local(2 * n, 0.), measure(2 * n);
        std::vector<char>   alive(n, 0);
        // the same strains on one assembly thread as on many (OneThread)
        const OneThread                    one_thread;
        FEValues<3>                        fe_values(dof_handler.get_fe(),
                              QGauss<3>(2),
                              update_gradients);
        std::vector<SymmetricTensor<2, 3>> eps(8);
        const FEValuesExtractors::Vector   displacement(0);
        BrickPoint                         point;
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            const unsigned int c = cell->active_cell_index();
            if (specimen.cell_region[c] != 0 || specimen.deleted[c])
              continue;
            for (unsigned int q = 0; q < 8; ++q)
              alive[8 * c + q] = 1;
            if (!cell->is_locally_owned())
              continue;
            fe_values.reinit(cell);
            fe_values[displacement].get_function_symmetric_gradients(ghosted,
                                                                     eps);
            for (unsigned int q = 0; q < 8; ++q)
              {
                const unsigned int          p = 8 * c + q;
                const std::array<double, 2> m =
                  material.nonlocal_measures(eps[q], bricks.old(p), point);
                local[p]     = m[0];
                local[n + p] = m[1];
              }
          }
        // every point's measures on every rank (set by its owner only)
        Utilities::MPI::sum(ArrayView<const double>(local),
                            comm,
                            ArrayView<double>(measure));
        std::array<std::vector<double>, 2> rho;
        const double                       floor[2] = {
                                strengths ? 1e-3 * strengths->tensile_strength() : 0.,
          strengths ? 1e-3 * strengths->compressive_strength() : 0.};
        for (unsigned int k = 0; k < 2; ++k)
          {
            rho[k].assign(n, 1.);
            const std::vector<double> values(measure.begin() + k * n,
                                             measure.begin() + (k + 1) * n);
            for (const auto &cell : dof_handler.active_cell_iterators())
              {
                const unsigned int c = cell->active_cell_index();
                if (!cell->is_locally_owned() || !alive[8 * c])
                  continue;
                for (unsigned int q = 0; q < 8; ++q)
                  {
                    const unsigned int p = 8 * c + q;
                    if (values[p] > 0)
                      rho[k][p] = average.average(p, values, alive) /
                                  std::max(values[p], floor[k]);
                  }
              }
          }
        return rho;
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
