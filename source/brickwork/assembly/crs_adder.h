/**
 * @file
 * Sums of element matrices into the tangent by precomputed positions in
 * its CRS storage.
 */
#ifndef masonry_brickwork_model_crs_adder_h
#define masonry_brickwork_model_crs_adder_h

#include <deal.II/lac/full_matrix.h>

#include <vector>

#include "system.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /**
       * Adds element matrices into system.matrix as
       * AffineConstraints::distribute_local_to_global() does with the
       * zero constraints (lines without entries): the same additions of
       * the same numbers (zeros left out; a constrained DoF's row and
       * column dropped and its diagonal given |k_ii|, or the mean |k_ii|
       * where k_ii = 0), so the matrix is the same bit for bit. The
       * sparsity never changes, so where each entry of an element goes in
       * the CRS values is found once per element instead of by searches
       * of global indices in every assembly. An element with a row on
       * another rank, or any case this does not cover, goes through
       * distribute_local_to_global().
       */
      class CrsAdder
      {
      public:
        /** Elements of two kinds, each numbered from 0. */
        enum Kind
        {
          cell  = 0,
          joint = 1
        };

        /** Before an assembly into system.matrix: where its values are
         * and which DoFs are constrained. */
        void
        prepare(System &system);

        /** Adds @p k of element @p index of @p kind, whose DoFs are
         * @p dofs (24). */
        void
        add(const Kind                                          kind,
            const unsigned int                                  index,
            const dealii::FullMatrix<double>                   &k,
            const std::vector<dealii::types::global_dof_index> &dofs);

      private:
        /** Where an element's entries go. */
        struct Positions
        {
          /** positions[24 i + j]: of entry (i, j) in the CRS values (-1:
           * not in the sparsity). */
          std::vector<int> positions;
          /** Every entry is in the sparsity. */
          bool complete = false;
          /** A row is on another rank (or the storage is not one array):
           * distribute_local_to_global(). */
          bool fallback = false;
        };

        void
        find(const std::vector<dealii::types::global_dof_index> &dofs,
             Positions                                          &p) const;

        System *system = nullptr;
        /** The matrix's values (all rows in one array); nullptr: not
         * usable, every element goes through the constraints. */
        double           *values  = nullptr;
        const int        *offsets = nullptr, *indices = nullptr;
        std::vector<char> constrained;
        std::vector<std::vector<Positions>> elements =
          std::vector<std::vector<Positions>>(2);
      };
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
