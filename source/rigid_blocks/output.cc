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
      const auto &patches = model.geometry().patches();
      for (unsigned int b = 0; b < model.blocks().size(); ++b)
        {
          const Block &block = model.blocks()[b];
          for (const auto &[uv, w] : model.quadrature(b))
            {
              const auto   ts = patches[block.patch].tangents(uv);
              const double dA =
                dealii::cross_product_3d(ts[0], ts[1]).norm() * w;
              const dealii::Point<3> x    = patches[block.patch].point(uv);
              const double           load = q.value(x);
              if (load == 0)
                continue;
              dealii::Tensor<1, 3> f;
              f[2] = -load * dA;
              force[b] += f;
              moment[b] += dealii::cross_product_3d(x - block.centroid, f);
            }
        }
    }

  } // namespace rigid_blocks
} // namespace masonry
