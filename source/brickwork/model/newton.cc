/**
 * @file
 * Newton-Raphson with line search.
 */
#include "newton.h"

#include <cmath>
#include <sstream>

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      namespace
      {
        /** The message of an exception in one line: deal.II's carry the
         * place in the source first, then `Additional information:'. */
        std::string
        first_line(const std::string &what)
        {
          std::string  m   = what;
          const size_t add = m.find("Additional information:");
          if (add != std::string::npos)
            m = m.substr(add + 23);
          std::string line;
          for (const char c : m)
            if (c == '\n')
              line += line.empty() || line.back() == ' ' ? "" : " ";
            else
              line += c;
          while (!line.empty() && line.front() == ' ')
            line.erase(0, 1);
          while (!line.empty() && (line.back() == ' ' || line.back() == '-'))
            line.pop_back();
          return line.empty() ? "an error" : line;
        }
      } // namespace

      Newton::Newton(const NewtonSettings &settings, const double minimum_force)
        : settings(settings)
        , minimum_force(minimum_force)
      {}

      bool
      Newton::converged(const double norm,
                        const double all,
                        const double reference,
                        double      &reaction) const
      {
        // the residual (constrained entries zeroed) against the platen
        // reactions, or against the elastic force of the whole applied
        // displacement when nothing is loaded; with the largest-reaction
        // reference, against the largest reactions of the run so far
        reaction = std::sqrt(std::max(all * all - norm * norm, 0.));
        const double scale =
          std::max({reaction,
                    minimum_force,
                    settings.largest_reaction_reference ? reference : 0.});
        return norm <= settings.newton_tolerance * scale;
      }

      bool
      Newton::solve_step(System       &system,
                         Assembler    &assembler,
                         LinearSolver &solver,
                         const double  displacement,
                         const double  time_step,
                         const double  reference,
                         unsigned int &iterations,
                         double       &reaction,
                         std::string  &non_finite,
                         std::string  &failure) const
      {
        non_finite.clear();
        failure.clear();
        const auto iteration = [&]() {
          return " (Newton iteration " + std::to_string(iterations) + ")";
        };
        const auto at = [&](const std::string &what) {
          non_finite = what + iteration();
          failure    = "a number that is not finite in " + non_finite;
        };
        system.set_platen(system.u, displacement);
        System::Vector r(system.owned, system.comm),
          du(system.owned, system.comm), u_start(system.owned, system.comm);
        // the next correction with the kept factorisation (a chord step):
        // the last full correction reduced the residual by the chord
        // contraction, so the tangent has hardly changed since it was
        // factorised; system.f_int then holds the forces at system.u
        bool chord = false;
        try
          {
            // iterations: the Newton corrections (each with a new tangent);
            // the chord corrections are not counted
            for (iterations = 0;;)
              {
                const bool use_kept = chord;
                chord               = false;
                if (!use_kept)
                  assembler.assemble(true, time_step);
                r = system.f_int;
                r *= -1;
                system.zero_constraints.set_zero(r);
                const double norm = r.l2_norm();
                const double all  = system.f_int.l2_norm();
                if (!std::isfinite(norm) || !std::isfinite(all))
                  {
                    const std::string part = assembler.non_finite();
                    at(!std::isfinite(system.u.l2_norm()) ?
                         "the displacements" :
                         (part.empty() ? "the internal forces" : part));
                    return false;
                  }
                if (converged(norm, all, reference, reaction))
                  return true;
                if (!use_kept && iterations == settings.max_newton)
                  {
                    std::ostringstream m;
                    m << "the residual was still " << norm
                      << " N after `Maximum Newton iterations' = "
                      << settings.max_newton;
                    failure = m.str();
                    return false;
                  }
                du = 0;
                try
                  {
                    if (use_kept)
                      solver.solve_with_kept_factors(system, du, r);
                    else
                      solver.solve(system, du, r, assembler.initial_tangent());
                  }
                catch (const LinearSolverFailure &e)
                  {
                    failure = e.what() + iteration();
                    return false;
                  }
                catch (const std::exception &e)
                  {
                    failure = first_line(e.what()) + iteration();
                    return false;
                  }
                if (!std::isfinite(du.l2_norm()))
                  {
                    at("the solution of the linear solve");
                    return false;
                  }
                system.zero_constraints.set_zero(du);
                u_start = system.u;
                system.u.add(1., du);
                if (use_kept)
                  {
                    // one trial: converged, or better (go on from there),
                    // or worse (back to where it started: the next
                    // correction is the Newton one it would have been)
                    assembler.assemble(false, time_step);
                    r = system.f_int;
                    system.zero_constraints.set_zero(r);
                    const double n      = r.l2_norm();
                    const bool   better = std::isfinite(n) && n < norm;
                    if (better && converged(n,
                                            system.f_int.l2_norm(),
                                            reference,
                                            reaction))
                      return true;
                    if (better)
                      chord = n <= settings.chord_contraction * norm;
                    else
                      system.u = u_start;
                    continue;
                  }
                ++iterations;
                double alpha = 1, accepted = 0;
                if (settings.line_search && line_search(system,
                                                        assembler,
                                                        u_start,
                                                        du,
                                                        norm,
                                                        time_step,
                                                        reference,
                                                        reaction,
                                                        alpha,
                                                        accepted))
                  return true;
                chord = settings.chord_contraction > 0 &&
                        settings.line_search && alpha == 1 &&
                        accepted <= settings.chord_contraction * norm &&
                        solver.has_kept_factors();
              }
          }
        catch (const std::exception &e)
          {
            failure = first_line(e.what()) + iteration();
            return false;
          }
        return false;
      }

      bool
      Newton::line_search(System               &system,
                          Assembler            &assembler,
                          const System::Vector &u_start,
                          const System::Vector &du,
                          const double          norm0,
                          const double          time_step,
                          const double          reference,
                          double               &reaction,
                          double               &accepted_alpha,
                          double               &accepted_norm) const
      {
        // backtracking on the residual norm
        System::Vector r(system.owned, system.comm);
        double         alpha = 1, best_alpha = 1, best = 0;
        for (unsigned int k = 0; k < 6; ++k)
          {
            assembler.assemble(false, time_step);
            r = system.f_int;
            system.zero_constraints.set_zero(r);
            const double n = r.l2_norm();
            // converged at this point already: the states were just
            // updated at it, so the tangent assembly of the next iteration
            // would only repeat this residual
            if (std::isfinite(n) && n < (1 - 1e-4 * alpha) * norm0 &&
                converged(n, system.f_int.l2_norm(), reference, reaction))
              return true;
            if (k == 0 || (std::isfinite(n) && n < best))
              {
                best       = n;
                best_alpha = alpha;
              }
            if (std::isfinite(n) && n < (1 - 1e-4 * alpha) * norm0)
              break;
            alpha /= 2;
            system.u = u_start;
            system.u.add(alpha, du);
          }
        if (alpha != best_alpha)
          {
            system.u = u_start;
            system.u.add(best_alpha, du);
          }
        accepted_alpha = best_alpha;
        accepted_norm  = best;
        return false;
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
