/**
 * @file
 * The wallette analysis's solver entries: see wallette_solver_entries.h.
 */
#include <masonry/brickwork/wallette.h>
#include <masonry/core/parameters.h>

#include <deal.II/base/parameter_handler.h>

#include "wallette_solver_entries.h"

namespace masonry
{
  namespace analysis
  {
    void
    declare_solver_entries(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
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
      prm.declare_entry("Step growth factor",
                        "2",
                        Double(1),
                        "Factor on the step after an easy step "
                        "(dimensionless, >= 1); also the largest factor "
                        "by which IMPL-EX extrapolates the last step's "
                        "changes of the internal variables.");
      prm.declare_entry("Maximum Newton iterations",
                        "20",
                        Integer(1, 1000),
                        "Newton-Raphson iterations of a step before it is "
                        "cut back.");
      prm.declare_entry("Newton tolerance",
                        "1e-8",
                        Double(0),
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
      prm.declare_entry(
        "Newton chord contraction",
        "0.1",
        Double(0),
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
      prm.declare_entry(
        "Assembly threads",
        "1",
        Integer(0),
        "Threads of each MPI rank that evaluate the laws of the cells and "
        "interfaces in an assembly (dimensionless count; 0: the cores "
        "divided among the ranks; the environment variable "
        "DEAL_II_NUM_THREADS caps it). The forces and tangents are summed "
        "in the order of the cells and what comes from deal.II's FEValues "
        "is computed on one thread, so the results are the same bit for "
        "bit with any number of threads. More threads shorten the "
        "assembly, some 40 % of the CPU time of a detailed wallette, on "
        "idle cores; on cores shared with other jobs they cost CPU time "
        "and gain little wall time (doc/notes/wallette-solver-speed.md).");
      prm.declare_entry(
        "Linear solver",
        "direct",
        Selection("direct|direct klu|cg amg|gmres amg"),
        "`direct': sparse LU by MUMPS through Trilinos Amesos (parallel); "
        "`direct klu': Amesos KLU (serial, gathers the matrix); `cg amg': "
        "conjugate gradients with Trilinos ML algebraic multigrid (for "
        "symmetric tangents: elastic joints); `gmres amg': GMRES with the "
        "same preconditioner (any tangent). A Krylov solve that fails "
        "(1000 iterations, or AztecOO's loss of precision on a cracked "
        "tangent) is redone by MUMPS, and MUMPS solves the rest of the "
        "run (damage does not heal); summary.json: "
        "direct_solver_fallbacks. Below some 10^5 DOFs `direct' is "
        "usually the fastest for damaged wallettes.");
      prm.declare_entry(
        "Factorisation reuse iterations",
        "0",
        Integer(0, 1000),
        "`Linear solver = direct' only: a Newton correction is first "
        "solved by GMRES with the last LU factorisation (of an earlier "
        "tangent) as the preconditioner, to `Linear solver tolerance'; "
        "when GMRES needs more than this many iterations the tangent is "
        "factorised anew and solved directly (dimensionless count; 0: "
        "every solve factorises). Saves factorisations while the tangent "
        "changes little (elastic legs, IMPL-EX steps); the Newton "
        "iterates differ from those of the direct solve by the linear "
        "tolerance, the converged states by the `Newton tolerance'.");
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
        "moved one by +3.3 % (contrib/benchmarks/wallette_cyclic/README.md).");
      prm.declare_entry("Linear solver tolerance",
                        "1e-10",
                        Double(0),
                        "Relative residual tolerance of the iterative "
                        "linear solvers (dimensionless).");
    }

    double
    positive_entry(dealii::ParameterHandler &prm, const std::string &entry)
    {
      const double v = prm.get_double(entry);
      AssertThrow(v > 0,
                  ExcParameter(entry,
                               "must be positive, got " + prm.get(entry)));
      return v;
    }

    void
    parse_solver_entries(dealii::ParameterHandler    &prm,
                         brickwork::WalletteSettings &s)
    {
      auto positive = [&](const std::string &entry) {
        return positive_entry(prm, entry);
      };
      s.protocol.max_cutbacks    = prm.get_integer("Maximum cut-backs");
      s.protocol.growth          = prm.get_double("Step growth factor");
      s.newton.max_newton        = prm.get_integer("Maximum Newton iterations");
      s.newton.newton_tolerance  = positive("Newton tolerance");
      s.newton.line_search       = prm.get_bool("Line search");
      s.newton.chord_contraction = prm.get_double("Newton chord contraction");
      s.newton.extrapolated_predictor = prm.get("Predictor") == "extrapolated";
      s.newton.largest_reaction_reference =
        prm.get("Residual reference") == "largest reaction";
      s.integrator.threads = prm.get_integer("Assembly threads");
      s.linear_solver.reuse_iterations =
        prm.get_integer("Factorisation reuse iterations");
      s.linear_solver.linear_solver    = prm.get("Linear solver");
      s.linear_solver.linear_tolerance = positive("Linear solver tolerance");
      s.integrator.implex_floor_correction =
        prm.get("IMPL-EX floor correction") != "accept";
      s.integrator.implex_correct_any_step =
        prm.get("IMPL-EX floor correction") == "iterate at any step";
      s.integrator.implex_minimum_step_unloading =
        prm.get_double("IMPL-EX minimum step when unloading");
    }
  } // namespace analysis
} // namespace masonry
