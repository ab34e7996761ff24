/**
 * @file
 * The IMPL-EX floor correction (`IMPL-EX floor correction = iterate'): a
 * step at `IMPL-EX minimum step' whose damage error is over `IMPL-EX
 * damage tolerance' is solved again with the states of its own update
 * frozen (not extrapolated), updated at the new displacements, and so on
 * until the update changes no damage by more than the tolerance (a
 * fixed-point iteration towards the implicit solution of the step;
 * doc/brickwork.md, IMPL-EX floor correction). With `iterate at any step'
 * a step of any size is corrected so, and redone smaller only when its
 * correction does not converge.
 */
#ifndef masonry_brickwork_model_floor_correction_h
#define masonry_brickwork_model_floor_correction_h

#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>

#include <deal.II/base/conditional_ostream.h>

#include <string>

#include "integrator.h"
#include "point_states.h"
#include "step_control.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** The points' states with their laws (the splitting law nullptr:
       * none). */
      struct CorrectedStates
      {
        PointStates         &bricks, &joints, &splitting;
        const BrickMaterial &material;
        const InterfaceLaw  &law;
        const InterfaceLaw  *splitting_law;
      };

      /** Passes of one correction at most; then the step is kept. */
      constexpr unsigned int max_correction_passes = 30;

      /** The correction of the present step, driven by the step loop. */
      class FloorCorrection
      {
      public:
        FloorCorrection(const CorrectedStates      &states,
                        Integrator                 &integrator,
                        StepSizeControl            &control,
                        const double                tolerance,
                        const MPI_Comm              comm,
                        dealii::ConditionalOStream &pcout);

        /** Whether the present solve is a pass of a correction. */
        bool
        active() const
        {
          return integrator.get_mode() == Integrator::Mode::frozen;
        }

        /** Whether a step judged `correct' is corrected (not if its
         * correction failed: then the IMPL-EX step is kept). */
        bool
        wanted() const
        {
          return !failed_here;
        }

        /** Start the correction of the step just solved (damage error
         * @p error): its updated states are frozen. @p may_redo: a
         * correction that does not converge within max_passes_above_floor
         * passes, or fails, ends in a smaller step (`IMPL-EX floor
         * correction = iterate at any step', above the floor). */
        void
        start(const double error, const bool may_redo);

        /** What follows a converged pass. */
        enum class Next
        {
          /** solve again */
          again,
          /** accept the step */
          accept,
          /** redo the step smaller */
          redo
        };

        /** A pass of the step of size @p taken converged and its states
         * were updated: what next (redo: progress.increment is set). */
        Next
        again(const double taken, Progress &progress);

        /** A pass did not converge (@p failure: why): back to IMPL-EX,
         * whose step is solved again and kept; or (may_redo) it is redone
         * smaller (progress.increment is set). */
        void
        fail(const std::string &failure,
             const double       taken,
             Progress          &progress);

        /** The step was accepted. */
        void
        accepted()
        {
          failed_here = false;
        }

      private:
        /** The largest change of a damage from the frozen to the updated
         * states, over all ranks. */
        double
        damage_change() const;
        void
        freeze();

        CorrectedStates             states;
        Integrator                 &integrator;
        StepSizeControl            &control;
        double                      tolerance;
        MPI_Comm                    comm;
        dealii::ConditionalOStream &pcout;
        unsigned int                passes      = 0;
        bool                        failed_here = false, may_redo = false;
      };
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
