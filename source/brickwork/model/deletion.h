/**
 * @file
 * Element deletion: after a converged step, the cells whose cell-averaged
 * largest principal strain exceeds `Deletion strain' are removed, the
 * largest first, the same decision on every rank; or, with a fade
 * opening, they first fade out over that lateral opening (crack band: the
 * fade strain is the opening / the cell size) and are deleted when they
 * carry nothing.
 */
#ifndef masonry_brickwork_model_deletion_h
#define masonry_brickwork_model_deletion_h

#include <masonry/brickwork/wallette.h>

#include "joints.h"
#include "specimen.h"
#include "system.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /**
       * Delete the cells over the threshold (at most the cap), the joints
       * at them, and constrain the DOFs no remaining cell holds (into
       * system.orphans and its constraints); how many cells. With
       * `Deletion fade opening' > 0 the cells past the threshold fade out
       * first (Specimen::fade) and are deleted at the end of the fade;
       * @p faded: how many fade factors changed.
       */
      unsigned int
      delete_cells(const SpecimenSettings &settings,
                   const Joints           &joints,
                   System                 &system,
                   Specimen               &specimen,
                   unsigned int           &faded);

      /** The DOFs in no remaining cell of @p specimen. */
      std::vector<dealii::types::global_dof_index>
      orphan_dofs(const System &system, const Specimen &specimen);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
