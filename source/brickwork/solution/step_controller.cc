/**
 * @file
 * The step controller.
 */
#include <masonry/core/parameters.h>

#include "step_controller.h"

#include <algorithm>
#include <cmath>

#include "bounds.h"
#include "stop_messages.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      void
      StepSettings::declare_parameters(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Bool;
        using dealii::Patterns::Double;
        using dealii::Patterns::Integer;
        using dealii::Patterns::Selection;
        prm.declare_entry(
          "Number of steps",
          "30",
          Integer(1, 100000),
          "Nominal number of load steps: the step is never "
          "larger than target / this number; it is halved "
          "when Newton fails and grows back (by the growth "
          "factor) after two consecutive steps of at most 2 iterations or a "
          "third of the "
          "maximum Newton iterations.");
        prm.declare_entry("Maximum cut-backs",
                          "10",
                          Integer(0, 60),
                          "Halvings of a step that does not converge: the "
                          "run stops with status `not converged' (results up "
                          "to the last converged step are written) when a "
                          "step fails after this many consecutive halvings or "
                          "when it is already smaller than the nominal step "
                          "/ 2^N (tiny converged steps between failures "
                          "would otherwise halve it without end).");
        declare_ranged_entry(prm,
                             "Step growth factor",
                             "2",
                             {1, 100, "(dimensionless)"},
                             "Factor on the step after an easy step "
                             "(dimensionless, >= 1); also the largest factor "
                             "by which IMPL-EX extrapolates the last step's "
                             "changes of the internal variables.");
        prm.declare_entry("Maximum steps",
                          "0",
                          Integer(0),
                          "Stop after this many converged steps of this run "
                          "with status `interrupted' and a checkpoint (0: no "
                          "limit); `Resume = true' continues.");
        prm.declare_entry(
          "Collapse stress ratio",
          "0",
          Double(0, 1),
          "The run ends when the specimen has collapsed: on a loading leg "
          "the stress has fallen below this fraction r of the peak stress "
          "of the run, and it lies more than r times the peak below the "
          "largest stress of the leg (a reloading from the unloading stress "
          "is not a collapse), dimensionless, in [0, 1). In a monotonic run "
          "that is a stress below min(r, 1 - r) times the peak, so 0.5 ends "
          "it at half the peak. Its status is `completed', its message "
          "(log.txt, summary.json) says where, and the last state is written; "
          "the rest of the protocol is not run. 0: never (the run goes on "
          "to the last amplitude whatever the specimen still carries).");
        // a tolerance below 1e-6 redoes the same step forever
        declare_ranged_entry(
          prm,
          "IMPL-EX damage tolerance",
          "0.05",
          {1e-06, 1, "(dimensionless)"},
          "IMPL-EX step control (dimensionless, > 0): when the largest "
          "difference between the updated and the extrapolated damage of "
          "a step exceeds this, the step is redone smaller in proportion "
          "(to no less than a fifth, and not below `IMPL-EX minimum step'; "
          "`implex_steps_redone' in summary.json); below half of it, the "
          "next step grows by `Step growth factor' up to the nominal "
          "step.");
        prm.declare_entry(
          "IMPL-EX minimum step",
          "0.01",
          Double(0, 1),
          "Smallest step the IMPL-EX step control asks for, as a fraction "
          "of the nominal step (dimensionless, 0 < value <= 1). Where a "
          "joint or a brick point snaps (its damage jumps whatever the "
          "step), the damage error stays above the tolerance for any step; "
          "at this floor such steps are accepted and counted "
          "(`implex_steps_over_tolerance' in summary.json) instead of "
          "shrinking the step towards zero. Cut-backs after a failed Newton "
          "solve are not limited by it, and the steps after a cut-back keep "
          "its smaller size while their damage error stays over the "
          "tolerance (they grow once it is below half of it).");
        prm.declare_entry(
          "IMPL-EX minimum step when unloading",
          "0",
          Double(0, 1),
          "The floor of `IMPL-EX minimum step' on the unloading legs of a "
          "cyclic run, as a fraction of the nominal step (dimensionless, 0 "
          "to 1; 0: the same as `IMPL-EX minimum step'). An unloading leg "
          "starts at it when the loading leg before hands on a smaller "
          "step. Past the peak most of the damage error of an unloading "
          "step comes from points that snap open (mortar cracking in "
          "tension), whose damage jumps whatever the step, and the loading "
          "floor holds whole unloading legs at its size; a larger floor "
          "there takes fewer steps. Too large a floor lags the damage of "
          "the unloading and moves the next cycle's peak: in the single "
          "cyclic example 0.25 keeps the cycle peaks within 0.03 %, 0.5 "
          "moved one by +3.3 % "
          "(contrib/benchmarks/wallette_cyclic/README.md).");
        prm.declare_entry(
          "IMPL-EX floor correction",
          "accept",
          Selection("accept|iterate|iterate at any step"),
          "What IMPL-EX does with a step at `IMPL-EX minimum step' whose "
          "damage error is still over `IMPL-EX damage tolerance': `accept' "
          "keeps it (counted in implex_steps_over_tolerance); `iterate' "
          "solves the step again with the states of its own update frozen "
          "(not extrapolated), updates them at the new displacements, and "
          "repeats until the update changes no damage by more than the "
          "tolerance (a fixed-point iteration towards the implicit "
          "solution of the step, each pass a step of positive tangent), at "
          "most 30 passes; so the states the run keeps are as close to "
          "equilibrium as those of any accepted step. summary.json: "
          "implex_steps_corrected, and implex_steps_uncorrected for steps "
          "still over the tolerance after the passes (kept) or whose "
          "solve failed (the IMPL-EX step is kept). `iterate at any step' "
          "corrects a step of any size over the tolerance the same way at "
          "its own size, instead of redoing it smaller first; a step whose "
          "correction does not reach the tolerance within 4 passes, or "
          "whose solve fails, is redone smaller, and at the floor it is "
          "corrected as by `iterate' (fewer, larger steps where the damage "
          "error comes from points that start to soften, which smaller "
          "steps do not remove; doc/notes/implex-step-control.md). Both "
          "need `Nonlocal length' = 0.");
      }

      void
      StepSettings::parse_parameters(dealii::ParameterHandler &prm)
      {
        n_steps        = prm.get_integer("Number of steps");
        max_cutbacks   = prm.get_integer("Maximum cut-backs");
        growth         = prm.get_double("Step growth factor");
        max_steps      = prm.get_integer("Maximum steps");
        collapse_ratio = prm.get_double("Collapse stress ratio");
        AssertThrow(collapse_ratio < 1,
                    ExcParameter("Collapse stress ratio",
                                 "must be below 1 (a fraction of the peak)"));
        implex_tolerance    = positive_entry(prm, "IMPL-EX damage tolerance");
        implex_minimum_step = positive_entry(prm, "IMPL-EX minimum step");
        implex_minimum_step_unloading =
          prm.get_double("IMPL-EX minimum step when unloading");
        implex_floor_correction =
          prm.get("IMPL-EX floor correction") != "accept";
        implex_correct_any_step =
          prm.get("IMPL-EX floor correction") == "iterate at any step";
      }

      StepController::StepController(const Protocol             &protocol,
                                     const StepSettings         &settings,
                                     const bool                  damage_error,
                                     const unsigned int          max_newton,
                                     const std::array<double, 2> stress_bound,
                                     dealii::ConditionalOStream &pcout)
        : protocol(protocol)
        , settings(settings)
        , legs(protocol.legs())
        , by_damage_error(damage_error)
        , max_newton(max_newton)
        , stress_bound(stress_bound)
        , pcout(pcout)
        , nominal(std::abs(protocol.target_displacement() / settings.n_steps))
        , increment(nominal)
        , stall_floor(
            nominal *
            std::min(stall_fraction,
                     damage_error ? settings.implex_minimum_step : 1.) *
            (1 - 1e-9))
      {}

      double
      StepController::floor_of(const Leg &leg) const
      {
        const double unloading = settings.implex_minimum_step_unloading;
        return (leg.unloading && unloading > 0 ? unloading :
                                                 settings.implex_minimum_step) *
               nominal;
      }

      double
      StepController::shrunk(const double step) const
      {
        return step * std::max(0.2, 0.9 / last_ratio);
      }

      void
      StepController::start_leg(const Leg &leg)
      {
        // a loading leg hands its last step (often its floor) on to the
        // unloading leg that follows
        if (by_damage_error)
          increment = std::max(increment, floor_of(leg));
      }

      bool
      StepController::next(const std::vector<CurvePoint> &curve, Step &step)
      {
        while (segment < legs.size())
          {
            const Leg &leg = legs[segment];
            double     to  = 0;
            if (!protocol.next_position(
                  leg, curve, position, increment, nominal, to))
              {
                // an unloading leg ends: the next loading starts at the
                // nominal step
                ++segment;
                if (leg.unloading)
                  increment = nominal;
                if (segment < legs.size())
                  start_leg(legs[segment]);
                continue;
              }
            step.leg        = leg;
            step.from       = position;
            step.to         = to;
            step.size       = std::abs(to - position);
            step.time_step  = protocol.pseudo_time(step.size);
            step.correction = correcting;
            // IMPL-EX: no extrapolation across a reversal, at most the step
            // growth (an unbounded ratio made the cyclic examples run
            // away: doc/notes/implex-step-control.md; brickwork_implex_ratio)
            step.ratio =
              last_increment > 0 && curve.size() > 1 &&
                  curve.back().unloading == leg.unloading &&
                  curve.back().cycle == leg.cycle ?
                std::min(step.size / last_increment, settings.growth) :
                0.;
            return true;
          }
        return false;
      }

      Decision
      StepController::solved(const Step &step, const StepOutcome &outcome)
      {
        if (!outcome.converged)
          return failed(step, outcome);
        consecutive_cutbacks = 0;
        if (!std::isfinite(outcome.damage_error))
          return Decision::stop(
            "failed",
            "a number that is not finite (nan or inf) in " +
              outcome.non_finite +
              " in the IMPL-EX update after the step to platen "
              "displacement " +
              dealii::Utilities::to_string(step.to) + " m; check " +
              likely_entries(outcome.non_finite) +
              "; results up to the step before are written");
        Decision decision = correcting ?
                              next_pass(step, outcome.damage_change) :
                              judge(step, outcome.damage_error);
        if (decision.kind == Decision::Kind::accept)
          failed_here = false;
        return decision;
      }

      Decision
      StepController::judge(const Step &step, const double error)
      {
        if (!by_damage_error)
          return {};
        const double floor     = floor_of(step.leg);
        last_ratio             = error / settings.implex_tolerance;
        const bool over        = last_ratio > 1;
        const bool above_floor = step.size > floor * (1 + 1e-12);
        // a step over the tolerance is redone smaller, down to the floor:
        // otherwise the first step that re-enters the envelope (elastic,
        // nothing to extrapolate from) overshoots the cycle peak by up to
        // E0 x the step; at the floor it is accepted or corrected. With
        // `iterate at any step' a step of any size is corrected first.
        const bool correct =
          over && (settings.implex_correct_any_step ||
                   (!above_floor && settings.implex_floor_correction));
        if (correct && !failed_here)
          {
            correcting = true;
            passes     = 0;
            may_redo   = settings.implex_correct_any_step && above_floor;
            pcout << "  IMPL-EX: step solved again with its updated states "
                     "(damage error "
                  << error << ")\n";
            return {Decision::Kind::correct};
          }
        if (correct)
          return {};
        if (over && above_floor)
          {
            ++n_redone;
            increment = std::max(shrunk(step.size), floor);
            pcout << "  IMPL-EX: step redone (damage error " << error
                  << "), step " << increment << " m\n";
            return {Decision::Kind::redo};
          }
        max_error = std::max(max_error, error);
        return {};
      }

      Decision
      StepController::next_pass(const Step &step, const double change)
      {
        pcout << "  IMPL-EX: correction " << ++passes << ", damage change "
              << change << "\n";
        const unsigned int limit =
          may_redo ? max_passes_above_floor : max_correction_passes;
        if (change > settings.implex_tolerance && passes < limit)
          return {Decision::Kind::correct};
        correcting = false;
        if (change > settings.implex_tolerance && may_redo)
          return end_correction(step.size, "correction not converged");
        ++(change <= settings.implex_tolerance ? n_corrected : n_uncorrected);
        was_corrected = change <= settings.implex_tolerance;
        return {};
      }

      Decision
      StepController::end_correction(const double size, const std::string &note)
      {
        ++n_redone;
        increment = std::max(shrunk(size), floor_of(legs[segment]));
        pcout << "  IMPL-EX: " << note << ", step redone, step " << increment
              << " m\n";
        return {Decision::Kind::redo};
      }

      Decision
      StepController::failed(const Step &step, const StepOutcome &outcome)
      {
        if (correcting)
          {
            // back to IMPL-EX, whose step is solved again and kept; or it
            // is redone smaller
            correcting = false;
            if (may_redo)
              return end_correction(step.size,
                                    "correction failed (" + outcome.failure +
                                      ")");
            ++n_uncorrected;
            was_corrected = false;
            failed_here   = true;
            pcout << "  IMPL-EX: correction failed (" << outcome.failure
                  << "), the IMPL-EX step is kept\n";
            return {Decision::Kind::redo};
          }
        ++total_cutbacks;
        // a converged step resets the consecutive count, so the step is
        // also bounded below: otherwise tiny converged steps between
        // failures halve it without end
        const double lower_bound =
          std::ldexp(nominal, -int(settings.max_cutbacks));
        const bool too_many = ++consecutive_cutbacks > settings.max_cutbacks;
        if (too_many || increment < lower_bound)
          {
            std::string       status;
            const std::string message =
              cutback_stop_message({consecutive_cutbacks - 1,
                                    total_cutbacks,
                                    settings.max_cutbacks,
                                    too_many,
                                    lower_bound,
                                    step.to,
                                    step.size,
                                    step.from,
                                    outcome.non_finite,
                                    outcome.failure},
                                   status);
            return Decision::stop(status, message);
          }
        if (!outcome.non_finite.empty())
          recent_non_finite = outcome.non_finite;
        increment /= 2;
        easy_steps = 0;
        pcout << "  cut-back: step halved to " << increment << " m ("
              << outcome.failure << ")\n";
        return {Decision::Kind::redo};
      }

      void
      StepController::accept(const Step &step, const double reaction)
      {
        last_increment     = step.size;
        reaction_reference = std::max(reaction_reference, reaction);
        time += step.time_step;
        position = step.to;
        ++step_number;
        ++steps_this_run;
      }

      Decision
      StepController::check_end(const Step                    &step,
                                const std::vector<CurvePoint> &curve)
      {
        // a physical end (collapse, status completed) or none: a solution
        // that ran away (solution/bounds.h)
        const std::string collapse =
          collapse_problem(curve, settings.collapse_ratio);
        const std::string end = !collapse.empty() ?
                                  collapse :
                                  runaway_problem(curve.back().stress,
                                                  curve.back().strain,
                                                  stress_bound[0],
                                                  stress_bound[1]);
        if (!end.empty())
          return Decision::stop(!collapse.empty() ? "completed" : "failed",
                                end + " (step " + std::to_string(step_number) +
                                  "); results up to there are written");
        small_steps = step.size < stall_floor ? small_steps + 1 : 0;
        if (small_steps == 0)
          recent_non_finite.clear();
        if (small_steps >= stall_steps)
          {
            std::string       status;
            const std::string message = stall_message(recent_non_finite,
                                                      stall_floor,
                                                      nominal,
                                                      step.size,
                                                      step.to,
                                                      by_damage_error,
                                                      status);
            return Decision::stop(status, message);
          }
        return {};
      }

      bool
      StepController::protocol_done(const std::vector<CurvePoint> &curve) const
      {
        return segment + 1 == legs.size() &&
               protocol.leg_done(legs[segment], curve, position, nominal);
      }

      void
      StepController::grow(const unsigned int iterations)
      {
        if (!by_damage_error)
          {
            // implicit: grow after two consecutive easy steps
            easy_steps =
              iterations <= std::max(2u, max_newton / 3) ? easy_steps + 1 : 0;
            if (easy_steps >= 2)
              {
                increment  = std::min(increment * settings.growth, nominal);
                easy_steps = 0;
              }
            return;
          }
        if (last_ratio > 1 && was_corrected && settings.implex_correct_any_step)
          {
            // the correction made the step implicit: keep its size
          }
        else if (last_ratio > 1)
          {
            // accepted only at (or below) the floor: shrink, but not below
            // the floor (and never raise a step that a cut-back made
            // smaller still); an implicit step is exact
            if (!was_corrected)
              ++n_over_tolerance;
            increment = std::max(shrunk(increment),
                                 std::min(increment, floor_of(legs[segment])));
          }
        else if (last_ratio < 0.5)
          increment = std::min(increment * settings.growth, nominal);
        was_corrected = false;
      }

      Decision
      StepController::check_interrupted(
        const std::vector<CurvePoint> &curve) const
      {
        const unsigned int max_steps = settings.max_steps;
        if (max_steps > 0 && steps_this_run >= max_steps &&
            segment < legs.size() && !protocol_done(curve))
          return Decision::stop("interrupted",
                                "stopped after `Maximum steps' = " +
                                  std::to_string(max_steps) +
                                  " steps; `set Resume = true' continues "
                                  "from the checkpoint");
        return {};
      }

      void
      StepController::write_summary(Json &summary) const
      {
        if (!by_damage_error)
          return;
        summary["implex_max_damage_error"]     = max_error;
        summary["implex_steps_over_tolerance"] = n_over_tolerance;
        summary["implex_steps_redone"]         = n_redone;
        if (settings.implex_floor_correction)
          {
            summary["implex_steps_corrected"]   = n_corrected;
            summary["implex_steps_uncorrected"] = n_uncorrected;
          }
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
