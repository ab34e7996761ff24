/**
 * @file
 * What makes one specimen of a series: the random strength factors of its
 * bricks and joints, the characteristic length of each cell, and the cells
 * and joints deleted so far.
 */
#ifndef masonry_brickwork_model_specimen_h
#define masonry_brickwork_model_specimen_h

#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/curve.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <vector>

#include "joints.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** The strength scatter of a specimen (`Strength scatter', `Random
       * seed'). */
      struct SpecimenSettings
      {
        /** Coefficient of variation of the strengths of bricks and joints
         * (a normal factor per brick and per joint, cut at 0.2 and 1.8). */
        double strength_scatter = 0;
        /** Seed of the random strength factors. */
        unsigned int seed = 1;

        /** Declare the entries in the present subsection. */
        static void
        declare_parameters(dealii::ParameterHandler &prm);
        /** Read them. */
        void
        parse_parameters(dealii::ParameterHandler &prm);
      };

      /** Per cell and per joint face data of a specimen. */
      struct Specimen
      {
        /** Per active cell: crack-band length (m; a unit cell's cube root
         * of its volume, a mortar cell's size across its layer: its height
         * in a bed joint, the smaller horizontal side in a head or collar
         * joint), strength factor. */
        std::vector<double> cell_length, cell_factor;
        std::vector<char>   deleted;
        /** Per active cell: the factor on its stress and stiffness while
         * it fades out before deletion (`Deletion fade opening'; 1:
         * intact). */
        std::vector<double> fade;
        /** Per active cell: its shortening (largest compressive principal
         * strain) when it passed `Deletion strain', the origin of its
         * crushing fade (`Deletion crushing length'); -1: not yet. */
        std::vector<double> split_shortening;
        /** Per active cell: the largest shortening it has had (with
         * `Deletion crushing length' > 0). */
        std::vector<double> max_shortening;
        /** Per active cell: its region, the key of its law in the LawSet
         * (0 unit, 1 mortar: the cells of material id n_bricks in the
         * detailed model). */
        std::vector<unsigned char> cell_region;
        /** Per joint face: strength factor, deleted. */
        std::vector<double> face_factor;
        std::vector<char>   face_deleted;
        /** Cells deleted so far. */
        unsigned int n_deleted = 0;
        /** The deleted cells in the order they went (deletions.csv). */
        std::vector<DeletedCell> deletions;
        /** Per brick point (8 c + q): the units' nonlocal factors of the
         * last IMPL-EX update (BrickPoint::tensile_factor, then
         * compressive_factor; `Nonlocal length'), so that the deletion
         * and the output evaluate the law at the converged state as the
         * step did; empty: local. Checkpointed: a resumed run that stops
         * before its first accepted step writes its output with them
         * (they cannot be recomputed from the accepted states). */
        std::array<std::vector<double>, 2> nonlocal_factors;

        /** The factors of brick point @p p into @p point (nothing if
         * local). */
        void
        apply_nonlocal_factors(const unsigned int p, BrickPoint &point) const
        {
          if (nonlocal_factors[0].empty())
            return;
          point.tensile_factor     = nonlocal_factors[0][p];
          point.compressive_factor = nonlocal_factors[1][p];
        }

        /** Write or read the deletions and the nonlocal factors (the
         * strength factors follow from the settings). */
        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          ar &n_deleted &deleted &face_deleted &fade &split_shortening
              &max_shortening &nonlocal_factors[0] &
            nonlocal_factors[1] & deletions;
        }
      };

      /**
       * The specimen of @p settings: a factor 1 + CoV N(0, 1), cut to
       * [0.2, 1.8], per brick (in brick order), then per joint (brick
       * pair, in pair order), then one for the mortar cells of the detailed
       * model (material id @p n_bricks), drawn from the seed; nothing
       * deleted.
       */
      Specimen
      make_specimen(const dealii::Triangulation<3> &triangulation,
                    const unsigned int              n_bricks,
                    const Joints                   &joints,
                    const SpecimenSettings         &settings);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
