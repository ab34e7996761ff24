/**
 * @file
 * The loading protocol (monotonic ramp or load-unload cycles) and the
 * control of the step size (cut-backs, growth after easy steps or from the
 * IMPL-EX damage error), each an object chosen once.
 */
#ifndef masonry_brickwork_model_step_control_h
#define masonry_brickwork_model_step_control_h

#include <masonry/brickwork/curve.h>
#include <masonry/brickwork/wallette.h>
#include <masonry/core/json.h>

#include <boost/serialization/version.hpp>

#include <memory>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** A leg of the displacement protocol. */
      struct Segment
      {
        /** Platen displacement to reach (loading) or the lowest allowed
         * (unloading), m along the direction. */
        double       target;
        bool         unloading;
        unsigned int cycle;
      };

      /** The legs of the platen's motion. */
      class Protocol
      {
      public:
        virtual ~Protocol() = default;
        /** The legs in order. */
        virtual std::vector<Segment>
        legs() const = 0;
        /** The platen displacement at which cycle @p cycle (from 1) turns
         * back, m. */
        virtual double
        amplitude(const unsigned int cycle) const = 0;
      };

      /** The protocol `Protocol' selects. */
      std::unique_ptr<Protocol>
      create_protocol(const ProtocolSettings &settings);

      /** The protocol's position, stored in checkpoints. */
      struct Progress
      {
        double       applied = 0, increment = 0, time = 0;
        unsigned int step = 0, easy_steps = 0, segment = 0;
        /** Platen displacement increment of the last converged step. */
        double last_increment = 0;
        /** Largest norm of the platen reactions of the converged steps so
         * far (N): the reference of the Newton residual. */
        double largest_reaction = 0;
        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          ar &applied &increment &time &step &easy_steps &segment
            &last_increment &largest_reaction;
        }
      };

      /**
       * The next platen position of leg @p leg from the current one
       * (progress.applied) and the curve so far; false when the leg is
       * done (progress.segment then points to the next leg).
       */
      /**
       * Whether the leg has reached its end: the target displacement when
       * loading; the unloading stress (or the target) when unloading.
       */
      bool
      leg_done(const Segment                 &leg,
               const std::vector<CurvePoint> &curve,
               const ProtocolSettings        &settings,
               const double                   nominal,
               const Progress                &progress);

      bool
      next_position(const Segment                 &leg,
                    const std::vector<CurvePoint> &curve,
                    const ProtocolSettings        &settings,
                    const double                   nominal,
                    Progress                      &progress,
                    double                        &next);

      /**
       * Stall detection: a run whose accepted steps are all smaller than
       * stall_fraction x the nominal step (and than `IMPL-EX minimum step'
       * x the nominal step, the smallest step IMPL-EX takes by design) for
       * stall_steps steps in a row makes no progress and stops with status
       * `stalled'. A halving chain of the default 10 cut-backs ends at
       * 2^-10 < 1e-3, but the step grows back after two easy steps.
       */
      constexpr double       stall_fraction = 1e-3;
      constexpr unsigned int stall_steps    = 50;

      /** The step below which an accepted step counts towards a stall:
       * stall_fraction x @p nominal, and below the IMPL-EX floor. */
      double
      stall_step(const IntegratorSettings &integrator, const double nominal);

      /** Passes of a correction above the floor (`IMPL-EX floor
       * correction = iterate at any step'); then the step is redone
       * smaller. */
      constexpr unsigned int max_passes_above_floor = 4;

      /** What to do with a converged step (StepSizeControl::judge()). */
      enum class Verdict
      {
        /** keep it */
        accept,
        /** solve it again smaller (progress.increment is set) */
        redo,
        /** IMPL-EX at the step floor (`iterate at any step': at any
         * size): solve it again with its updated states */
        correct
      };

      /** How the step size follows the steps' difficulty. */
      class StepSizeControl
      {
      public:
        virtual ~StepSizeControl() = default;
        /**
         * A converged step of size @p taken with damage error @p error:
         * accept it, redo it smaller, or (IMPL-EX at the floor) correct
         * it.
         */
        virtual Verdict
        judge(const double taken, const double error, Progress &progress);
        /** The leg of the next step (its floor may depend on whether the
         * leg unloads). */
        virtual void
        set_leg(const Segment &leg);
        /** Leg @p leg starts (called once, when the protocol moves on to
         * it): a leg with a higher floor than the step it inherits starts
         * at its floor (progress.increment). */
        virtual void
        start_leg(const Segment &leg, Progress &progress);
        /** A step judged `correct' was corrected (@p converged: its
         * damage change within the tolerance) or not (kept as it is). */
        virtual void
        corrected(const bool converged);
        /** Whether a correction of a step of size @p taken that does not
         * converge is redone smaller (else it is kept). */
        virtual bool
        may_redo(const double taken) const;
        /** The correction of a step over the floor of size @p taken did not
         * reach the tolerance or failed: it is redone smaller
         * (progress.increment is set). */
        virtual void
        redo_after_correction(const double taken, Progress &progress);
        /** An accepted step of @p iterations Newton iterations: the next
         * increment, from the errors of its last judge(). */
        virtual void
        after_step(const unsigned int iterations, Progress &progress) = 0;
        /** Counters into summary.json. */
        virtual void
        write_summary(Json &summary) const;
        /** Write or read the counters (version 1: the corrections). */
        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int version)
        {
          ar &max_error &n_over_tolerance &n_redone;
          if (version > 0)
            ar &n_corrected &n_uncorrected;
        }

      protected:
        /** Largest damage error of an accepted step; steps accepted over
         * the tolerance (at the minimum step); steps redone. */
        double       max_error        = 0;
        unsigned int n_over_tolerance = 0, n_redone = 0;
        /** IMPL-EX steps at the floor corrected; those whose correction
         * did not reach the tolerance or failed. */
        unsigned int n_corrected = 0, n_uncorrected = 0;
        /** The damage error of the last judged step over the tolerance;
         * whether it was then corrected. */
        double last_ratio    = 0;
        bool   was_corrected = false;
      };

      /** The control of the integrator `Damage integration' selects:
       * Newton iterations (implicit) or the damage error (IMPL-EX). */
      std::unique_ptr<StepSizeControl>
      create_step_size_control(const IntegratorSettings &integrator,
                               const ProtocolSettings   &protocol,
                               const NewtonSettings     &newton,
                               const double              nominal);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

BOOST_CLASS_VERSION(masonry::brickwork::model::StepSizeControl, 1)

#endif
