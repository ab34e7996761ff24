/**
 * @file
 * The assembler's implicit update of every point after a step (when the
 * integrator asks for it: Integrator::updates_after_step()): the units'
 * factors of the nonlocal average, the new states of the brick and joint
 * points at the solution, and the largest change of a damage against its
 * extrapolation (the elastic caches, the internal forces and the tangent:
 * assembler.cc).
 */
#include <algorithm>
#include <cmath>
#include <limits>

#include "assembler.h"
#include "guarded_work_stream.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      using namespace dealii;

      namespace
      {
        /**
         * The largest change of a damage against its extrapolation (a
         * non-finite one is flagged: std::max would drop a NaN); the points
         * on the threads, the largest change (the same in any order) and
         * the flags gathered item by item (an item: a cell or a face of
         * Assembler::update_states(); the change is dimensionless).
         */
        struct DamageChange
        {
          double       error  = 0;
          unsigned int flags  = 0;
          bool         active = false;
        };

        /** The damages of a point at the updated, old and older states
         * (scratch of damage_change()). */
        struct DamageScratch
        {
          std::vector<double> d, d_old, d_older;
        };

        /** Adds the change of the damages of @p law at point @p p of
         * @p states against their extrapolation (@p integrator) to
         * @p change; a non-finite one sets bit @p flag of its flags. */
        template <class Law>
        void
        damage_change(const Integrator  &integrator,
                      const unsigned int flag,
                      const Law         &law,
                      const PointStates &states,
                      const unsigned int p,
                      DamageScratch     &s,
                      DamageChange      &change)
        {
          const unsigned int n_damages = law.damage_names().size();
          s.d.resize(n_damages);
          s.d_old.resize(n_damages);
          s.d_older.resize(n_damages);
          law.damages(states.updated(p), s.d);
          law.damages(states.old(p), s.d_old);
          law.damages(states.older(p), s.d_older);
          for (unsigned int k = 0; k < n_damages; ++k)
            {
              const double e = std::abs(
                s.d[k] - integrator.extrapolated(s.d_old[k], s.d_older[k]));
              if (!std::isfinite(e))
                change.flags |= 1u << flag;
              else
                change.error = std::max(change.error, e);
            }
        }

        /** A copier of the changes of the items: the largest into
         * @p error, the flags into @p bits. */
        auto
        gather_into(double &error, unsigned int &bits)
        {
          return [&error, &bits](const DamageChange &change) {
            if (!change.active)
              return;
            bits |= change.flags;
            error = std::max(error, change.error);
          };
        }
      } // namespace

      void
      Assembler::update_nonlocal_factors()
      {
        // the units' law (the mortar's is local: LawSet)
        const BrickMaterial    &material = parts.laws.brick_law(unit_region);
        System                 &system   = parts.system;
        const System::Vector   &ghosted  = system.ghosted;
        const NonlocalMeasures *measures = nonlocal_of(material);
        if (measures && measures->nonlocal_length() > 0)
          {
            if (!nonlocal)
              nonlocal = std::make_unique<NonlocalAverage>(
                make_unit_average(system.dof_handler,
                                  parts.specimen,
                                  measures->nonlocal_length()));
            rho = model::nonlocal_factors(*nonlocal,
                                          *measures,
                                          strengths_of(material),
                                          system.dof_handler,
                                          ghosted,
                                          parts.states.bricks[unit_region],
                                          parts.specimen,
                                          system.comm);
          }
      }

      double
      Assembler::update_brick_states(const double time_step)
      {
        const System::Vector &ghosted = parts.system.ghosted;
        double                error   = 0;
        struct BrickScratch : DamageScratch
        {
          std::vector<types::global_dof_index> dofs =
            std::vector<types::global_dof_index>(24);
          Vector<double>                       ue = Vector<double>(24);
          std::array<SymmetricTensor<2, 3>, 8> eps;
        };
        const auto worker = [&](const DoFHandler<3>::active_cell_iterator &cell,
                                BrickScratch                              &s,
                                DamageChange &change) {
          const unsigned int c = cell->active_cell_index();
          change               = DamageChange();
          change.active =
            cell->is_locally_owned() && !parts.specimen.deleted[c];
          if (!change.active)
            return;
          cell->get_dof_indices(s.dofs);
          for (unsigned int i = 0; i < 24; ++i)
            s.ue[i] = ghosted[s.dofs[i]];
          cell_strains(geometries[geometry_of_cell[c]], s.ue, s.eps);
          BrickPoint            point    = brick_point(c, time_step);
          const BrickMaterial  &material = parts.brick_law(c);
          PointStates          &states   = parts.brick_states(c);
          SymmetricTensor<2, 3> stress;
          for (unsigned int q = 0; q < 8; ++q)
            {
              const unsigned int p = 8 * c + q;
              if (!rho[0].empty())
                {
                  point.tensile_factor     = rho[0][p];
                  point.compressive_factor = rho[1][p];
                }
              material.update_state(
                s.eps[q], states.old(p), point, states.updated(p), stress);
              damage_change(
                parts.integrator, 2, material, states, p, s, change);
            }
        };
        run_guarded(parts.system.dof_handler.begin_active(),
                    parts.system.dof_handler.end(),
                    worker,
                    gather_into(error, non_finite_bits),
                    BrickScratch(),
                    DamageChange());
        return error;
      }

      double
      Assembler::update_joint_states(const double time_step)
      {
        const System::Vector           &ghosted = parts.system.ghosted;
        double                          error   = 0;
        const auto                     &faces   = parts.joints.faces;
        const std::vector<unsigned int> items   = active_faces(parts);
        const auto                      worker =
          [&](const std::vector<unsigned int>::const_iterator &it,
              DamageScratch                                   &s,
              DamageChange                                    &change) {
            const unsigned int n       = *it;
            change                     = DamageChange();
            change.active              = true;
            const auto         &face   = faces[n];
            const InterfaceLaw &law    = parts.law_of(n);
            PointStates        &states = parts.states_of(n);
            InterfacePoint      point;
            point.time_step       = time_step;
            point.strength_factor = parts.specimen.face_factor[n];
            Vector<double> ue(24);
            for (unsigned int i = 0; i < 24; ++i)
              ue[i] = ghosted[face.dofs[i]];
            std::array<Local3, 4> jumps;
            interface_element.jumps(face.axis, ue, jumps);
            Local3  t;
            Local33 D;
            for (unsigned int q = 0; q < 4; ++q)
              {
                const unsigned int p = 4 * n + q;
                law.evaluate(
                  jumps[q], states.old(p), point, states.updated(p), t, D);
                damage_change(parts.integrator, 3, law, states, p, s, change);
              }
          };
        run_guarded(items.cbegin(),
                    items.cend(),
                    worker,
                    gather_into(error, non_finite_bits),
                    DamageScratch(),
                    DamageChange());
        return error;
      }

      double
      Assembler::update_states(const double time_step)
      {
        System &system  = parts.system;
        system.ghosted  = system.u;
        non_finite_bits = 0;
        // the units' factors of the nonlocal average (empty: local)
        update_nonlocal_factors();
        double error = 0;
        if (!parts.laws.bricks_linear())
          error = update_brick_states(time_step);
        error = std::max(error, update_joint_states(time_step));
        gather_non_finite();
        if (!non_finite().empty())
          return std::numeric_limits<double>::quiet_NaN();
        return Utilities::MPI::max(error, system.comm);
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
