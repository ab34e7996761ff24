/**
 * @file
 * Results of rigid-block analyses: crack list, interface forces, VTU/PVD
 * files and a picture.
 */
#ifndef masonry_rigid_blocks_output_h
#define masonry_rigid_blocks_output_h

#include <masonry/core/run_context.h>
#include <masonry/rigid_blocks/block_model.h>

#include <deal.II/base/function.h>

#include <functional>

namespace masonry
{
  namespace rigid_blocks
  {
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

    /**
     * Write the results of a solved rigid-block problem: the crack list
     * into the summary, interface_forces.csv (@p forces: per contact point
     * normal, across and along forces, N, compression positive),
     * blocks.csv (centroid, translation and rotation of every block, full
     * precision), blocks.vtu, interfaces.vtu, vault.pvd and vault.png.
     * @p settlement gives the ground motion at a support point with a
     * label.
     */
    void
    write_results(
      const BlockModel &model,
      const Motion     &motion,
      const std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &,
                                               const std::string &)>
                                               &settlement,
      const std::vector<std::array<double, 3>> &forces,
      const OutputOptions                      &options,
      RunContext                               &context);
  } // namespace rigid_blocks
} // namespace masonry

#endif
