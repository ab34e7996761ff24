/**
 * @file
 * Newton-Raphson with line search.
 */
#include <masonry/core/parameters.h>

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

      void
      NewtonSettings::declare_parameters(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Bool;
        using dealii::Patterns::Double;
        using dealii::Patterns::Integer;
        using dealii::Patterns::Selection;
        // one iteration cannot converge a non-linear step: the steps are cut
        // back to nothing (1e-10 m) instead
        declare_ranged_iterations(
          prm,
          "Maximum Newton iterations",
          "20",
          2,
          1000,
          "Newton-Raphson iterations of a step before it is "
          "cut back.");
        declare_ranged_entry(prm,
                             "Newton tolerance",
                             "1e-8",
                             {1e-14, 0.1, "(dimensionless)"},
                             "Convergence when the out-of-balance force (l2 "
                             "norm over the free DOFs, N) is below this times "
                             "the norm of the platen reactions "
                             "(dimensionless).");
        prm.declare_entry("Line search",
                          "true",
                          Bool(),
                          "Backtracking line search on the residual norm "
                          "(halving the Newton correction up to 5 times).");
        prm.declare_entry(
          "Predictor",
          "constant",
          Selection("extrapolated|constant"),
          "First iterate of a load step: `extrapolated' adds the "
          "displacement increment of the last converged step, scaled by the "
          "ratio of the platen increments, to the last converged solution "
          "(only within a leg: after a reversal of the platen, a cut-back "
          "or a deletion the increment of the last step is not used); "
          "`constant' starts from the last converged solution with only the "
          "platen moved. The converged state is the same to the `Newton "
          "tolerance'; the extrapolated start saves about a third of the "
          "Newton iterations, but its converged states are only as close "
          "as the tolerance, where Newton from the constant start usually "
          "lands far below it, and past the peak of the cyclic examples "
          "that moved the collapse of the wall by a cycle "
          "(doc/notes/wallette-solver-speed.md): "
          "`constant' is the default.");
        // a chord correction must at least halve the residual to pay
        declare_ranged_entry(
          prm,
          "Newton chord contraction",
          "0.1",
          {0, 0.5, "(dimensionless)"},
          "A full Newton correction (line search at its first trial) that "
          "leaves at most this fraction of the residual is followed by a "
          "chord correction: the same LU factorisation solves for the new "
          "residual (no tangent assembly, no factorisation), and chord "
          "corrections go on while each leaves at most this fraction; one "
          "that does not lower the residual is undone, and Newton goes on "
          "with a new tangent. Near the solution the tangent hardly changes, "
          "so a chord correction gains almost as much as a Newton one at a "
          "fraction of the cost. The converged state meets the same `Newton "
          "tolerance' (dimensionless; 0: every correction with a "
          "new tangent; `Line search = true' and `Linear solver = "
          "direct' and `direct klu' only, the Krylov solvers ignore it).");
        prm.declare_entry(
          "Newton chord across steps",
          "false",
          dealii::Patterns::Bool(),
          "Whether a step starts with chord corrections (true): the LU "
          "factorisation of the last tangent of the step before solves for "
          "the residual of the moved platen, and chord corrections go on "
          "while each leaves at most `Newton chord contraction' of the "
          "residual; the first that does not is undone, and Newton goes on "
          "with a new tangent. A step whose tangent changed little since (an "
          "IMPL-EX step, whose damages are extrapolated) then converges "
          "without a factorisation, the largest cost of a step, at the price "
          "of a few forward and backward substitutions and force "
          "assemblies. The converged states meet the same `Newton "
          "tolerance', so they differ from those of false by what that "
          "tolerance lets through (the single cyclic example with 1e-8: cycle "
          "peaks within 1e-7, 0.72-0.78 of the CPU time; the triple one with 1e-3: "
          "the peak within 2e-4, 0.84 of the CPU time; "
          "doc/notes/wallette-solver-speed.md). The kept factorisation is "
          "let go at every checkpoint, so a run resumed from a checkpoint of "
          "`Checkpoint interval' equals the uninterrupted run to round-off; "
          "one resumed from the checkpoint of a signal (SIGTERM, Ctrl-C) "
          "equals it to the tolerance; another `Checkpoint interval' moves "
          "the results by as much. `Linear solver = direct' and `direct "
          "klu' only (the Krylov solvers ignore it).");
        prm.declare_entry(
          "Residual reference",
          "present reaction",
          Selection("largest reaction|present reaction"),
          "What `Newton tolerance' is relative to: `present reaction', the "
          "norm of the platen reactions of the iterate; `largest "
          "reaction', the larger of that and the largest such norm of the "
          "converged steps so far (the peak force). After the wall has "
          "collapsed the present reactions are near zero, and a tolerance "
          "relative to them asks for residuals of hundredths of a newton "
          "that round-off prevents; relative to the peak force the "
          "tolerance is that of the peak (but a state accepted to it can be "
          "off the exact one by about the tolerance times the peak force, "
          "where `present reaction' is exact to round-off on an elastic "
          "reload). Before the peak of a monotonic run the two are "
          "equal.");
      }

      void
      NewtonSettings::parse_parameters(dealii::ParameterHandler &prm)
      {
        max_newton             = prm.get_integer("Maximum Newton iterations");
        newton_tolerance       = positive_entry(prm, "Newton tolerance");
        line_search            = prm.get_bool("Line search");
        chord_contraction      = prm.get_double("Newton chord contraction");
        chord_across_steps     = prm.get_bool("Newton chord across steps");
        extrapolated_predictor = prm.get("Predictor") == "extrapolated";
        largest_reaction_reference =
          prm.get("Residual reference") == "largest reaction";
      }

      void
      Newton::predict(System &system, const double ratio) const
      {
        // the last step's increment scaled to this one (none after a
        // reversal or a deletion, or in a correction)
        if (settings.extrapolated_predictor && ratio > 0)
          system.u.add(ratio, system.last_increment);
      }

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
                         StepOutcome  &outcome) const
      {
        unsigned int &iterations = outcome.iterations;
        double       &reaction   = outcome.reaction;
        std::string  &non_finite = outcome.non_finite;
        std::string  &failure    = outcome.failure;
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
        // a step may start with chord corrections too, with the
        // factorisation kept from the last step (whose forces at the
        // moved platen are assembled first)
        bool chord = settings.chord_across_steps && solver.has_kept_factors();
        if (chord)
          assembler.assemble(false, time_step);
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
                system.condense(r);
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
                      solver.solve_with_kept_factors(du, r);
                    else
                      solver.solve(system.matrix,
                                   du,
                                   r,
                                   assembler.initial_tangent());
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
                system.distribute(du);
                u_start = system.u;
                system.u.add(1., du);
                if (use_kept)
                  {
                    // one trial: converged, or better (go on from there),
                    // or worse (back to where it started: the next
                    // correction is the Newton one it would have been)
                    assembler.assemble(false, time_step);
                    r = system.f_int;
                    system.condense(r);
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
            system.condense(r);
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
