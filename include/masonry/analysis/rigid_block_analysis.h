/**
 * @file
 * The common part of the rigid-block analyses (`settlement`, `limit load`,
 * `minimum thickness`): the block discretisation, supports, dead loads,
 * the interface model, the LP solver and the results.
 */
#ifndef masonry_analysis_rigid_block_analysis_h
#define masonry_analysis_rigid_block_analysis_h

#include <masonry/analysis/interface.h>
#include <masonry/lp/interface.h>
#include <masonry/rigid_blocks/block_model.h>
#include <masonry/rigid_blocks/output.h>

#include <deal.II/base/function_parser.h>

#include <functional>
#include <memory>

namespace masonry
{
  namespace geometry
  {
    class Interface;
  }
  namespace rigid_blocks
  {
    class InterfaceModel;
    struct MechanismProblem;
    namespace postprocess
    {
      class Interface;
    }
  } // namespace rigid_blocks
  namespace adaptation
  {
    class Optimiser;
  }

  namespace analysis
  {
    /**
     * Base class of analyses of a vault cut into rigid blocks. A derived
     * class declares the shared entries with declare_block_parameters() in
     * its own subsection, reads them with parse_block_parameters(), and in
     * run() calls build_model() and then solve() on the LPs it assembles.
     */
    class RigidBlockAnalysis : public Interface
    {
    public:
      /** Constructor (out of line: the members' types are incomplete). */
      RigidBlockAnalysis();

      /** Destructor. */
      ~RigidBlockAnalysis() override;

      /**
       * Declare the entries shared by rigid-block analyses: blocks along u
       * and v, stations per edge, quadrature points, supported edges,
       * support contact, surface load and the output options.
       */
      static void
      declare_block_parameters(dealii::ParameterHandler &prm);

      /**
       * Create the geometry model, the LP solver and the interface model,
       * and build the blocks once (so that `--validate` finds bad labels
       * and geometry).
       */
      void
      setup(dealii::ParameterHandler &prm) override;

      /**
       * Adapt the mesh if an optimiser is selected (`subsection
       * Adaptation`), then analyse() the (best) mesh.
       */
      void
      run(RunContext &context) final;

    protected:
      /** The analysis of the current mesh, with all its output. */
      virtual void
      analyse(RunContext &context) = 0;

      /**
       * The quantity the adaptation maximises for the current mesh
       * (`mesh_vertices`), without output: −∞ if the mesh has no optimal
       * answer.
       */
      virtual double
      evaluate(RunContext &context) = 0;

      /** Name and unit of the quantity evaluate() returns. */
      virtual std::string
      fitness_name() const = 0;

      /**
       * evaluate(), and the crack activity of the model it solved into
       * @p activity (crack_activity(): two numbers per interface), for
       * `Optimiser = crack refinement`. By default an error: only analyses that
       * override it (`settlement`) can be refined at their cracks.
       */
      virtual double
      evaluate_cracks(RunContext &context, std::vector<double> &activity);

      /**
       * The crack activity of every interface of the current model under
       * the block motion @p motion and the ground motion @p ground (zero
       * if null), two numbers per interface k: [2k] Σ over its contact
       * points of tributary area × |jump|, [2k + 1] Σ area × |jump − the
       * mean jump of its intrados or extrados points| (how much the jump
       * varies along the interface), m³ per unit of the motion.
       */
      std::vector<double>
      crack_activity(
        const rigid_blocks::Motion                                     &motion,
        const std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &,
                                                 const std::string &)> &ground)
        const;

      /**
       * The crack activity of every block of the current model from that
       * of the interfaces (@p activity, as crack_activity() returns it):
       * half the [2k] number of every interface k between two blocks to
       * each, all of a support interface's to its block (m³).
       */
      std::vector<double>
      block_activity(const std::vector<double> &activity) const;

      /**
       * The parameter meshes of the `lines' genes: per patch n_u − 1 genes
       * for the lines u = const, then n_v − 1 genes shared by all patches
       * for the lines v = const; each group is sorted and mapped to
       * positions k h + q_k (1 − n h) with h the minimum block size.
       */
      std::vector<std::vector<dealii::Point<2>>>
      vertices_from_genes(const std::vector<double> &genes) const;

