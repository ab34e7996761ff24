/**
 * @file
 * The step loop of the wallette model. The parts live in folders that read
 * in the order the data flows (specimen/: mesh, joints, specimen; assembly/:
 * interface element, point states, integrators, assembler; solution/:
 * system, linear solvers, Newton, step controller, deletion; protocols/;
 * laws/; postprocess/; checkpoint); this file builds them once and moves the
 * platen through the protocol:
 *
 *   settings -> mesh -> joints -> system -> specimen, point states ->
 *   for each step of the step controller: Newton (assembler, linear
 *   solver) -> update of the states -> the controller's decision (accept,
 *   redo, correct, stop) -> accept -> deletion -> curve -> postprocessors
 *   -> checkpoint
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>
#include <masonry/core/output_directory.h>
#include <masonry/core/stop_signals.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/distributed/shared_tria.h>

#include "wallette.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <typeinfo>

#include "curve_summary.h"
#include "postprocess/report.h"
#include "postprocess/view.h"
#include "solution/bounds.h"
#include "solution/stop_messages.h"

namespace masonry
{
  namespace brickwork
  {
    void
    WalletteSettings::declare_parameters(dealii::ParameterHandler &prm)
    {
      MeshSettings::declare_parameters(prm);
      model::PlatenSettings::declare_parameters(prm);
      model::StepSettings::declare_parameters(prm);
      model::NewtonSettings::declare_parameters(prm);
      model::AssemblySettings::declare_parameters(prm);
      model::SpecimenSettings::declare_parameters(prm);
      model::DeletionSettings::declare_parameters(prm);
      OutputSettings::declare_parameters(prm);
      model::CheckpointSettings::declare_parameters(prm);
    }

    void
    WalletteSettings::parse_parameters(dealii::ParameterHandler &prm)
    {
      mesh.parse_parameters(prm);
      platen.parse_parameters(prm);
      steps.parse_parameters(prm);
      newton.parse_parameters(prm);
      assembly.parse_parameters(prm);
      specimen.parse_parameters(prm);
      deletion.parse_parameters(prm);
      output.parse_parameters(prm);
      checkpoint.parse_parameters(prm);
    }

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
                 const LawSet           &laws,
                 const WalletteSettings &settings,
                 const WallettePlugins  &plugins,
                 RunContext             &context);

        /** The solver lets go of the matrix before it goes. */
        ~Wallette();

        void
        run();

      private:
        /** Mesh, joints, system, specimen, point states, caches. */
        void
        setup(const std::vector<Box> &boxes);
        /** The point states of the laws (8 per cell, 4 per joint face, as
         * the laws declare them). */
        void
        setup_point_states();
        /** Solve @p step from the present state: predictor, Newton, the
         * update of the states after it. */
        StepOutcome
        solve(const Step &step);
        /** The largest change of a damage from the frozen to the updated
         * states, over all ranks (an IMPL-EX correction pass). */
        double
        damage_change() const;
        /** Every point's updated state is kept as the frozen one (the next
         * pass of a correction). */
        void
        freeze();
        /** The converged @p step becomes the old state; the deletions after
         * it (how many cells). */
        unsigned int
        accept(const Step &step, const StepOutcome &outcome);
        /** The converged step into the curve, the postprocessors and the
         * screen; false (and nothing recorded) when its reaction, strain
         * or damages are not finite. */
        bool
        record_step(const Step        &step,
                    const unsigned int its,
                    const unsigned int removed);
        /** Every postprocessor's output of the present state. */
        void
        output();
        CheckpointParts
        checkpoint_parts();
        /** Write a checkpoint with @p status. */
        void
        save(const std::string &status);
        /** Start from zero or from the checkpoint. */
        void
        begin();
        /** Summary entries and the closing line. */
        void
        finish(const std::string &status,
               const std::string &message,
               const double       seconds);

        /** The laws of the cell regions and the joint types. */
        const LawSet                      &laws;
        const WalletteSettings            &settings;
        const WallettePlugins             &plugins;
        Integrator                        &integrator;
        LinearSolver                      &solver;
        RunContext                        &context;
        ConditionalOStream                &pcout;
        parallel::shared::Triangulation<3> triangulation;
        Geometry                           geometry;
        System                             system;
        Joints                             joints;
        Specimen                           specimen;
        /** The states of the laws' points. */
        LawStates                       states;
        std::unique_ptr<Assembler>      assembler;
        std::unique_ptr<Newton>         newton;
        std::unique_ptr<StepController> controller;
        std::vector<std::string>        postprocessor_data;
        std::vector<CurvePoint>         curve;
        RunStatistics                   statistics;
        std::unique_ptr<ModelView>      view;
        /** The solution of the last converged step. */
        System::Vector u_converged;
      };

      Wallette::Wallette(const std::vector<Box> &boxes,
                         const LawSet           &laws,
                         const WalletteSettings &settings,
                         const WallettePlugins  &plugins,
                         RunContext             &context)
        : laws(laws)
        , settings(settings)
        , plugins(plugins)
        , integrator(plugins.integrator)
        , solver(plugins.solver)
        , context(context)
        , pcout(context.pcout)
        , triangulation(context.mpi_communicator,
                        Triangulation<3>::none,
                        false,
                        parallel::shared::Triangulation<3>::partition_metis)
        , system(triangulation, context.mpi_communicator)
      {
        // the threads of the assemblies (0: deal.II's choice at start-up)
        if (settings.assembly.threads > 0)
          MultithreadInfo::set_thread_limit(settings.assembly.threads);
        setup(boxes);
      }

      Wallette::~Wallette()
      {
        solver.clear();
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
        system.setup(joints,
                     geometry,
                     settings.platen,
                     settings.mesh.gauss,
                     plugins.protocol);
        specimen = make_specimen(triangulation,
                                 geometry.n_bricks,
                                 joints,
                                 settings.specimen);
        setup_point_states();
        assembler = std::make_unique<Assembler>(
          AssemblyParts{system, joints, specimen, laws, integrator, states},
          settings.mesh.gauss,
          spacing[0]);
        assembler->make_elastic_caches();
        solver.initialize(system.dof_handler, pcout);
        const double target = plugins.protocol.target_displacement();
        newton              = std::make_unique<Newton>(
          settings.newton,
          1e-6 * laws.brick_law(unit_region).youngs_modulus() *
            geometry.gross_area * std::abs(target) / geometry.height);
        controller =
          std::make_unique<StepController>(plugins.protocol,
                                           settings.steps,
                                           integrator.updates_after_step(),
                                           settings.newton.max_newton,
                                           bound_materials(laws),
                                           pcout);
        view = std::make_unique<ModelView>(ModelView{settings,
                                                     context,
                                                     laws,
                                                     plugins.protocol,
                                                     curve,
                                                     joints,
                                                     geometry,
                                                     system,
                                                     specimen,
                                                     assembler->element(),
                                                     states,
                                                     *controller});
        postprocessor_data.assign(plugins.postprocessors.size(), std::string());
        u_converged = system.u;
      }

      void
      Wallette::setup_point_states()
      {
        check_laws(laws, integrator, settings);
        // each law's points: every cell's (face's) points are in every
        // law's states, and each cell (face) uses and checkpoints those of
        // the law of its region (type)
        std::vector<std::vector<unsigned int>> owned_bricks(laws.n_regions()),
          owned_joints(laws.n_joint_laws());
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const unsigned int   c      = cell->active_cell_index();
              const unsigned int   region = specimen.cell_region[c];
              const BrickMaterial &law    = laws.brick_law(region);
              if (law.is_linear())
                continue;
              BrickPoint point;
              point.characteristic_length = specimen.cell_length[c];
              point.strength_factor       = specimen.cell_factor[c];
              law.check_point(point);
              for (unsigned int q = 0; q < 8; ++q)
                owned_bricks[region].push_back(8 * c + q);
            }
        for (unsigned int t = 0; t < joints.n_faces_of_type.size(); ++t)
          AssertThrow(joints.n_faces_of_type[t] == 0 || laws.has_joint_law(t),
                      ExcMessage(std::string("internal error: ") +
                                 joint_type_name[t] + " faces without a law"));
        for (unsigned int n = 0; n < joints.faces.size(); ++n)
          if (joints.faces[n].owned)
            for (unsigned int q = 0; q < InterfaceElement::n_points; ++q)
              owned_joints[laws.slot_of_type(joints.faces[n].type)].push_back(
                InterfaceElement::n_points * n + q);
        std::vector<double> initial;
        states.bricks.resize(laws.n_regions());
        for (unsigned int r = 0; r < laws.n_regions(); ++r)
          {
            const BrickMaterial &law = laws.brick_law(r);
            initial.assign(
              law.is_linear() ? 0 : n_state_values(law.state_variables()), 0.);
            law.initial_state(initial);
            states.bricks[r].initialize(8 * triangulation.n_active_cells(),
                                        initial,
                                        owned_bricks[r]);
          }
        states.joints.resize(laws.n_joint_laws());
        for (unsigned int slot = 0; slot < laws.n_joint_laws(); ++slot)
          {
            const InterfaceLaw &law = *laws.joint(slot).law;
            initial.assign(n_state_values(law.state_variables()), 0.);
            law.initial_state(initial);
            states.joints[slot].initialize(InterfaceElement::n_points *
                                             joints.faces.size(),
                                           initial,
                                           owned_joints[slot]);
          }
      }

      StepOutcome
      Wallette::solve(const Step &step)
      {
        StepOutcome outcome;
        // the predictor: none in a correction (it starts from its last pass)
        newton->predict(system, step.correction ? 0. : step.ratio);
        outcome.converged = newton->solve_step(system,
                                               *assembler,
                                               solver,
                                               step.to,
                                               step.time_step,
                                               controller->largest_reaction(),
                                               outcome);
        // a converged mechanism is no state of the wallette: a smaller
        // step, or the run stops (solution/deletion.h)
        if (outcome.converged)
          {
            outcome.failure   = mechanism_problem(system, specimen);
            outcome.converged = outcome.failure.empty();
          }
        if (!outcome.converged || !integrator.updates_after_step())
          return outcome;
        outcome.damage_error = assembler->update_states(step.time_step);
        if (!std::isfinite(outcome.damage_error))
          outcome.non_finite = assembler->non_finite();
        else if (step.correction)
          outcome.damage_change = damage_change();
        return outcome;
      }

      double
      Wallette::damage_change() const
      {
        double c = 0;
        for (unsigned int r = 0; r < laws.n_regions(); ++r)
          if (!laws.brick_law(r).is_linear())
            c = std::max(
              c, states.bricks[r].largest_damage_change(laws.brick_law(r)));
        for (unsigned int slot = 0; slot < laws.n_joint_laws(); ++slot)
          c = std::max(c,
                       states.joints[slot].largest_damage_change(
                         *laws.joint(slot).law));
        return Utilities::MPI::max(c, context.mpi_communicator);
      }

      void
      Wallette::freeze()
      {
        for (PointStates &s : states.bricks)
          s.freeze();
        for (PointStates &s : states.joints)
          s.freeze();
      }

      unsigned int
      Wallette::accept(const Step &step, const StepOutcome &outcome)
      {
        const bool older = integrator.keeps_older();
        for (unsigned int n = 0; n < joints.faces.size(); ++n)
          if (joints.faces[n].owned)
            for (unsigned int q = 0; q < InterfaceElement::n_points; ++q)
              states.joints[laws.slot_of_type(joints.faces[n].type)].accept(
                InterfaceElement::n_points * n + q, older);
        if (!laws.bricks_linear())
          for (const auto &cell : triangulation.active_cell_iterators())
            {
              const unsigned int c = cell->active_cell_index();
              if (cell->is_locally_owned() && !specimen.deleted[c])
                for (unsigned int q = 0; q < 8; ++q)
                  states.bricks[specimen.cell_region[c]].accept(8 * c + q,
                                                                older);
            }
        // the deletion and the output evaluate the law with them
        specimen.nonlocal_factors = assembler->nonlocal_factors();
        system.last_increment     = system.u;
        system.last_increment -= u_converged;
        u_converged = system.u;
        controller->accept(step, outcome.reaction);
        unsigned int       faded = 0;
        const DeletionStep after{controller->n_steps(),
                                 step.leg.cycle,
                                 step.leg.unloading};
        const unsigned int removed = delete_cells(settings.deletion,
                                                  joints,
                                                  laws,
                                                  states,
                                                  system,
                                                  specimen,
                                                  after,
                                                  faded);
        // the deleted cells' DOFs are fixed from now on: no extrapolation
        // across the change of the structure
        if (removed > 0)
          system.last_increment = 0;
        if (removed > 0 || faded > 0)
          {
            assembler->invalidate();
            solver.forget();
          }
        return removed;
      }

      bool
      Wallette::record_step(const Step        &step,
                            const unsigned int its,
                            const unsigned int removed)
      {
        CurvePoint p;
        p.displacement = controller->applied();
        p.strain       = p.displacement / geometry.height;
        p.force        = system.reaction();
        p.stress       = p.force / geometry.gross_area;
        p.newton       = its;
        std::tie(p.max_damage, p.brick_damages) = max_damages(*view);
        p.gauge_strain                          = system.gauge_strain();
        p.cycle                                 = step.leg.cycle;
        p.unloading                             = step.leg.unloading;
        p.deleted                               = specimen.n_deleted;
        bool finite = std::isfinite(p.force) && std::isfinite(p.stress) &&
                      std::isfinite(p.max_damage) &&
                      std::isfinite(p.gauge_strain);
        for (const double d : p.brick_damages)
          finite = finite && std::isfinite(d);
        if (!finite)
          return false;
        curve.push_back(p);
        for (auto &pp : plugins.postprocessors)
          pp->step(*view);
        pcout << "Step " << controller->n_steps();
        if (plugins.protocol.is_cyclic())
          pcout << " (cycle " << step.leg.cycle
                << (step.leg.unloading ? ", unloading" : "") << ")";
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

      void
      Wallette::output()
      {
        for (auto &pp : plugins.postprocessors)
          pp->output(*view, controller->n_steps(), curve.back().strain);
      }

      CheckpointParts
      Wallette::checkpoint_parts()
      {
        return {*controller,
                curve,
                statistics,
                specimen,
                states,
                solver,
                system,
                postprocessor_data,
                settings.checkpoint.inputs};
      }

      void
      Wallette::save(const std::string &status)
      {
        // each postprocessor's data behind the name of its class, so that
        // a resumed run with another list is told apart even where the
        // counts agree and the data are empty
        for (unsigned int i = 0; i < plugins.postprocessors.size(); ++i)
          postprocessor_data[i] =
            std::string(typeid(*plugins.postprocessors[i]).name()) + '\n' +
            plugins.postprocessors[i]->save();
        save_checkpoint(checkpoint_parts(), status, context);
      }

      void
      Wallette::begin()
      {
        auto &postprocessors = plugins.postprocessors;
        if (settings.checkpoint.resume)
          {
            auto parts = checkpoint_parts();
            load_checkpoint(parts, context, postprocessors.size());
            u_converged = system.u;
            for (unsigned int i = 0; i < postprocessors.size(); ++i)
              {
                const std::string &data = postprocessor_data[i];
                const std::size_t  end  = data.find('\n');
                AssertThrow(end != std::string::npos &&
                              data.compare(
                                0, end, typeid(*postprocessors[i]).name()) == 0,
                            other_postprocessors(""));
                try
                  {
                    postprocessors[i]->load(data.substr(end + 1));
                  }
                catch (const std::exception &e)
                  {
                    AssertThrow(false, other_postprocessors(e.what()));
                  }
              }
            pcout << "Resumed from the checkpoint at step "
                  << controller->n_steps() << " (platen displacement "
                  << controller->applied() << " m)\n";
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

      void
      Wallette::run()
      {
        const auto  start = Clock::now();
        StopSignals stop_signals;
        describe_model(*view);
        begin();
        if (!plugins.protocol.description().empty())
          pcout << plugins.protocol.description() << "\n";
        Decision   end;
        bool       bad_state = false;
        Step       step;
        const auto interval = settings.output.vtu_interval;
        const auto every    = settings.checkpoint.checkpoint_interval;
        while (end.kind != Decision::Kind::stop &&
               controller->next(curve, step))
          {
            integrator.set_mode(step.correction ?
                                  Integrator::Mode::frozen :
                                  Integrator::Mode::extrapolated);
            integrator.set_ratio(step.ratio);
            const StepOutcome outcome = solve(step);
            statistics.total_newton += outcome.iterations;
            end = controller->solved(step, outcome);
            if (end.kind == Decision::Kind::redo)
              system.u = u_converged;
            if (end.kind == Decision::Kind::correct)
              freeze();
            if (end.kind != Decision::Kind::accept)
              continue;
            const unsigned int removed = accept(step, outcome);
            if (!record_step(step, outcome.iterations, removed))
              {
                bad_state = true;
                end       = Decision::stop(
                  "failed",
                  "the platen reaction, the gauge strain or a damage is not "
                        "finite (nan or inf) after the step to platen displacement " +
                    Utilities::to_string(step.to) + " m; check " +
                    likely_entries("bricks") + " and " +
                    likely_entries("joints") +
                    "; results up to the step before are written");
                break;
              }
            end = controller->check_end(step, curve);
            if (end.kind == Decision::Kind::stop)
              break;
            // the step that ends the last leg (in a cyclic run an unloading
            // one) writes its state whatever the output interval
            if ((interval > 0 && controller->n_steps() % interval == 0) ||
                controller->protocol_done(curve))
              output();
            controller->grow(outcome.iterations);
            if (every > 0 && controller->n_steps() % every == 0)
              {
                save("running");
                // a run resumed from here starts without the factorisation
                // that the next step's chord corrections would use: so
                // does this one, and the two stay the same to round-off
                if (settings.newton.chord_across_steps)
                  solver.drop_factors();
              }
            end = controller->check_interrupted(curve);
            // a batch system's time limit or Ctrl-C: stop here, with the
            // checkpoint written below
            if (end.kind != Decision::Kind::stop)
              if (const int signal = stop_signals.received(system.comm))
                end = Decision::stop(
                  "interrupted",
                  StopSignals::name(signal) + " received: stopped after step " +
                    std::to_string(controller->n_steps()) +
                    "; `set Resume = true' continues from the checkpoint");
          }
        std::string status = "completed", message;
        if (end.kind == Decision::Kind::stop)
          {
            status  = end.status;
            message = end.message;
            pcout << "Stopped: " << message << "\n";
            system.u = u_converged;
            if (!bad_state)
              {
                // the checkpoint first: a resumed run lists the output
                // steps of an uninterrupted one, not this stop's extra
                // state (its files stay, written below)
                if (status != "completed")
                  save(status);
                output();
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
        // the curve's entries first: the result line below and every
        // postprocessor may read them
        write_curve_summary(curve,
                            system.gauge_span,
                            laws.brick_damage_names(),
                            summary);
        for (auto &pp : plugins.postprocessors)
          pp->finish(*view, summary);
        const MPI_Comm comm = context.mpi_communicator;
        summary["status"]   = status;
        if (!message.empty())
          summary["message"] = message;
        const auto &a                        = assembler->statistics;
        const auto &s                        = solver.statistics;
        summary["steps"]                     = controller->n_steps();
        summary["newton_iterations"]         = statistics.total_newton;
        summary["cut_backs"]                 = controller->n_cutbacks();
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
        controller->write_summary(summary);
        // share of the evaluations skipped by the elastic check, over all
        // ranks (work skipped where nothing can change)
        const auto elastic_fraction = [&](const unsigned long elastic,
                                          const unsigned long evaluated) {
          const double e   = Utilities::MPI::sum(double(elastic), comm),
                       all = e + Utilities::MPI::sum(double(evaluated), comm);
          return all > 0 ? e / all : 0.;
        };
        if (!laws.bricks_linear())
          summary["cell_evaluations_elastic_fraction"] =
            elastic_fraction(a.n_elastic_cells, a.n_material_cells);
        if (!laws.joints_linear() || laws.has_joint_law(splitting_type))
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
              << controller->n_steps() << " steps, " << statistics.total_newton
              << " Newton iterations, " << controller->n_cutbacks()
              << " cut-backs";
        if (specimen.n_deleted > 0)
          pcout << ", " << specimen.n_deleted << " cells deleted";
        pcout << "\n";
        for (auto &pp : plugins.postprocessors)
          pp->after_summary(*view, summary);
      }
    } // namespace

    void
    check_laws(const LawSet            &laws,
               const model::Integrator &integrator,
               const WalletteSettings  &settings)
    {
      const double radius = nonlocal_length(laws.brick_law(unit_region));
      AssertThrow(radius == 0 || integrator.updates_after_step(),
                  ExcMessage("Brick material: `Nonlocal length' > 0 needs "
                             "`Damage integration = implex'"));
      AssertThrow(radius == 0 || !settings.steps.implex_floor_correction,
                  ExcMessage("Brick material: `Nonlocal length' > 0 needs "
                             "`IMPL-EX floor correction = accept'"));
      for (unsigned int r = 1; r < laws.n_regions(); ++r)
        AssertThrow(nonlocal_length(laws.brick_law(r)) == 0,
                    ExcMessage("the law of `" + laws.region(r).entry +
                               "': `Nonlocal length' must be 0 (the "
                               "nonlocal average acts on the units only)"));
      if (!integrator.extrapolates_laws())
        return;
      const auto refuse = [](const std::string &entry) {
        return ExcMessage(
          "`Damage integration = implex' needs laws that extrapolate "
          "their internal variables, and the law of `" +
          entry +
          "' does not (its extrapolates() is false: it has no IMPL-EX "
          "evaluate_extrapolated()); set `Damage integration = implicit' "
          "or give the law both");
      };
      const auto check = [&](const auto &entry) {
        AssertThrow(entry.law->is_linear() || entry.law->extrapolates(),
                    refuse(entry.entry));
      };
      for (unsigned int r = 0; r < laws.n_regions(); ++r)
        check(laws.region(r));
      for (unsigned int slot = 0; slot < laws.n_joint_laws(); ++slot)
        check(laws.joint(slot));
    }

    void
    run_wallette(const std::vector<Box> &boxes,
                 const LawSet           &laws,
                 const WalletteSettings &settings,
                 const WallettePlugins  &plugins,
                 RunContext             &context)
    {
      if (!settings.mesh.detailed)
        check_mesh(boxes, settings.mesh);
      AssertThrow(laws.n_regions() == (settings.mesh.detailed ? 2u : 1u),
                  ExcMessage("internal error: the detailed model needs the "
                             "laws of the units and of the mortar, the "
                             "simplified one that of the units"));
      for (unsigned int t = 0; t < splitting_type; ++t)
        AssertThrow(laws.has_joint_law(t),
                    ExcMessage(std::string("internal error: no law of the ") +
                               joint_type_name[t] + " joints"));
      AssertThrow(!settings.mesh.split_units ||
                    laws.has_joint_law(splitting_type),
                  ExcMessage("internal error: split units need the "
                             "splitting interfaces' law"));
      Wallette wallette(boxes, laws, settings, plugins, context);
      wallette.run();
    }
  } // namespace brickwork
} // namespace masonry
