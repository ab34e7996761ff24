/**
 * @file
 * The IMPL-EX floor correction.
 */
#include <deal.II/base/mpi.h>

#include "floor_correction.h"

#include <algorithm>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      FloorCorrection::FloorCorrection(const CorrectedStates      &states,
                                       Integrator                 &integrator,
                                       StepSizeControl            &control,
                                       const double                tolerance,
                                       const MPI_Comm              comm,
                                       dealii::ConditionalOStream &pcout)
        : states(states)
        , integrator(integrator)
        , control(control)
        , tolerance(tolerance)
        , comm(comm)
        , pcout(pcout)
      {}

      void
      FloorCorrection::freeze()
      {
        states.bricks.freeze();
        states.joints.freeze();
        states.splitting.freeze();
      }

      double
      FloorCorrection::damage_change() const
      {
        double c = states.joints.largest_damage_change(states.law);
        if (!states.material.is_linear())
          c = std::max(c, states.bricks.largest_damage_change(states.material));
        if (states.splitting_law)
          c = std::max(
            c, states.splitting.largest_damage_change(*states.splitting_law));
        return dealii::Utilities::MPI::max(c, comm);
      }

      void
      FloorCorrection::start(const double error, const bool may_redo_step)
      {
        // from the IMPL-EX solution and its updated states
        freeze();
        integrator.set_mode(Integrator::Mode::frozen);
        passes   = 0;
        may_redo = may_redo_step;
        pcout << "  IMPL-EX: step solved again with its updated states "
                 "(damage error "
              << error << ")\n";
      }

      FloorCorrection::Next
      FloorCorrection::again(const double taken, Progress &progress)
      {
        const double change = damage_change();
        pcout << "  IMPL-EX: correction " << ++passes << ", damage change "
              << change << "\n";
        const unsigned int limit =
          may_redo ? max_passes_above_floor : max_correction_passes;
        if (change > tolerance && passes < limit)
          {
            freeze();
            return Next::again;
          }
        integrator.set_mode(Integrator::Mode::extrapolated);
        if (change > tolerance && may_redo)
          {
            control.redo_after_correction(taken, progress);
            pcout << "  IMPL-EX: correction not converged, step redone, "
                     "step "
                  << progress.increment << " m\n";
            return Next::redo;
          }
        control.corrected(change <= tolerance);
        return Next::accept;
      }

      void
      FloorCorrection::fail(const std::string &failure,
                            const double       taken,
                            Progress          &progress)
      {
        integrator.set_mode(Integrator::Mode::extrapolated);
        if (may_redo)
          {
            control.redo_after_correction(taken, progress);
            pcout << "  IMPL-EX: correction failed (" << failure
                  << "), step redone, step " << progress.increment << " m\n";
            return;
          }
        control.corrected(false);
        failed_here = true;
        pcout << "  IMPL-EX: correction failed (" << failure
              << "), the IMPL-EX step is kept\n";
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