      /** The genes of the uniform mesh. */
      std::vector<double>
      uniform_genes() const;

      /** Read the shared entries; @p section names the subsection. */
      void
      parse_block_parameters(dealii::ParameterHandler &prm,
                             const std::string        &section);

      /**
       * Build the blocks and interfaces from the geometry (with its current
       * thickness factor) and the dead loads on every block: self weight and
       * surface load.
       */
      void
      build_model();

      /**
       * After geometry->set_thickness_factor(): the blocks, interfaces and
       * dead loads of the current model at the new thickness, from the
       * middle-surface samples the model kept
       * (rigid_blocks::BlockModel::update_thickness(); the same numbers as
       * build_model(), without evaluating the NURBS patches again).
       * build_model() if there is no model yet.
       */
      void
      update_thickness();

      /** `Adaptation/Reuse evaluations' (true without an optimiser's
       * parameters). */
      bool
      reuse_evaluations() const;

      /** dead_force and dead_moment of the current model: self weight and
       * `Surface load'. */
      void
      compute_dead_loads();

      /** Total magnitude of the dead loads (N). */
      double
      dead_load_magnitude() const;

      /**
       * Write @p lp to @p mps_name in the output directory if `Export MPS
       * file` is set (and this is not an adaptation's silent evaluation).
       */
      void
      export_lp(const lp::LinearProgram &lp,
                RunContext              &context,
                const std::string       &mps_name = "lp.mps") const;

      /**
       * Solve @p lp, timing it into seconds_solve, and write it to
       * @p mps_name in the output directory if `Export MPS file` is set.
       * With @p warm (and `LP solver/Warm starts` true), the solver starts
       * from (and updates) that state (lp::Interface::solve_warm()).
       */
      lp::Solution
      solve(const lp::LinearProgram &lp,
            RunContext              &context,
            const std::string       &mps_name = "lp.mps",
            lp::WarmStart           *warm     = nullptr);

      /**
       * The check of an optimal @p solution on its LP (lp::Solution::check,
       * which solve() fills in for every optimum) into the summary:
       * `lp_max_violation` (largest bound violation), `lp_dual_violation`,
       * `lp_relative_gap` and `lp_check` (`passed' or `failed'); a warning
       * on screen with the numbers if it fails `LP solver/Optimality check
       * tolerance`.
       */
      void
      check_solution(const lp::Solution &solution, RunContext &context) const;

      /** Sizes and timings of the model and the LP into the summary. */
      void
      record(const lp::LinearProgram &lp,
             const lp::Solution      &solution,
             RunContext              &context) const;

      /**
       * The sizes of the model and the timings so far into the summary
       * (what record() writes without an LP solution), and the LP's size
       * if @p lp is given.
       */
      void
      record_model(RunContext &context, const lp::LinearProgram *lp) const;

      /** CPU time of the calling thread, s. */
      static double
      thread_cpu_seconds();

      /**
       * The block of patch @p patch whose cell contains the parameter point
       * @p uv (the first one if @p uv is on a cell edge).
       */
      unsigned int
      locate_block(const unsigned int patch, const dealii::Point<2> &uv) const;

      /**
       * End a run without an optimum: set `status` and `explanation` in the
       * summary, print them, and run the postprocessors that write without
       * a solution (the `report' page: the status, the explanation and
       * whatever diagnostics the summary holds, on the undeformed blocks
       * with the prescribed support motion).
       */
      void
      report(RunContext        &context,
             const std::string &status,
             const std::string &explanation) const;

      /**
       * The prescribed motion of the supports (m) for the outputs of a run
       * without an optimum: none by default; `settlement' gives its
       * settlement.
       */
      virtual rigid_blocks::SupportMotion
      prescribed_support_motion() const;

      /**
       * The factor that makes the largest centroid translation of the
       * block columns of @p x equal to 1 cm (a mechanism's magnitude is
       * arbitrary).
       */
      double
      centimetre_scale(const std::vector<double> &x) const;

      /**
       * Run the postprocessors of `Postprocess/Rigid blocks/List of
       * postprocessors` on the result: the block motion, the support motion
       * (@p supports_move: prescribed, as in a settlement analysis) and the
       * contact forces (N per contact point, as returned by
       * rigid_blocks::contact_forces()). Records `seconds_output`.
       */
      void
      write_results(const rigid_blocks::Motion               &motion,
                    const rigid_blocks::SupportMotion        &support_motion,
                    const bool                                supports_move,
                    const std::vector<std::array<double, 3>> &forces,
                    RunContext                               &context) const;

