/**
 * @file
 * The step loop of the wallette model. The parts live in model/ (mesh,
 * joints, interface element, system, point states, integrator, assembler,
 * linear solvers, Newton, step control, deletion, checkpoint) and the
 * outputs in postprocess/; this file builds them once and moves the platen
 * through the protocol:
 *
 *   settings -> mesh -> joints -> system -> protocol -> for each step:
 *   Newton (assembler, linear solver) -> integrator update -> accept ->
 *   deletion -> curve -> postprocessors -> checkpoint
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/wallette.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/stop_signals.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/distributed/shared_tria.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "model/assembler.h"
#include "model/bounds.h"
#include "model/checkpoint.h"
#include "model/deletion.h"
#include "model/floor_correction.h"
#include "model/integrator.h"
#include "model/linear_solvers.h"
#include "model/mesh.h"
#include "model/newton.h"
#include "model/regions.h"
#include "model/report.h"
#include "model/step_control.h"
#include "model/stop_messages.h"
#include "model/system.h"
#include "model/view.h"
#include "postprocess/builtin.h"

namespace masonry
{
  namespace brickwork
  {
    namespace
    {
      using namespace dealii;
      using namespace model;
      using Clock = std::chrono::steady_clock;

      /** One run of the wallette model. */
      class Wallette
      {
      public:
        Wallette(const std::vector<Box> &boxes,
                 const BrickMaterial    &material,
                 const InterfaceLaw     &law,
                 const InterfaceLaw     *splitting_law,
                 const BrickMaterial    *mortar,
                 const WalletteSettings &settings,
                 std::vector<std::unique_ptr<postprocess::Postprocessor>>
                            &postprocessors,
                 RunContext &context);

        void
        run();

      private:
        /** Mesh, joints, system, specimen, point states, caches. */
        void
        setup(const std::vector<Box> &boxes);
        /** The converged step into the curve, the postprocessors and the
         * screen; false (and nothing recorded) when its reaction, strain
         * or damages are not finite. */
        bool
        record_step(const Segment     &leg,
                    const unsigned int its,
                    const unsigned int removed,
                    const unsigned int n_legs);
        /** The converged step becomes the old state. */
        void
        accept_step();
        CheckpointParts
        checkpoint_parts();
        /** Start from zero or from the checkpoint. */
        void
        begin();
        /** Whether `Maximum steps' stops the run after this step. */
        bool
        interrupted(const unsigned int steps_this_run,
                    const unsigned int n_legs,
                    const bool         finished) const;
        /** Summary entries and the closing line. */
        void
        finish(const std::string &status,
               const std::string &message,
               const double       seconds);

        const BrickMaterial &material;
        const InterfaceLaw  &law;
        /** The splitting interfaces' law, nullptr: none. */
        const InterfaceLaw *splitting_law;
        /** The mortar's own law (detailed model; `material' then holds
         * both), nullptr: the simplified model. */
        const BrickMaterial               *mortar;
        const WalletteSettings            &settings;
        RunContext                        &context;
        ConditionalOStream                &pcout;
        parallel::shared::Triangulation<3> triangulation;
        Geometry                           geometry;
        System                             system;
        Joints                             joints;
        Specimen                           specimen;
        PointStates                      bricks, joint_points, splitting_points;
        std::unique_ptr<Integrator>      integrator;
        std::unique_ptr<LinearSolver>    solver;
        std::unique_ptr<Protocol>        protocol;
        std::unique_ptr<StepSizeControl> step_control;
        std::unique_ptr<Assembler>       assembler;
        std::vector<std::unique_ptr<postprocess::Postprocessor>>
                                  &postprocessors;
        std::vector<std::string>   postprocessor_data;
        Progress                   progress;
        std::vector<CurvePoint>    curve;
        RunStatistics              statistics;
        std::unique_ptr<ModelView> view;
      };

      Wallette::Wallette(
        const std::vector<Box> &boxes,
        const BrickMaterial    &material,
        const InterfaceLaw     &law,
        const InterfaceLaw     *splitting_law,
        const BrickMaterial    *mortar,
        const WalletteSettings &settings,
        std::vector<std::unique_ptr<postprocess::Postprocessor>>
                   &postprocessors,
        RunContext &context)
        : material(material)
        , law(law)
        , splitting_law(splitting_law)
        , mortar(mortar)
        , settings(settings)
        , context(context)
        , pcout(context.pcout)
        , triangulation(context.mpi_communicator,
                        Triangulation<3>::none,
                        false,
                        parallel::shared::Triangulation<3>::partition_metis)
        , system(triangulation, context.mpi_communicator)
        , integrator(create_integrator(settings.integrator))
        , solver(create_linear_solver(settings.linear_solver, pcout))
        , protocol(create_protocol(settings.protocol))
        , postprocessors(postprocessors)
      {
        // the threads of the assemblies (0: deal.II's choice at start-up)
        if (settings.integrator.threads > 0)
          MultithreadInfo::set_thread_limit(settings.integrator.threads);
        setup(boxes);
      }

      void
      Wallette::setup(const std::vector<Box> &boxes)
      {
        geometry = settings.mesh.detailed ?
                     make_detailed_mesh(boxes, settings.mesh, triangulation) :
                     make_mesh(boxes, settings.mesh, triangulation);
        system.distribute_dofs();
        const auto spacing = mesh_spacing(settings.mesh);
        joints             = find_joints(system.dof_handler, geometry.height);
        system.setup(joints, geometry, settings.platen, settings.mesh.gauss);
        specimen = make_specimen(triangulation,
                                 geometry.n_bricks,
                                 joints,
                                 settings.specimen);

        AssertThrow(material.nonlocal_length() == 0 ||
                      settings.integrator.implex,
                    ExcMessage("Brick material: `Nonlocal length' > 0 needs "
                               "`Damage integration = implex'"));
        AssertThrow(material.nonlocal_length() == 0 ||
                      !settings.integrator.implex_floor_correction,
                    ExcMessage("Brick material: `Nonlocal length' > 0 needs "
                               "`IMPL-EX floor correction = accept'"));
        // point states: 8 per cell, 4 per joint face, as the laws declare
        std::vector<unsigned int> owned_bricks, owned_joints, owned_splitting;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              if (!material.is_linear())
                {
                  BrickPoint point;
                  point.characteristic_length =
                    specimen.cell_length[cell->active_cell_index()];
                  point.strength_factor =
                    specimen.cell_factor[cell->active_cell_index()];
                  point.region =
                    specimen.cell_region[cell->active_cell_index()];
                  material.check_point(point);
                  for (unsigned int q = 0; q < 8; ++q)
                    owned_bricks.push_back(8 * cell->active_cell_index() + q);
                }
            }
        for (unsigned int n = 0; n < joints.faces.size(); ++n)
          if (joints.faces[n].owned)
            for (unsigned int q = 0; q < InterfaceElement::n_points; ++q)
              (joints.faces[n].type == splitting_type ? owned_splitting :
                                                        owned_joints)
                .push_back(InterfaceElement::n_points * n + q);
        std::vector<double> initial(
          material.is_linear() ? 0 :
                                 n_state_values(material.state_variables()));
        material.initial_state(initial);
        bricks.initialize(8 * triangulation.n_active_cells(),
                          initial,
                          owned_bricks);
        initial.assign(n_state_values(law.state_variables()), 0.);
        law.initial_state(initial);
        joint_points.initialize(InterfaceElement::n_points *
                                  joints.faces.size(),
                                initial,
                                owned_joints);
        AssertThrow(splitting_law ||
                      joints.n_faces_of_type[splitting_type] == 0,
                    ExcMessage("internal error: splitting interfaces "
                               "without a law"));
        // the splitting interfaces' states, indexed like the joints' (only
        // those of splitting faces are used)
        initial.clear();
        if (splitting_law)
          {
            initial.assign(n_state_values(splitting_law->state_variables()),
                           0.);
            splitting_law->initial_state(initial);
          }
        splitting_points.initialize(InterfaceElement::n_points *
                                      joints.faces.size(),
                                    initial,
                                    owned_splitting);

        assembler = std::make_unique<Assembler>(AssemblyParts{system,
                                                              joints,
                                                              specimen,
                                                              material,
                                                              law,
                                                              *integrator,
                                                              bricks,
                                                              joint_points,
                                                              splitting_law,
                                                              splitting_points},
                                                settings.mesh.gauss,
                                                spacing[0]);
        assembler->make_elastic_caches();
        const double nominal = std::abs(settings.protocol.target_displacement /
                                        settings.protocol.n_steps);
        step_control         = create_step_size_control(settings.integrator,
                                                settings.protocol,
                                                settings.newton,
                                                nominal);
        view                 = std::make_unique<ModelView>(ModelView{settings,
                                                     context,
                                                     material,
                                                     law,
                                                     curve,
                                                     geometry,
                                                     system,
                                                     joints,
                                                     specimen,
                                                     assembler->element(),
                                                     bricks,
                                                     joint_points,
                                                     splitting_law,
                                                     splitting_points,
                                                     *protocol,
                                                     progress});
        postprocessor_data.assign(postprocessors.size(), std::string());
      }

      void
      Wallette::accept_step()
      {
        const bool older = integrator->keeps_older();
        for (unsigned int n = 0; n < joints.faces.size(); ++n)
          if (joints.faces[n].owned)
            for (unsigned int q = 0; q < InterfaceElement::n_points; ++q)
              (joints.faces[n].type == splitting_type ? splitting_points :
                                                        joint_points)
                .accept(InterfaceElement::n_points * n + q, older);
        if (!material.is_linear())
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned() &&
                !specimen.deleted[cell->active_cell_index()])
              for (unsigned int q = 0; q < 8; ++q)
                bricks.accept(8 * cell->active_cell_index() + q, older);
        // the deletion and the output evaluate the law with them
        specimen.nonlocal_factors = assembler->nonlocal_factors();
      }

      bool
      Wallette::record_step(const Segment     &leg,
                            const unsigned int its,
                            const unsigned int removed,
                            const unsigned int n_legs)
      {
        CurvePoint p;
        p.displacement = progress.applied;
        p.strain       = progress.applied / geometry.height;
        p.force        = system.reaction();
        p.stress       = p.force / geometry.gross_area;
        p.newton       = its;
        std::tie(p.max_damage, p.brick_damages) = max_damages(*view);
        p.gauge_strain                          = system.gauge_strain();
        p.cycle                                 = leg.cycle;
        p.unloading                             = leg.unloading;
        p.deleted                               = specimen.n_deleted;
        bool finite = std::isfinite(p.force) && std::isfinite(p.stress) &&
                      std::isfinite(p.max_damage) &&
                      std::isfinite(p.gauge_strain);
        for (const double d : p.brick_damages)
          finite = finite && std::isfinite(d);
        if (!finite)
          return false;
        curve.push_back(p);
        for (auto &pp : postprocessors)
          pp->step(*view);
        pcout << "Step " << progress.step;
        if (n_legs > 1)
          pcout << " (cycle " << leg.cycle
                << (leg.unloading ? ", unloading" : "") << ")";
        pcout << ": strain " << std::setprecision(4) << p.strain << ", stress "
              << p.stress * 1e-6 << " MPa, max damage " << p.max_damage;
        if (!p.brick_damages.empty())
          {
            pcout << ", bricks ";
            for (unsigned int k = 0; k < p.brick_damages.size(); ++k)
              pcout << (k > 0 ? " / " : "") << p.brick_damages[k];
          }
        pcout << ", " << its << " Newton iterations";
        if (removed > 0)
          pcout << ", " << removed << " cells deleted";
        pcout << std::setprecision(6) << "\n";
        return true;
      }

      CheckpointParts
      Wallette::checkpoint_parts()
      {
        return {progress,
                curve,
                statistics,
                specimen,
                bricks,
                joint_points,
                splitting_points,
                *solver,
                *step_control,
                system,
                postprocessor_data};
      }

      void
      Wallette::begin()
      {
        if (settings.checkpoint.resume)
          {
            auto parts = checkpoint_parts();
            load_checkpoint(parts, context, postprocessors.size());
            for (unsigned int i = 0; i < postprocessors.size(); ++i)
              try
                {
                  postprocessors[i]->load(postprocessor_data[i]);
                }
              catch (const std::exception &e)
                {
                  AssertThrow(false, other_postprocessors(e.what()));
                }
            pcout << "Resumed from the checkpoint at step " << progress.step
                  << " (platen displacement " << progress.applied << " m)\n";
            for (auto &pp : postprocessors)
              pp->resume(*view);
          }
        else
          {
            curve.emplace_back();
            for (auto &pp : postprocessors)
              pp->start(*view);
            for (auto &pp : postprocessors)
              pp->output(*view, 0, 0);
          }
      }

      bool
      Wallette::interrupted(const unsigned int steps_this_run,
                            const unsigned int n_legs,
                            const bool         finished) const
      {
        const unsigned int max_steps = settings.protocol.max_steps;
        return max_steps > 0 && steps_this_run >= max_steps &&
               progress.segment < n_legs && !finished;
      }

      void
      Wallette::run()
      {
        const auto  start = Clock::now();
        StopSignals stop_signals;
        describe_model(*view, mortar);
        const std::vector<Segment> legs = protocol->legs();
        const double nominal = std::abs(settings.protocol.target_displacement /
                                        settings.protocol.n_steps);
        progress.increment   = nominal;
        begin();
        if (legs.size() > 1)
          pcout << "Protocol: " << legs.size() / 2
                << " load-unload cycles, unloading to "
                << settings.protocol.unloading_stress * 1e-6 << " MPa\n";

        const Newton newton(settings.newton,
                            1e-6 * material.youngs_modulus() *
                              geometry.gross_area *
                              std::abs(settings.protocol.target_displacement) /
                              geometry.height);
        const auto   save = [&](const std::string &status) {
          for (unsigned int i = 0; i < postprocessors.size(); ++i)
            postprocessor_data[i] = postprocessors[i]->save();
          save_checkpoint(checkpoint_parts(), status, context);
        };
        unsigned int consecutive_cutbacks = 0, steps_this_run = 0,
                     small_steps = 0;
        std::string status       = "completed", message, non_finite;
        // a non-finite failure since the steps fell below the stall floor
        std::string recent_non_finite;
        // no progress: steps this small, stall_steps in a row
        const double stall_floor = stall_step(settings.integrator, nominal);
        // the state of the last converged step is bad: not written
        bool bad_state = false;
        // the physical bound on the platen stress (model/bounds.h)
        const std::array<double, 2> bound = bound_materials(material, mortar);
        System::Vector              u_converged(system.u);
        FloorCorrection             correction({bricks,
                                                joint_points,
                                                splitting_points,
                                                material,
                                                law,
                                                splitting_law},
                                   *integrator,
                                   *step_control,
                                   settings.integrator.implex_tolerance,
                                   context.mpi_communicator,
                                   pcout);
        // along the direction: positive displacement is the loading sense
        while (progress.segment < legs.size())
          {
            const Segment &leg = legs[progress.segment];
            double         next;
            if (!next_position(
                  leg, curve, settings.protocol, nominal, progress, next))
              {
                if (progress.segment < legs.size())
                  step_control->start_leg(legs[progress.segment], progress);
                continue;
              }
            const double applied   = progress.applied;
            const double taken     = std::abs(next - applied);
            const double time_step = taken / settings.protocol.platen_speed;
            // IMPL-EX: no extrapolation across a reversal, at most the
            // step growth (an unbounded ratio made the cyclic examples run
            // away: doc/brickwork.md, IMPL-EX; brickwork_implex_ratio)
            const double ratio = progress.last_increment > 0 &&
                                     curve.size() > 1 &&
                                     curve.back().unloading == leg.unloading &&
                                     curve.back().cycle == leg.cycle ?
                                   std::min(taken / progress.last_increment,
                                            settings.protocol.growth) :
                                   0.;
            integrator->set_ratio(ratio);
            step_control->set_leg(leg);
            // the predictor: the last step's increment scaled to this one
            // (none after a reversal or a deletion, or in a correction)
            if (settings.newton.extrapolated_predictor && ratio > 0 &&
                !correction.active())
              system.u.add(ratio, system.last_increment);
            unsigned int its      = 0;
            double       reaction = 0;
            std::string  failure;
            bool         ok = newton.solve_step(system,
                                        *assembler,
                                        *solver,
                                        next,
                                        time_step,
                                        progress.largest_reaction,
                                        its,
                                        reaction,
                                        non_finite,
                                        failure);
            statistics.total_newton += its;
            // a converged mechanism is no state of the wallette: a
            // smaller step, or the run stops (model/deletion.h)
            if (ok)
              failure = mechanism_problem(system, specimen);
            ok = ok && failure.empty();
            if (!ok && correction.active())
              {
                system.u = u_converged;
                correction.fail(failure, taken, progress);
                continue;
              }
            if (!ok)
              {
                system.u = u_converged;
                ++statistics.total_cutbacks;
                // a converged step resets the consecutive count, so the
                // step is also bounded below: otherwise tiny converged
                // steps between failures halve it without end
                const double lower_bound =
                  std::ldexp(nominal, -int(settings.protocol.max_cutbacks));
                const bool too_many =
                  ++consecutive_cutbacks > settings.protocol.max_cutbacks;
                if (too_many || progress.increment < lower_bound)
                  {
                    message =
                      cutback_stop_message({consecutive_cutbacks - 1,
                                            statistics.total_cutbacks,
                                            settings.protocol.max_cutbacks,
                                            too_many,
                                            lower_bound,
                                            next,
                                            taken,
                                            applied,
                                            non_finite,
                                            failure},
                                           status);
                    pcout << "Stopped: " << message << "\n";
                    break;
                  }
                if (!non_finite.empty())
                  recent_non_finite = non_finite;
                progress.increment /= 2;
                progress.easy_steps = 0;
                pcout << "  cut-back: step halved to " << progress.increment
                      << " m (" << failure << ")\n";
                continue;
              }
            consecutive_cutbacks = 0;
            const double error = integrator->after_step(*assembler, time_step);
            if (!std::isfinite(error))
              {
                // (std::max would keep a NaN step and the run would go on)
                system.u = u_converged;
                status   = "failed";
                message  = "a number that is not finite (nan or inf) in " +
                          assembler->non_finite() +
                          " in the IMPL-EX update after the step to platen "
                          "displacement " +
                          Utilities::to_string(next) + " m; check " +
                          likely_entries(assembler->non_finite()) +
                          "; results up to the step before are written";
                pcout << "Stopped: " << message << "\n";
                break;
              }
            if (correction.active())
              {
                const FloorCorrection::Next then =
                  correction.again(taken, progress);
                if (then == FloorCorrection::Next::redo)
                  system.u = u_converged;
                if (then != FloorCorrection::Next::accept)
                  continue;
              }
            else
              {
                const Verdict verdict =
                  step_control->judge(taken, error, progress);
                if (verdict == Verdict::redo)
                  {
                    system.u = u_converged;
                    pcout << "  IMPL-EX: step redone (damage error " << error
                          << "), step " << progress.increment << " m\n";
                    continue;
                  }
                if (verdict == Verdict::correct && correction.wanted())
                  {
                    correction.start(error, step_control->may_redo(taken));
                    continue;
                  }
              }
            correction.accepted();
            accept_step();
            progress.last_increment = taken;
            progress.largest_reaction =
              std::max(progress.largest_reaction, reaction);
            system.last_increment = system.u;
            system.last_increment -= u_converged;
            u_converged = system.u;
            progress.time += time_step;
            progress.applied = next;
            ++progress.step;
            ++steps_this_run;
            unsigned int       faded   = 0;
            const unsigned int removed = delete_cells(settings.specimen,
                                                      joints,
                                                      material,
                                                      bricks,
                                                      system,
                                                      specimen,
                                                      faded);
            // the deleted cells' DOFs are fixed from now on: no
            // extrapolation across the change of the structure
            if (removed > 0)
              system.last_increment = 0;
            if (removed > 0 || faded > 0)
              {
                assembler->invalidate();
                solver->forget();
              }
            if (!record_step(leg, its, removed, legs.size()))
              {
                status    = "failed";
                bad_state = true;
                message =
                  "the platen reaction, the gauge strain or a damage is not "
                  "finite (nan or inf) after the step to platen displacement " +
                  Utilities::to_string(next) + " m; check " +
                  likely_entries("bricks") + " and " +
                  likely_entries("joints") +
                  "; results up to the step before are written";
                pcout << "Stopped: " << message << "\n";
                break;
              }
            // a physical end (collapse, status completed) or none: a
            // solution that ran away (model/bounds.h)
            const std::string collapse =
              collapse_problem(curve, settings.protocol.collapse_ratio);
            const std::string end = !collapse.empty() ?
                                      collapse :
                                      runaway_problem(curve.back().stress,
                                                      curve.back().strain,
                                                      bound[0],
                                                      bound[1]);
            if (!end.empty())
              {
                message = end + " (step " + std::to_string(progress.step) +
                          "); results up to there are written";
                pcout << "Stopped: " << message << "\n";
                if (!collapse.empty())
                  for (auto &pp : postprocessors)
                    pp->output(*view, progress.step, curve.back().strain);
                else
                  status = "failed";
                break;
              }
            small_steps = taken < stall_floor ? small_steps + 1 : 0;
            if (small_steps == 0)
              recent_non_finite.clear();
            if (small_steps >= stall_steps)
              {
                message = stall_message(recent_non_finite,
                                        stall_floor,
                                        nominal,
                                        taken,
                                        next,
                                        settings.integrator.implex,
                                        status);
                pcout << "Stopped: " << message << "\n";
                break;
              }
            // the step that ends the last leg (in a cyclic run an unloading
            // one) writes its state whatever the output interval
            const bool last =
              progress.segment + 1 == legs.size() &&
              leg_done(leg, curve, settings.protocol, nominal, progress);
            const unsigned int interval = settings.output.vtu_interval;
            if ((interval > 0 && progress.step % interval == 0) || last)
              for (auto &pp : postprocessors)
                pp->output(*view, progress.step, curve.back().strain);
            step_control->after_step(its, progress);
            if (settings.checkpoint.checkpoint_interval > 0 &&
                progress.step % settings.checkpoint.checkpoint_interval == 0)
              save("running");
            if (interrupted(steps_this_run, legs.size(), last))
              {
                status  = "interrupted";
                message = "stopped after `Maximum steps' = " +
                          std::to_string(settings.protocol.max_steps) +
                          " steps; `set Resume = true' continues from the "
                          "checkpoint";
                pcout << "Stopped: " << message << "\n";
                break;
              }
            // a batch system's time limit or Ctrl-C: stop here, with the
            // checkpoint written below
            if (const int signal = stop_signals.received(system.comm))
              {
                status  = "interrupted";
                message = StopSignals::name(signal) + " received: stopped " +
                          "after step " + std::to_string(progress.step) +
                          "; `set Resume = true' continues from the "
                          "checkpoint";
                pcout << "Stopped: " << message << "\n";
                break;
              }
          }
        if (status != "completed")
          {
            system.u = u_converged;
            if (!bad_state)
              {
                for (auto &pp : postprocessors)
                  pp->output(*view, progress.step, curve.back().strain);
                save(status);
              }
          }
        finish(status,
               message,
               std::chrono::duration<double>(Clock::now() - start).count());
      }

      void
      Wallette::finish(const std::string &status,
                       const std::string &message,
                       const double       seconds)
      {
        Json &summary = context.summary;
        for (auto &pp : postprocessors)
          pp->finish(*view, summary);
        const MPI_Comm comm = context.mpi_communicator;
        summary["status"]   = status;
        if (!message.empty())
          summary["message"] = message;
        const auto &a                        = assembler->statistics;
        const auto &s                        = solver->statistics;
        summary["steps"]                     = progress.step;
        summary["newton_iterations"]         = statistics.total_newton;
        summary["cut_backs"]                 = statistics.total_cutbacks;
        summary["linear_solves"]             = s.n_solves;
        summary["matrix_assemblies"]         = a.n_matrix_assemblies;
        summary["factorisations_reused"]     = s.n_factorisations_reused;
        summary["factorisations"]            = s.n_factorisations;
        summary["null_pivot_factorisations"] = s.n_null_pivot_factorisations;
        summary["reuse_gmres_solves"]        = s.n_reuse_solves;
        summary["reuse_gmres_iterations"]    = s.n_reuse_iterations;
        summary["chord_solves"]              = s.n_chord_solves;
        summary["deleted_cells"]             = specimen.n_deleted;
        summary["direct_solver_fallbacks"]   = s.n_direct_fallbacks;
        step_control->write_summary(summary);
        // share of the evaluations skipped by the elastic check, over all
        // ranks (work skipped where nothing can change)
        const auto elastic_fraction = [&](const unsigned long elastic,
                                          const unsigned long evaluated) {
          const double e   = Utilities::MPI::sum(double(elastic), comm),
                       all = e + Utilities::MPI::sum(double(evaluated), comm);
          return all > 0 ? e / all : 0.;
        };
        if (!material.is_linear())
          summary["cell_evaluations_elastic_fraction"] =
            elastic_fraction(a.n_elastic_cells, a.n_material_cells);
        if (!law.is_linear() || splitting_law)
          summary["interface_evaluations_elastic_fraction"] =
            elastic_fraction(a.n_elastic_interfaces, a.n_law_interfaces);
        summary["seconds"]          = seconds;
        summary["seconds_assembly"] = a.seconds;
        summary["seconds_solve"]    = s.seconds;
        pcout << "Result: peak stress " << std::setprecision(6)
              << summary["peak_stress"].get<double>() * 1e-6
              << " MPa at strain " << summary["strain_at_peak"].get<double>()
              << ", initial modulus "
              << summary["initial_modulus"].get<double>() * 1e-9 << " GPa; "
              << progress.step << " steps, " << statistics.total_newton
              << " Newton iterations, " << statistics.total_cutbacks
              << " cut-backs";
        if (specimen.n_deleted > 0)
          pcout << ", " << specimen.n_deleted << " cells deleted";
        pcout << "\n";
      }
    } // namespace

    void
    run_wallette(
      const std::vector<Box>                                   &boxes,
      const BrickMaterial                                      &material,
      const InterfaceLaw                                       &law,
      const WalletteSettings                                   &settings,
      std::vector<std::unique_ptr<postprocess::Postprocessor>> &postprocessors,
      RunContext                                               &context,
      const InterfaceLaw                                       *splitting_law,
      const BrickMaterial                                      *mortar_material)
    {
      if (!settings.mesh.detailed)
        check_mesh(boxes, settings.mesh);
      AssertThrow(!settings.mesh.split_units || splitting_law,
                  ExcMessage("internal error: split units need the "
                             "splitting interfaces' law"));
      AssertThrow(!settings.mesh.detailed || mortar_material,
                  ExcMessage("internal error: the detailed model needs the "
                             "mortar's material"));
      // the detailed model: units and mortar behind one material
      std::unique_ptr<BrickMaterial> regions;
      if (settings.mesh.detailed)
        regions = std::make_unique<RegionMaterial>(material, *mortar_material);
      Wallette wallette(boxes,
                        regions ? *regions : material,
                        law,
                        splitting_law,
                        settings.mesh.detailed ? mortar_material : nullptr,
                        settings,
                        postprocessors,
                        context);
      wallette.run();
    }
  } // namespace brickwork
} // namespace masonry
