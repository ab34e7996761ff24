/**
 * @file
 * The nonlocal average of the units' tensile and compressive measures
 * (`Nonlocal length' of the unit's law, BrickPoint::tensile_factor,
 * compressive_factor): every unit point's value is
 * replaced by the average over the points of the same unit (cells of the
 * same material id, region 0) within the radius R, weighted by the bell
 * function w(r) = (1 - r^2 / R^2)^2 (Bazant & Jirasek 2002) times the
 * points' volumes (JxW), normalised by the sum of those weights (so a
 * uniform field is unchanged, and a linear field's average at a point whose
 * sphere lies inside the unit is its value). Deleted cells take no part.
 * The triangulation is shared: every rank knows every point's position, so
 * the neighbour lists and weights of the points of this rank's cells are
 * computed once; the measures are summed over the ranks (each point is set
 * by the rank that owns it) before the average, so the result does not
 * depend on the partition.
 */
#ifndef masonry_brickwork_model_nonlocal_h
#define masonry_brickwork_model_nonlocal_h

#include <masonry/brickwork/brick_material.h>

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <mpi.h>

#include "../specimen/specimen.h"
#include "point_states.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** Neighbour lists and weights of the nonlocal average. */
      class NonlocalAverage
      {
      public:
        /**
         * Points @p x with volumes @p volume; @p group: the unit of each
         * point (points average only within their group;
         * numbers::invalid_unsigned_int: no average, e.g. mortar);
         * @p mine: the points whose neighbour lists this rank keeps;
         * @p radius R, m (> 0).
         */
        NonlocalAverage(const std::vector<dealii::Point<3>> &x,
                        const std::vector<double>           &volume,
                        const std::vector<unsigned int>     &group,
                        const std::vector<char>             &mine,
                        const double                         radius);

        /**
         * The average at point @p p (one of mine, in a group) of
         * @p values (one per point), over the neighbours j with
         * @p alive[j] (p itself is always alive here).
         */
        double
        average(const unsigned int         p,
                const std::vector<double> &values,
                const std::vector<char>   &alive) const;

        /** Number of neighbours of point @p p (itself included). */
        unsigned int
        n_neighbours(const unsigned int p) const
        {
          return offsets[p + 1] - offsets[p];
        }

      private:
        /** CSR lists: the neighbours of point p are entries offsets[p] to
         * offsets[p + 1] of neighbours and weights (w(r) JxW). */
        std::vector<unsigned int> offsets, neighbours;
        std::vector<double>       weights;
      };

      /**
       * The nonlocal average of the unit points (QGauss(2), 8 per active
       * cell, index 8 c + q) of @p dof_handler's shared triangulation with
       * radius @p radius, m.
       */
      NonlocalAverage
      make_unit_average(const dealii::DoFHandler<3> &dof_handler,
                        const Specimen              &specimen,
                        const double                 radius);

      /**
       * BrickPoint::tensile_factor and compressive_factor of every point of
       * this rank's unit cells (8 per active cell, 1 elsewhere) at the
       * displacements @p ghosted (every entry on every rank): rho = average
       * / max(local, 1e-3 f) of each of @p material's nonlocal_measures()
       * from the converged states (f: f_t, f_c of @p strengths; 0 without
       * them). The measures are summed
       * over the ranks of @p comm (collective).
       */
      std::array<std::vector<double>, 2>
      nonlocal_factors(const NonlocalAverage                       &average,
                       const NonlocalMeasures                      &material,
                       const MaterialStrengths                     *strengths,
                       const dealii::DoFHandler<3>                 &dof_handler,
                       const dealii::TrilinosWrappers::MPI::Vector &ghosted,
                       const PointStates                           &bricks,
                       const Specimen                              &specimen,
                       MPI_Comm                                     comm);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
