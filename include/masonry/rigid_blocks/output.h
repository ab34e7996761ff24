/**
 * @file
 * The motion of rigid blocks, surface loads on them and the output options
 * of the rigid-block analyses (the outputs themselves are postprocessors:
 * rigid_blocks/postprocess/interface.h).
 */
#ifndef masonry_rigid_blocks_output_h
#define masonry_rigid_blocks_output_h

#include <masonry/rigid_blocks/block_model.h>

#include <deal.II/base/function.h>

#include <functional>

namespace masonry
{
  namespace rigid_blocks
  {
    /** Motion of the ground at a support point with an edge label, m. */
    using SupportMotion =
      std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &,
                                         const std::string &)>;

    /** Rigid motion of every block: translation of the centroid (m) and
     * rotation (rad). */
    struct Motion
    {
      explicit Motion(const unsigned int n_blocks)
        : translation(n_blocks)
        , rotation(n_blocks)
      {}
      /** Translations of the centroids, m. */
      std::vector<dealii::Tensor<1, 3>> translation;
      /** Rotations, rad. */
      std::vector<dealii::Tensor<1, 3>> rotation;

      /** Displacement of point @p x of block @p b of @p model. */
      dealii::Tensor<1, 3>
      displacement(const BlockModel       &model,
                   const unsigned int      b,
                   const dealii::Point<3> &x) const;
    };

    /** What to write. */
    struct OutputOptions
    {
      /** Displacement factor in the deformed output (0: automatic). */
      double amplification = 0;
      /** Subdivisions per block and direction in the VTU. */
      unsigned int subdivisions = 4;
      /** Whether to render vault.png. */
      bool write_picture = true;
    };

    /**
     * Add to @p force and @p moment (about each centroid) the resultants of
     * a vertical load @p q (Pa, positive downwards) per unit area of the
     * middle surface.
     */
    void
    integrate_surface_load(const BlockModel                  &model,
                           const dealii::Function<3>         &q,
                           std::vector<dealii::Tensor<1, 3>> &force,
                           std::vector<dealii::Tensor<1, 3>> &moment);

  } // namespace rigid_blocks
} // namespace masonry

#endif