      /**
       * Write the results of a mechanism with fixed supports: write_results()
       * with a zero support motion.
       */
      void
      write_mechanism(const rigid_blocks::Motion               &motion,
                      const std::vector<std::array<double, 3>> &forces,
                      RunContext                               &context) const;

      /** Comma-separated labels as a set (empty entries dropped). */
      static std::set<std::string>
      split_labels(const std::string &text);

      /** Run the optimiser and set mesh_vertices to the best mesh. */
      void
      adapt(RunContext &context);

      /**
       * After adapt()'s evaluations: the state of the final analysis, on
       * the mesh of @p genes, with screen output, its timings and counts
       * from zero, and without the other threads' copies.
       */
      void
      finish_adaptation(const std::vector<double> &genes);

      /**
       * `Optimiser = crack refinement` (source/adaptation/
       * crack_refinement.cc): from the uniform mesh, `Stages` times solve
       * (evaluate_cracks()) and split the parameter strips where the
       * mechanism cracks most; set mesh_vertices (and the numbers of
       * blocks in `options`) to the last mesh.
       */
      void
      refine_at_cracks(RunContext &context);

      /**
       * Parameter-space vertices of every patch (empty: uniform), used by
       * build_model().
       */
      std::vector<std::vector<dealii::Point<2>>> mesh_vertices;
      /** The optimiser (`none` by default). */
      std::unique_ptr<adaptation::Optimiser> optimiser;
      /** Its name. */
      std::string optimiser_name;
      /** True while the adaptation evaluates meshes: no screen output. */
      bool quiet = false;
      /**
       * Copies of this analysis for the adaptation's other threads
       * (`Adaptation/Threads' − 1), each set up from the same parameters
       * with its own geometry, LP solver and blocks, so that islands are
       * evaluated concurrently without sharing any mutable state.
       */
      std::vector<std::unique_ptr<RigidBlockAnalysis>> workers;
      /** Whether this analysis is such a copy (it makes none itself). */
      bool is_worker = false;

      /** The subsection name (for error messages). */
      std::string section;
      /** The discretisation. */
      rigid_blocks::Discretisation options;
      /** Whether supports are bonded (rigid) rather than unilateral. */
      bool bonded_supports = false;
      /** `Implied contact rows = leave out`. */
      bool leave_out_implied_rows = true;
      /** Extra vertical dead load per unit area, Pa. */
      dealii::FunctionParser<3> surface_load{1};
      /** Output options. */
      rigid_blocks::OutputOptions output_options;
      /** The listed postprocessors, in the order they run. */
      std::vector<
        std::pair<std::string,
                  std::unique_ptr<rigid_blocks::postprocess::Interface>>>
        postprocessors;
      /** The geometry. */
      std::unique_ptr<geometry::Interface> geometry;
      /** The LP solver. */
      std::unique_ptr<lp::Interface> solver;
      /** Its name. */
      std::string solver_name;
      /** The interface model. */
      std::unique_ptr<rigid_blocks::InterfaceModel> joints;
      /** Its name. */
      std::string joints_name;
      /** The blocks. */
      std::unique_ptr<rigid_blocks::BlockModel> model;
      /** mesh_vertices when @p model was built (update_thickness() builds
       * a new model if the mesh has changed since). */
      std::vector<std::vector<dealii::Point<2>>> model_vertices;
      /** Dead loads on every block: force (N) and moment about the
       * centroid (N·m), self weight included. */
      std::vector<dealii::Tensor<1, 3>> dead_force, dead_moment;
      /** Seconds spent in build_model(), assembly and solve(). */
      double seconds_geometry = 0, seconds_assembly = 0, seconds_solve = 0;
      /** CPU seconds of the solving thread in solve() (unlike seconds_solve,
       * not inflated by other processes on a shared machine). */
      double cpu_seconds_solve = 0;
      /** Number of LP solves and their iterations. */
      unsigned int n_solves = 0, n_iterations = 0;
    };
  } // namespace analysis
} // namespace masonry

#endif
