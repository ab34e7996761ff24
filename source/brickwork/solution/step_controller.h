/**
 * @file
 * The step controller: where the platen goes next and how far, and what
 * becomes of a solved step. It owns the platen's position in the protocol,
 * the step size (growth after easy steps or from the IMPL-EX damage error,
 * cut-backs), the IMPL-EX redo and floor correction, and every reason to
 * stop (cut-backs that did not help, a stall, a collapse, a run-away
 * solution, `Maximum steps'). The step loop asks it for the next step and
 * hands it the outcome; it answers accept, redo, correct or stop. Nothing
 * else writes the step size.
 */
#ifndef masonry_brickwork_solution_step_controller_h
#define masonry_brickwork_solution_step_controller_h

#include <masonry/brickwork/curve.h>
#include <masonry/brickwork/protocol.h>
#include <masonry/core/json.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <boost/serialization/version.hpp>

#include <array>
#include <string>
#include <vector>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** The entries of the step size and of the end of a run (`Number of
       * steps', `Maximum cut-backs', `Step growth factor', `Maximum steps',
       * `Collapse stress ratio' and the IMPL-EX step entries). */
      struct StepSettings
      {
        /** Nominal number of steps (the largest step is target / n_steps). */
        unsigned int n_steps = 30;
        /** Consecutive halvings of a step before the run stops. */
        unsigned int max_cutbacks = 10;
        /** Factor on the step after an easy step (up to the nominal step);
         * also the largest IMPL-EX extrapolation ratio. */
        double growth = 2;
        /** Stop (status `interrupted', checkpoint written) after this many
         * converged steps of this run (0: no limit). */
        unsigned int max_steps = 0;
        /** The run ends (status completed) once the specimen has collapsed
         * (collapse_problem()); 0: never. */
        double collapse_ratio = 0;
        /** IMPL-EX: the largest allowed difference between the extrapolated
         * and the updated damage of a step. */
        double implex_tolerance = 0.05;
        /** IMPL-EX: the smallest step, as a fraction of the nominal step,
         * on loading and (0: the same) unloading legs. */
        double implex_minimum_step = 0.01, implex_minimum_step_unloading = 0;
        /** IMPL-EX: a step at the floor over the tolerance is corrected
         * (solved again with its own updated states, frozen); with
         * implex_correct_any_step a step of any size. */
        bool implex_floor_correction = false, implex_correct_any_step = false;

        /** Declare the entries in the present subsection. */
        static void
        declare_parameters(dealii::ParameterHandler &prm);
        /** Read them; errors name the entry. */
        void
        parse_parameters(dealii::ParameterHandler &prm);
      };

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

      /** Passes of a correction above the floor (`IMPL-EX floor
       * correction = iterate at any step'); then the step is redone
       * smaller. */
      constexpr unsigned int max_passes_above_floor = 4;

      /** Passes of one correction at the floor at most; then the step is
       * kept. */
      constexpr unsigned int max_correction_passes = 30;

      /** A step to solve. */
      struct Step
      {
        /** The leg it belongs to. */
        Leg leg;
        /** Platen displacement before and after the step, the step's size
         * (m) and its pseudo-time (s). */
        double from = 0, to = 0, size = 0, time_step = 0;
        /** Pseudo-time ratio of this step to the last converged one: the
         * IMPL-EX extrapolation and the extrapolated predictor (0: none,
         * for example across a reversal). */
        double ratio = 0;
        /** The step is a pass of an IMPL-EX correction: the laws are
         * evaluated with the frozen states of its last update. */
        bool correction = false;
      };

      /** What becomes of a solved step. */
      struct Decision
      {
        enum class Kind
        {
          /** keep it */
          accept,
          /** solve it again from the last converged state (with the step
           * size the controller has set) */
          redo,
          /** solve it again from where it ended, with the laws' updated
           * states frozen (an IMPL-EX correction pass) */
          correct,
          /** end the run */
          stop
        };
        /** What becomes of the step; stop: the run's status (`completed',
         * `failed', ...) and why. */
        Decision(const Kind         kind    = Kind::accept,
                 const std::string &status  = "",
                 const std::string &message = "")
          : kind(kind)
          , status(status)
          , message(message)
        {}

        Kind        kind;
        std::string status, message;

        static Decision
        stop(const std::string &status, const std::string &message)
        {
          return {Kind::stop, status, message};
        }
      };

      /** The outcome of the solve of a step. */
      struct StepOutcome
      {
        /** Newton converged (and the state is no mechanism). */
        bool converged = false;
        /** Newton iterations; the norm of the platen reactions (N). */
        unsigned int iterations = 0;
        double       reaction   = 0;
        /** Failed: why, and where a number was not finite ("": nowhere). */
        std::string failure, non_finite;
        /** Converged, IMPL-EX: the damage error of the update (NaN: a
         * number that is not finite, in @p non_finite); correction pass:
         * the largest change of a damage from the frozen states. */
        double damage_error = 0, damage_change = 0;
      };

      /** See the file's description. */
      class StepController
      {
      public:
        /**
         * @p damage_error: the integrator measures the damage error of a
         * step (IMPL-EX: the step size follows it; otherwise the Newton
         * iterations). @p stress_bound: the largest compressive strength
         * and constrained modulus of the laws (runaway_problem()).
         */
        StepController(const Protocol             &protocol,
                       const StepSettings         &settings,
                       const bool                  damage_error,
                       const unsigned int          max_newton,
                       const std::array<double, 2> stress_bound,
                       dealii::ConditionalOStream &pcout);

        /** The next step along the protocol from the last converged state
         * of @p curve; false when the protocol is done. */
        bool
        next(const std::vector<CurvePoint> &curve, Step &step);

        /** What becomes of @p step, solved with @p outcome. */
        Decision
        solved(const Step &step, const StepOutcome &outcome);

        /** @p step was accepted (its platen reaction @p reaction, N). */
        void
        accept(const Step &step, const double reaction);

        /** After the accepted step entered @p curve: the end of the run
         * (collapse, a solution that ran away, a stall) or none (accept). */
        Decision
        check_end(const Step &step, const std::vector<CurvePoint> &curve);

        /** Whether the accepted step ended the last leg. */
        bool
        protocol_done(const std::vector<CurvePoint> &curve) const;

        /** The size of the next step after an accepted one of
         * @p iterations Newton iterations. */
        void
        grow(const unsigned int iterations);

        /** `Maximum steps' stops the run here (or accept). */
        Decision
        check_interrupted(const std::vector<CurvePoint> &curve) const;

        /** Converged steps so far; platen displacement (m) and pseudo-time
         * (s) of the last one. */
        unsigned int
        n_steps() const
        {
          return step_number;
        }
        double
        applied() const
        {
          return position;
        }
        /** The nominal (largest) step, m. */
        double
        nominal_step() const
        {
          return nominal;
        }
        /** The largest norm of the platen reactions of the converged steps
         * so far, N (the residual reference). */
        double
        largest_reaction() const
        {
          return reaction_reference;
        }
        /** Steps that failed to converge (cut-backs) in the run. */
        unsigned int
        n_cutbacks() const
        {
          return total_cutbacks;
        }

        /** Counters into summary.json. */
        void
        write_summary(Json &summary) const;

        /** Write or read the position and the counters. */
        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          ar &position &increment &time &step_number &easy_steps &segment
            &last_increment &reaction_reference;
          ar &max_error &n_over_tolerance &n_redone &n_corrected &n_uncorrected
            &total_cutbacks;
        }

      private:
        /** The judgement of an IMPL-EX step by its damage error. */
        Decision
        judge(const Step &step, const double error);
        /** A pass of a correction converged: again, accept or redo. */
        Decision
        next_pass(const Step &step, const double change);
        /** Newton failed: a cut-back, the end of a correction, or stop. */
        Decision
        failed(const Step &step, const StepOutcome &outcome);
        /** Leg @p leg starts: a leg with a higher floor than the step it
         * inherits starts at its floor. */
        void
        start_leg(const Leg &leg);
        /** The IMPL-EX floor of @p leg, m. */
        double
        floor_of(const Leg &leg) const;
        /** A step shrunk in proportion to the damage error of the last
         * judged step (to no less than a fifth). */
        double
        shrunk(const double step) const;
        /** The end of a correction of a step of size @p size that did not
         * converge: redone smaller when allowed. */
        Decision
        end_correction(const double size, const std::string &note);

        const Protocol             &protocol;
        const StepSettings          settings;
        const std::vector<Leg>      legs;
        const bool                  by_damage_error;
        const unsigned int          max_newton;
        const std::array<double, 2> stress_bound;
        dealii::ConditionalOStream &pcout;
        const double                nominal;

        /** @name The position (checkpointed) */
        /** @{ */
        double       position = 0, increment = 0, time = 0;
        unsigned int step_number = 0, easy_steps = 0, segment = 0;
        /** Platen displacement increment of the last converged step. */
        double last_increment     = 0;
        double reaction_reference = 0;
        /** @} */

        /** @name IMPL-EX counters (checkpointed): the largest damage error
         * of an accepted step; steps accepted over the tolerance; steps
         * redone; corrected; corrections that did not converge or failed.
         * */
        /** @{ */
        double       max_error        = 0;
        unsigned int n_over_tolerance = 0, n_redone = 0, n_corrected = 0,
                     n_uncorrected = 0;
        /** @} */
        unsigned int total_cutbacks = 0;

        /** The damage error of the last judged step over the tolerance;
         * whether it was then corrected. */
        double last_ratio    = 0;
        bool   was_corrected = false;
        /** The present correction: running, passes, may it end in a
         * smaller step, did it fail at this step. */
        bool         correcting = false, may_redo = false, failed_here = false;
        unsigned int passes = 0;
        /** Halvings since the last converged step; accepted steps below the
         * stall floor in a row; converged steps of this run. */
        unsigned int consecutive_cutbacks = 0, small_steps = 0,
                     steps_this_run = 0;
        /** A non-finite failure since the steps fell below the stall
         * floor. */
        std::string recent_non_finite;
        /** The step below which an accepted step counts towards a stall,
         * m. */
        double stall_floor;
      };
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
