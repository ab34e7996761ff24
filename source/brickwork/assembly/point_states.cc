/**
 * @file
 * Flat storage of point states.
 */
#include <deal.II/base/exceptions.h>

#include "point_states.h"

#include <algorithm>
#include <cmath>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      void
      PointStates::initialize(const unsigned int               n_points,
                              const std::vector<double>       &initial,
                              const std::vector<unsigned int> &points)
      {
        n     = initial.size();
        count = n_points;
        old_values.resize(n_points * n);
        for (unsigned int p = 0; p < n_points; ++p)
          std::copy(initial.begin(), initial.end(), old_values.begin() + p * n);
        new_values    = old_values;
        older_values  = old_values;
        frozen_values = old_values;
        checkpointed  = points;
      }

      void
      PointStates::keep(const unsigned int p)
      {
        std::copy_n(old_values.begin() + p * n, n, new_values.begin() + p * n);
      }

      void
      PointStates::accept(const unsigned int p, const bool keep_older)
      {
        if (keep_older)
          std::copy_n(old_values.begin() + p * n,
                      n,
                      older_values.begin() + p * n);
        std::copy_n(new_values.begin() + p * n, n, old_values.begin() + p * n);
      }

      double
      PointStates::largest_damage_change(const PointLaw &law) const
      {
        std::vector<double> a(law.damage_names().size()), b(a.size());
        double              change = 0;
        for (const unsigned int p : checkpointed)
          {
            law.damages(updated(p), dealii::make_array_view(a));
            law.damages(frozen(p), dealii::make_array_view(b));
            for (unsigned int k = 0; k < a.size(); ++k)
              {
                const double d = std::abs(a[k] - b[k]);
                if (!std::isfinite(d))
                  return d;
                change = std::max(change, d);
              }
          }
        return change;
      }

      std::vector<double>
      PointStates::gather() const
      {
        std::vector<double> data;
        data.reserve(2 * n * checkpointed.size());
        for (const unsigned int p : checkpointed)
          {
            data.insert(data.end(),
                        old_values.begin() + p * n,
                        old_values.begin() + (p + 1) * n);
            data.insert(data.end(),
                        older_values.begin() + p * n,
                        older_values.begin() + (p + 1) * n);
          }
        return data;
      }

      void
      PointStates::scatter(const std::vector<double> &data)
      {
        AssertThrow(data.size() == 2 * n * checkpointed.size(),
                    dealii::ExcMessage("the checkpoint holds point states of "
                                       "another size: resume with the same "
                                       "laws and parameters"));
        auto it = data.begin();
        for (const unsigned int p : checkpointed)
          {
            std::copy_n(it, n, old_values.begin() + p * n);
            std::copy_n(it, n, new_values.begin() + p * n);
            it += n;
            std::copy_n(it, n, older_values.begin() + p * n);
            it += n;
          }
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
