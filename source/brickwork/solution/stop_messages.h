/**
 * @file
 * The one-line messages of a wallette run that stops before the end of
 * its protocol (cut-backs that did not help, no progress): what happened,
 * where, and which entries to look at.
 */
#ifndef masonry_brickwork_model_stop_messages_h
#define masonry_brickwork_model_stop_messages_h

#include <string>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** The entries to look at when @p stage (Assembler::non_finite(),
       * Newton) holds a number that is not finite. */
      std::string
      likely_entries(const std::string &stage);

      /** A step that failed after its cut-backs. */
      struct CutbackStop
      {
        /** Halvings since the last converged step, failed attempts in the
         * run, `Maximum cut-backs'. */
        unsigned int halvings, attempts, max_cutbacks;
        /** Whether the halvings ran out (else the step reached its lower
         * bound, m). */
        bool   too_many;
        double lower_bound;
        /** Platen displacement aimed at, the step, the last converged
         * displacement, m. */
        double next, taken, applied;
        /** Where a number was not finite ("": nowhere), why the last
         * attempt failed. */
        std::string non_finite, failure;
      };

      /** The message of @p stop; @p status becomes `failed' (a number
       * that is not finite) or `not converged'. */
      std::string
      cutback_stop_message(const CutbackStop &stop, std::string &status);

      /**
       * The message of a run whose last stall_steps steps were all smaller
       * than @p stall_floor (m; @p nominal the nominal step, @p taken the
       * last, @p next where it went, m): a number that is not finite in
       * @p recent_non_finite whenever the platen moved on (status
       * `failed'), or no progress (`stalled'; @p implex names the step
       * control's entries).
       */
      std::string
      stall_message(const std::string &recent_non_finite,
                    const double       stall_floor,
                    const double       nominal,
                    const double       taken,
                    const double       next,
                    const bool         implex,
                    std::string       &status);
    } // namespace model
  }   // namespace brickwork
} // namespace masonry

#endif
