#include <masonry/geometry/interface.h>
#include <masonry/rigid_blocks/output.h>

#include <deal.II/base/quadrature_lib.h>

#include <cmath>

namespace masonry
{
  namespace rigid_blocks
  {
    dealii::Tensor<1, 3>
    Motion::displacement(const BlockModel       &model,
                         const unsigned int      b,
                         const dealii::Point<3> &x) const
    {
      return rigid_motion(translation[b],
                          rotation[b],
                          model.blocks()[b].centroid,
                          x);
    }

    void
    integrate_surface_load(const BlockModel                  &model,
                           const dealii::Function<3>         &q,
                           std::vector<dealii::Tensor<1, 3>> &force,
                           std::vector<dealii::Tensor<1, 3>> &moment)
    {
      for (unsigned int b = 0; b < model.blocks().size(); ++b)
        {
          const Block &block = model.blocks()[b];
          for (const auto &sample : model.surface_samples(b))
            {
              const dealii::Point<3> &x    = sample.point;
              const double            load = q.value(x);
              if (load == 0)
                continue;
              const auto  &ts = sample.tangents;
              const double dA =
                dealii::cross_product_3d(ts[0], ts[1]).norm() * sample.weight;
              dealii::Tensor<1, 3> f;
              f[2] = -load * dA;
              force[b] += f;
              moment[b] += dealii::cross_product_3d(x - block.centroid, f);
            }
        }
    }

  } // namespace rigid_blocks
} // namespace masonry
