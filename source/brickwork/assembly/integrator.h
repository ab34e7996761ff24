/**
 * @file
 * How the laws are integrated in a load step: implicitly (the law's
 * algorithmic tangent at the trial state, states updated in every Newton
 * iteration) or by IMPL-EX (Oliver, Huespe & Cante 2008: internal variables
 * extrapolated from the two last converged states and frozen within the
 * step; the implicit update follows at the converged displacements). A
 * plugin family (`Damage integration', one file per integrator:
 * implicit.cc, implex.cc); the assembler asks the integrator how to
 * evaluate each point.
 */
#ifndef masonry_brickwork_model_integrator_h
#define masonry_brickwork_model_integrator_h

#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>
#include <masonry/core/plugins.h>

#include <string>

#include "point_states.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      /** The integration of brick and joint laws within a step. */
      class Integrator : public plugins::InterfaceBase
      {
      public:
        /** The selection `set Damage integration = ...' stands in
         * `subsection Wallette'. */
        static constexpr const char *registry_section  = "Wallette";
        static constexpr const char *registry_entry    = "Damage integration";
        static constexpr bool        shared_subsection = true;
        /** Default selection: "implicit". */
        static const char *
        default_plugin();
        /** Help text of the selection entry. */
        static std::string
        selection_documentation();


        /** Pseudo-time ratio of this step to the last converged one (0: no
         * extrapolation, for example across a reversal). */
        void
        set_ratio(const double r)
        {
          ratio = r;
        }
        double
        get_ratio() const
        {
          return ratio;
        }

        /**
         * IMPL-EX: how the laws are evaluated in the present step.
         * `extrapolated': the step of IMPL-EX. `frozen': with the states
         * that PointStates::freeze() kept, not extrapolated: the correction
         * of a step at the floor whose damage error is over the tolerance
         * (`IMPL-EX floor correction'), solved again with its own updated
         * states until their update no longer changes them. No effect on
         * the implicit integrator.
         */
        enum class Mode
        {
          extrapolated,
          frozen
        };
        void
        set_mode(const Mode m)
        {
          mode = m;
        }
        Mode
        get_mode() const
        {
          return mode;
        }

        /** Whether brick point @p p responds with the initial elastic
         * stiffness at @p strain. */
        virtual bool
        brick_is_elastic(const BrickMaterial                 &material,
                         const dealii::SymmetricTensor<2, 3> &strain,
                         const PointStates                   &states,
                         const unsigned int                   p,
                         const BrickPoint                    &point) const = 0;

        /** Stress and (if @p tangent) tangent of brick point @p p. */
        virtual void
        brick_response(const BrickMaterial                 &material,
                       const dealii::SymmetricTensor<2, 3> &strain,
                       PointStates                         &states,
                       const unsigned int                   p,
                       const BrickPoint                    &point,
                       dealii::SymmetricTensor<2, 3>       &stress,
                       dealii::SymmetricTensor<4, 3>       *tangent) const = 0;

        /** Whether joint point @p p responds with the elastic tangent. */
        virtual bool
        joint_is_elastic(const InterfaceLaw   &law,
                         const Local3         &jump,
                         const PointStates    &states,
                         const unsigned int    p,
                         const InterfacePoint &point) const = 0;

        /** A joint point found elastic: what its step state becomes. */
        virtual void
        keep_elastic_joint(PointStates &states, const unsigned int p) const = 0;

        /** Traction and tangent of joint point @p p. */
        virtual void
        joint_response(const InterfaceLaw   &law,
                       const Local3         &jump,
                       PointStates          &states,
                       const unsigned int    p,
                       const InterfacePoint &point,
                       Local3               &traction,
                       Local33              &tangent) const = 0;

        /** The state of joint point @p p that the step's tangent was built
         * from (its damages decide whether the tangent is the initial
         * one). */
        virtual ConstStateView
        step_state(const PointStates &states, const unsigned int p) const = 0;

        /** Accepting a step: whether the converged state is also kept as
         * the older one. */
        virtual bool
        keeps_older() const = 0;

        /**
         * Whether the states of a converged step are updated after it at
         * the converged displacements (Assembler::update_states()), whose
         * damage error against extrapolated() then controls the step size;
         * otherwise the step's evaluations updated them and the step size
         * follows the Newton iterations.
         */
        virtual bool
        updates_after_step() const = 0;

        /**
         * Whether the integrator evaluates the laws with their internal
         * variables extrapolated (IMPL-EX): then every nonlinear law must
         * say that it extrapolates (BrickMaterial::extrapolates(),
         * InterfaceLaw::extrapolates()), or the run stops before its first
         * step. False by default.
         */
        virtual bool
        extrapolates_laws() const
        {
          return false;
        }

        /** The damage a point had in the step, from its two last converged
         * values (IMPL-EX extrapolation, within [d_old, 1]). */
        double
        extrapolated(const double d_old, const double d_older) const;

      protected:
        double ratio = 0;
        Mode   mode  = Mode::extrapolated;
      };

    } // namespace model
  }   // namespace brickwork
} // namespace masonry

/** Register an integrator (one line in its .cc file). */
#define MASONRY_REGISTER_INTEGRATOR(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::brickwork::model::Integrator,  \
                          classname,                              \
                          name,                                   \
                          description)

#endif
