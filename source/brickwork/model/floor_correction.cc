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
      FloorCorrection::start(const double error)
      {
        // from the IMPL-EX solution and its updated states
        freeze();
        integrator.set_mode(Integrator::Mode::frozen);
        passes = 0;
        pcout << "  IMPL-EX: step solved again with its updated states "
                 "(damage error "
              << error << ")\n";
      }

      bool
      FloorCorrection::again()
      {
        const double change = damage_change();
        pcout << "  IMPL-EX: correction " << ++passes << ", damage change "
              << change << "\n";
        if (change > tolerance && passes < max_correction_passes)
          {
            freeze();
            return true;
          }
        control.corrected(change <= tolerance);
        integrator.set_mode(Integrator::Mode::extrapolated);
        return false;
      }

      void
      FloorCorrection::fail(const std::string &failure)
      {
        control.corrected(false);
        integrator.set_mode(Integrator::Mode::extrapolated);
        failed_here = true;
        pcout << "  IMPL-EX: correction failed (" << failure
              << "), the IMPL-EX step is kept\n";
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
