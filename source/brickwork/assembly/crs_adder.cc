/**
 * @file
 * Element matrices into the CRS storage of the tangent.
 */
#include <deal.II/lac/trilinos_index_access.h>

#include "crs_adder.h"

#include <Epetra_CrsMatrix.h>
#include <cmath>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using namespace dealii;

      void
      CrsAdder::prepare(System &s)
      {
        system = &s;
        // (the values are written through the pointers, as Amesos does)
        auto &matrix =
          const_cast<Epetra_CrsMatrix &>(s.matrix.trilinos_matrix());
        int    *o = nullptr, *i = nullptr;
        double *v = nullptr;
        if (matrix.ExtractCrsDataPointers(o, i, v) != 0)
          v = nullptr;
        if (v != values || o != offsets || i != indices)
          for (auto &kind : elements)
            kind.clear();
        values  = v;
        offsets = o;
        indices = i;
        // the constraints change with deletions: read every assembly
        constrained.assign(s.dof_handler.n_dofs(), 0);
        for (const auto dof : s.relevant)
          if (s.zero_constraints.is_constrained(dof))
            {
              const auto *entries =
                s.zero_constraints.get_constraint_entries(dof);
              if ((entries != nullptr && !entries->empty()) ||
                  s.zero_constraints.is_inhomogeneously_constrained(dof))
                values = nullptr;
              constrained[dof] = 1;
            }
      }

      void
      CrsAdder::find(const std::vector<types::global_dof_index> &dofs,
                     Positions                                  &p) const
      {
        const Epetra_CrsMatrix &matrix = system->matrix.trilinos_matrix();
        p.positions.assign(dofs.size() * dofs.size(), -1);
        p.complete = true;
        p.fallback = false;
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const int row = matrix.RowMap().LID(
              static_cast<TrilinosWrappers::types::int_type>(dofs[i]));
            if (row < 0)
              {
                p.fallback = true;
                return;
              }
            for (unsigned int j = 0; j < dofs.size(); ++j)
              {
                const int col = matrix.ColMap().LID(
                  static_cast<TrilinosWrappers::types::int_type>(dofs[j]));
                for (int k = offsets[row]; col >= 0 && k < offsets[row + 1];
                     ++k)
                  if (indices[k] == col)
                    {
                      p.positions[dofs.size() * i + j] = k;
                      break;
                    }
                if (p.positions[dofs.size() * i + j] < 0)
                  p.complete = false;
              }
          }
      }

      void
      CrsAdder::add(const Kind                                  kind,
                    const unsigned int                          index,
                    const FullMatrix<double>                   &k,
                    const std::vector<types::global_dof_index> &dofs)
      {
        const unsigned int n = dofs.size();
        if (values == nullptr || n != 24)
          {
            system->zero_constraints.distribute_local_to_global(k,
                                                                dofs,
                                                                system->matrix);
            return;
          }
        auto &of_kind = elements[kind];
        if (of_kind.size() <= index)
          of_kind.resize(index + 1);
        Positions &p = of_kind[index];
        if (p.positions.empty())
          find(dofs, p);
        bool any_constrained = false;
        for (const auto dof : dofs)
          if (constrained[dof])
            any_constrained = true;
        // the entries this element adds must all be in the sparsity (a
        // zero is not added: a joint's entries between nodes that do not
        // face each other, with Lobatto points, are left out of it)
        bool usable = !p.fallback;
        if (usable && !p.complete)
          for (unsigned int i = 0; i < n && usable; ++i)
            for (unsigned int j = 0; j < n && usable; ++j)
              if ((constrained[dofs[i]] || constrained[dofs[j]] ?
                     i == j && constrained[dofs[i]] :
                     k(i, j) != 0.) &&
                  p.positions[n * i + j] < 0)
                usable = false;
        if (!usable)
          {
            system->zero_constraints.distribute_local_to_global(k,
                                                                dofs,
                                                                system->matrix);
            return;
          }
        const int *pos = p.positions.data();
        if (!any_constrained)
          {
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                if (k(i, j) != 0.)
                  values[pos[n * i + j]] += k(i, j);
            return;
          }
        for (unsigned int i = 0; i < n; ++i)
          if (!constrained[dofs[i]])
            for (unsigned int j = 0; j < n; ++j)
              if (!constrained[dofs[j]] && k(i, j) != 0.)
                values[pos[n * i + j]] += k(i, j);
        // set_matrix_diagonals() of deal.II
        double average = 0;
        for (unsigned int i = 0; i < n; ++i)
          average += std::abs(k(i, i));
        average /= static_cast<double>(n);
        if (average == 0.)
          {
            average = k.l1_norm() / static_cast<double>(n);
            if (average == 0.)
              average = 1.;
          }
        for (unsigned int i = 0; i < n; ++i)
          if (constrained[dofs[i]])
            values[pos[n * i + i]] +=
              std::abs(k(i, i)) != 0. ? std::abs(k(i, i)) : average;
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
