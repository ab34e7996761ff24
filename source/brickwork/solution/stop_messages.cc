/**
 * @file
 * Messages of a stopped run.
 */
#include "stop_messages.h"

#include <sstream>

#include "step_controller.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      std::string
      likely_entries(const std::string &stage)
      {
        if (stage.find("bricks") != std::string::npos)
          return "the entries of `subsection Brick material' (moduli, "
                 "strengths, fracture energies)";
        if (stage.find("joints") != std::string::npos)
          return "the entries of `subsection Interface law' (stiffnesses, "
                 "strengths, fracture energies)";
        return "`Linear solver' and `Maximum damage' of the interface law "
               "(a fully debonded joint leaves a singular tangent)";
      }

      std::string
      cutback_stop_message(const CutbackStop &stop, std::string &status)
      {
        // why the step control gave up, honestly: the count restarts at
        // every converged step, the bound does not
        std::ostringstream why;
        why << stop.halvings << " halvings since the last converged step, "
            << stop.attempts << " failed attempts in the run";
        if (stop.too_many)
          why << "; `Maximum cut-backs' = " << stop.max_cutbacks
              << " halvings in a row did not help";
        else
          why << "; the step reached its lower bound, the nominal step / "
                 "2^`Maximum cut-backs' = "
              << stop.lower_bound << " m";
        std::ostringstream m;
        if (!stop.non_finite.empty())
          {
            // a smaller step did not help: a bad model
            m << "a number that is not finite (nan or inf) in "
              << stop.non_finite << " at platen displacement " << stop.next
              << " m, also with a step of " << stop.taken << " m (" << why.str()
              << "; last converged: " << stop.applied << " m); check "
              << likely_entries(stop.non_finite)
              << "; results up to there are written";
            status = "failed";
          }
        else
          {
            m << "no convergence at platen displacement " << stop.next
              << " m with a step of " << stop.taken << " m (" << why.str()
              << "; last converged: " << stop.applied
              << " m); the last attempt: " << stop.failure
              << "; results up to there are written";
            status = "not converged";
          }
        return m.str();
      }

      std::string
      stall_message(const std::string &recent_non_finite,
                    const double       stall_floor,
                    const double       nominal,
                    const double       taken,
                    const double       next,
                    const bool         implex,
                    std::string       &status)
      {
        std::ostringstream m;
        if (!recent_non_finite.empty())
          {
            // cut back before a non-finite number again and again
            m << "a number that is not finite (nan or inf) in "
              << recent_non_finite << " whenever the platen moves past " << next
              << " m: the steps shrank below " << stall_floor
              << " m without getting past it; check "
              << likely_entries(recent_non_finite)
              << "; results up to there are written";
            status = "failed";
            return m.str();
          }
        m << "no progress: the last " << stall_steps
          << " steps were all smaller than "
          << stall_floor / nominal * (1 + 1e-9) << " x the nominal step (the "
          << "last " << taken << " m, at platen displacement " << next
          << " m); check "
          << (implex ? "`IMPL-EX damage tolerance', `IMPL-EX minimum step'" :
                       "`Maximum Newton iterations', `Newton tolerance'")
          << " and `Step growth factor'; results up to there are written";
        status = "stalled";
        return m.str();
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
