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

#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/law_set.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/fe_values.h>

#include "../assembly/point_states.h"
#include "../assembly/system.h"
#include "../specimen/joints.h"
#include "../specimen/specimen.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** Element deletion (`Deletion strain', `Deletion fade opening',
       * `Deletion crushing length', `Deletion stress', `Maximum deletions
       * per step'). */
      struct DeletionSettings
      {
        /** Remove cells whose maximum principal strain exceeds
         * deletion_strain after a converged step (0: never). */
        double deletion_strain = 0;
        /** Past deletion_strain a cell fades out: its stress and stiffness
         * are scaled by 1 - (e1 - deletion_strain) l / deletion_fade_opening
         * (l: its crack-band length, BrickPoint::characteristic_length, e1:
         * the largest cell-averaged principal strain so far), and it is
         * deleted when the factor reaches 0, m (0: deleted at once). */
        double deletion_fade_opening = 0;
        /** Past deletion_strain a cell also fades with its shortening since
         * then: the factor is at most 1 - (s - s_split) l /
         * deletion_crushing_length (s: largest compressive principal strain
         * of the cell), m (0: no crushing fade). */
        double deletion_crushing_length = 0;
        /** A cell past deletion_strain (or at the end of its fade) is
         * deleted only when the largest absolute principal value of its
         * cell-averaged stress is at most this, Pa: a cell that still
         * carries load stays (0: no such condition). */
        double deletion_stress = 0;
        /** At most this many cells are deleted after one step. */
        unsigned int max_deletions = 10;

        /** Declare the entries in the present subsection. */
        static void
        declare_parameters(dealii::ParameterHandler &prm);
        /** Read them. */
        void
        parse_parameters(dealii::ParameterHandler &prm);
      };

      /** The converged step a deletion follows (DeletedCell). */
      struct DeletionStep
      {
        unsigned int number    = 0;
        unsigned int cycle     = 0;
        bool         unloading = false;
      };

      /**
       * Delete the cells over the threshold (at most the cap), the joints
       * at them, and constrain the DOFs no remaining cell holds (into
       * system.orphans and its constraints); how many cells. With
       * `Deletion fade opening' > 0 the cells past the threshold fade out
       * first (Specimen::fade) and are deleted at the end of the fade;
       * with `Deletion stress' > 0 a cell is deleted only once the largest
       * absolute principal value of its cell-averaged stress (of
       * the cells' laws at their converged @p states) is at most that;
       * @p faded: how many fade factors changed. Each deleted cell, with
       * @p step and what it carried, goes into Specimen::deletions.
       */
      unsigned int
      delete_cells(const DeletionSettings &settings,
                   const Joints           &joints,
                   const LawSet           &laws,
                   const LawStates        &states,
                   System                 &system,
                   Specimen               &specimen,
                   const DeletionStep     &step,
                   unsigned int           &faded);

      /** The cell-averaged stress (Pa) of cell @p cell (its fade
       * included) at the displacement @p ghosted: the stress of each
       * point from its converged state in @p states at the converged
       * strain, as solution.pvd shows it. */
      dealii::SymmetricTensor<2, 3>
      cell_stress(const dealii::DoFHandler<3>::active_cell_iterator &cell,
                  const System::Vector                              &ghosted,
                  const LawSet                                      &laws,
                  const LawStates                                   &states,
                  const Specimen                                    &specimen,
                  dealii::FEValues<3>                               &fe_values);

      /**
       * The stress of brick point @p q of cell @p c at the strain @p eps
       * by the law of its region from its converged state (the initial one
       * for a linear law), with the cell's length and strength factor and
       * the step's
       * nonlocal factors (Specimen::nonlocal_factors): the stress the
       * step left, no further loading, without the cell's fade. What the
       * deletion and the output (solution.pvd) read.
       */
      dealii::SymmetricTensor<2, 3>
      converged_stress(const LawSet                        &laws,
                       const dealii::SymmetricTensor<2, 3> &eps,
                       const LawStates                     &states,
                       const Specimen                      &specimen,
                       const unsigned int                   c,
                       const unsigned int                   q);

      /**
       * No brick or mortar cell of a small-strain model means anything at
       * a strain of this (1000 %: a cell eleven times its length): a
       * solution with a remaining cell strained beyond it is a mechanism
       * of the damaged structure (nearly free parts moved without bound),
       * not a state of the wallette. Not 100 %: the squeezed mortar of a
       * weak joint flows steadily to 100 % at a nominal strain of 0.015
       * (tests/brickwork_detailed_band), while the runaway of the double
       * cyclic example grows by 15-25 % a step
       * (doc/notes/implex-step-control.md).
       */
      constexpr double mechanism_strain = 10;

      /** The largest absolute principal value of the cell-averaged strain
       * over the remaining cells at the displacement system.u (all
       * ranks; updates system.ghosted). */
      double
      largest_cell_strain(System &system, const Specimen &specimen);

      /** Empty if largest_cell_strain() is at most mechanism_strain, else
       * the reason, one line. */
      std::string
      mechanism_problem(System &system, const Specimen &specimen);

      /** The DOFs in no remaining cell of @p specimen. */
      std::vector<dealii::types::global_dof_index>
      orphan_dofs(const System &system, const Specimen &specimen);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
