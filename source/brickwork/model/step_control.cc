/**
 * @file
 * Protocols and step-size control.
 */
#include "step_control.h"

#include <algorithm>
#include <cmath>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      namespace
      {
        /** One ramp to the target displacement. */
        class Monotonic : public Protocol
        {
        public:
          explicit Monotonic(const double target)
            : target(target)
          {}
          std::vector<Segment>
          legs() const override
          {
            return {{target, false, 1}};
          }
          double
          amplitude(const unsigned int) const override
          {
            return target;
          }

        private:
          double target;
        };

        /** Load-unload cycles, `repeats' at each amplitude. */
        class Cyclic : public Protocol
        {
        public:
          Cyclic(const std::vector<double> &amplitudes,
                 const unsigned int         repeats)
            : amplitudes(amplitudes)
            , repeats(repeats)
          {}
          std::vector<Segment>
          legs() const override
          {
            std::vector<Segment> legs;
            unsigned int         cycle = 0;
            for (const double a : amplitudes)
              for (unsigned int r = 0; r < repeats; ++r)
                {
                  ++cycle;
                  legs.push_back({a, false, cycle});
                  legs.push_back({0., true, cycle});
                }
            return legs;
          }
          double
          amplitude(const unsigned int cycle) const override
          {
            return amplitudes[(cycle - 1) / repeats];
          }

        private:
          std::vector<double> amplitudes;
          unsigned int        repeats;
        };
      } // namespace

      std::unique_ptr<Protocol>
      create_protocol(const ProtocolSettings &s)
      {
        if (s.cycle_amplitudes.empty())
          return std::make_unique<Monotonic>(s.target_displacement);
        return std::make_unique<Cyclic>(s.cycle_amplitudes,
                                        s.cycles_per_amplitude);
      }

      bool
      leg_done(const Segment                 &leg,
               const std::vector<CurvePoint> &curve,
               const ProtocolSettings        &settings,
               const double                   nominal,
               const Progress                &progress)
      {
        if (!leg.unloading)
          return progress.applied >= leg.target * (1 - 1e-12);
        // the aimed last step lands a little above: the aim takes the
        // slope of the last step, and the IMPL-EX states lag one step
        // (0.1 % of the unloading stress in the cyclic examples); without
        // the 1 % the leg went on with a tiny step (2e-8 m) and then a
        // whole one past the unloading stress
        return curve.size() > 1 &&
               (curve.back().stress <= 1.01 * settings.unloading_stress +
                                         1e-6 * std::abs(curve[1].stress) ||
                progress.applied <= leg.target + 1e-9 * nominal);
      }

      bool
      next_position(const Segment                 &leg,
                    const std::vector<CurvePoint> &curve,
                    const ProtocolSettings        &settings,
                    const double                   nominal,
                    Progress                      &progress,
                    double                        &next)
      {
        const double applied = progress.applied, increment = progress.increment;
        if (!leg.unloading)
          {
            if (leg_done(leg, curve, settings, nominal, progress))
              {
                ++progress.segment;
                return false;
              }
            next = applied + increment;
            if (next > leg.target * (1 - 1e-9))
              next = leg.target;
            return true;
          }
        const CurvePoint &last = curve.back();
        if (leg_done(leg, curve, settings, nominal, progress))
          {
            ++progress.segment;
            progress.increment = nominal;
            return false;
          }
        next = applied - increment;
        // aim at the unloading stress with the slope of the last unloading
        // step (elastic unloading is linear)
        const CurvePoint &before = curve[curve.size() - 2];
        if (last.unloading && last.displacement < before.displacement)
          {
            const double slope = (before.stress - last.stress) /
                                 (before.displacement - last.displacement);
            if (slope > 0)
              {
                const double aim =
                  applied - (last.stress - settings.unloading_stress) / slope;
                if (aim > next - 1e-12 * nominal)
                  next = aim;
              }
          }
        next = std::max(next, leg.target);
        if (applied - next < 1e-9 * nominal)
          {
            ++progress.segment;
            progress.increment = nominal;
            return false;
          }
        return true;
      }

      double
      stall_step(const IntegratorSettings &integrator, const double nominal)
      {
        return nominal *
               std::min(stall_fraction,
                        integrator.implex ? integrator.implex_minimum_step :
                                            1.) *
               (1 - 1e-9);
      }

      Verdict
      StepSizeControl::judge(const double, const double, Progress &)
      {
        return Verdict::accept;
      }

      void
      StepSizeControl::set_leg(const Segment &)
      {}

      void
      StepSizeControl::start_leg(const Segment &, Progress &)
      {}

      void
      StepSizeControl::corrected(const bool converged)
      {
        ++(converged ? n_corrected : n_uncorrected);
        was_corrected = converged;
      }

      bool
      StepSizeControl::may_redo(const double) const
      {
        return false;
      }

      void
      StepSizeControl::redo_after_correction(const double, Progress &)
      {}

      void
      StepSizeControl::write_summary(Json &) const
      {}

      namespace
      {
        /** Implicit integration: grow after two consecutive easy steps. */
        class NewtonIterationControl : public StepSizeControl
        {
        public:
          NewtonIterationControl(const double       growth,
                                 const unsigned int max_newton,
                                 const double       nominal)
            : growth(growth)
            , max_newton(max_newton)
            , nominal(nominal)
          {}

          void
          after_step(const unsigned int its, Progress &progress) override
          {
            progress.easy_steps =
              its <= std::max(2u, max_newton / 3) ? progress.easy_steps + 1 : 0;
            if (progress.easy_steps >= 2)
              {
                progress.increment =
                  std::min(progress.increment * growth, nominal);
                progress.easy_steps = 0;
              }
          }

        private:
          double       growth;
          unsigned int max_newton;
          double       nominal;
        };

        /**
         * IMPL-EX: the step follows the damage error. A step over the
         * tolerance is redone smaller, down to the floor: otherwise the
         * first step that re-enters the envelope (elastic, nothing to
         * extrapolate from) overshoots the cycle peak by up to E0 x the
         * step. At the floor it is accepted or (`IMPL-EX floor correction
         * = iterate') corrected. With `iterate at any step' a step of any
         * size is corrected first and redone smaller only when its
         * correction does not converge; a corrected step keeps its size
         * for the next one. The unloading legs may have a floor of their
         * own (`IMPL-EX minimum step when unloading'): there the damage
         * error comes from points that snap open (mostly mortar in
         * tension), which a smaller step does not remove.
         */
        class DamageErrorControl : public StepSizeControl
        {
        public:
          DamageErrorControl(const IntegratorSettings &s,
                             const double              growth,
                             const double              nominal)
            : tolerance(s.implex_tolerance)
            , floor(s.implex_minimum_step * nominal)
            , loading_floor(floor)
            , unloading_floor(s.implex_minimum_step_unloading > 0 ?
                                s.implex_minimum_step_unloading * nominal :
                                floor)
            , growth(growth)
            , nominal(nominal)
            , correct(s.implex_floor_correction)
            , correct_any_step(s.implex_correct_any_step)
          {}

          Verdict
          judge(const double taken,
                const double error,
                Progress    &progress) override
          {
            last_ratio = error / tolerance;
            if (last_ratio > 1 && correct_any_step)
              return Verdict::correct;
            if (last_ratio > 1 && taken > floor * (1 + 1e-12))
              {
                ++n_redone;
                progress.increment = std::max(shrunk(taken), floor);
                return Verdict::redo;
              }
            if (last_ratio > 1 && correct)
              return Verdict::correct;
            max_error = std::max(max_error, error);
            return Verdict::accept;
          }

          void
          set_leg(const Segment &leg) override
          {
            floor = leg.unloading ? unloading_floor : loading_floor;
          }

          void
          start_leg(const Segment &leg, Progress &progress) override
          {
            // a loading leg hands its last step (often its floor) on to
            // the unloading leg that follows
            set_leg(leg);
            progress.increment = std::max(progress.increment, floor);
          }

          bool
          may_redo(const double taken) const override
          {
            return correct_any_step && taken > floor * (1 + 1e-12);
          }

          void
          redo_after_correction(const double taken, Progress &progress) override
          {
            ++n_redone;
            progress.increment = std::max(shrunk(taken), floor);
          }

          void
          after_step(const unsigned int, Progress &progress) override
          {
            double &increment = progress.increment;
            if (last_ratio > 1 && was_corrected && correct_any_step)
              {
                // the correction made the step implicit: keep its size
              }
            else if (last_ratio > 1)
              {
                // accepted only at (or below) the floor: shrink, but not
                // below the floor (and never raise a step that a cut-back
                // made smaller still); an implicit step is exact
                if (!was_corrected)
                  ++n_over_tolerance;
                increment =
                  std::max(shrunk(increment), std::min(increment, floor));
              }
            else if (last_ratio < 0.5)
              increment = std::min(increment * growth, nominal);
            was_corrected = false;
          }

          void
          write_summary(Json &summary) const override
          {
            summary["implex_max_damage_error"]     = max_error;
            summary["implex_steps_over_tolerance"] = n_over_tolerance;
            summary["implex_steps_redone"]         = n_redone;
            if (correct)
              {
                summary["implex_steps_corrected"]   = n_corrected;
                summary["implex_steps_uncorrected"] = n_uncorrected;
              }
          }

        private:
          /** A step shrunk in proportion to the damage error of the last
           * judged step (to no less than a fifth). */
          double
          shrunk(const double step) const
          {
            return step * std::max(0.2, 0.9 / last_ratio);
          }

          /** The tolerance; the floor of the present leg (the loading or
           * the unloading one). */
          double tolerance, floor, loading_floor, unloading_floor, growth,
            nominal;
          bool correct, correct_any_step;
        };
      } // namespace

      std::unique_ptr<StepSizeControl>
      create_step_size_control(const IntegratorSettings &integrator,
                               const ProtocolSettings   &protocol,
                               const NewtonSettings     &newton,
                               const double              nominal)
      {
        if (integrator.implex)
          return std::make_unique<DamageErrorControl>(integrator,
                                                      protocol.growth,
                                                      nominal);
        return std::make_unique<NewtonIterationControl>(protocol.growth,
                                                        newton.max_newton,
                                                        nominal);
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
