/**
 * @file
 * Implicit and IMPL-EX integration.
 */
#include "integrator.h"

#include <algorithm>

#include "assembler.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      double
      Integrator::extrapolated(const double d, const double d_older) const
      {
        return std::clamp(d + ratio * (d - d_older), d, 1.);
      }

      namespace
      {
        /** The law's algorithmic tangent at the trial state; the states
         * of the step are updated in every evaluation. */
        class Implicit : public Integrator
        {
        public:
          bool
          brick_is_elastic(const BrickMaterial                 &material,
                           const dealii::SymmetricTensor<2, 3> &strain,
                           const PointStates                   &states,
                           const unsigned int                   p,
                           const BrickPoint &point) const override
          {
            return material.is_elastic(strain, states.old(p), point);
          }

          void
          brick_response(const BrickMaterial                 &material,
                         const dealii::SymmetricTensor<2, 3> &strain,
                         PointStates                         &states,
                         const unsigned int                   p,
                         const BrickPoint                    &point,
                         dealii::SymmetricTensor<2, 3>       &stress,
                         dealii::SymmetricTensor<4, 3> *tangent) const override
          {
            // a residual assembly (line search) needs no tangent
            if (tangent)
              material.evaluate(strain,
                                states.old(p),
                                point,
                                states.updated(p),
                                stress,
                                *tangent);
            else
              material.update_state(
                strain, states.old(p), point, states.updated(p), stress);
          }

          bool
          joint_is_elastic(const InterfaceLaw   &law,
                           const Local3         &jump,
                           const PointStates    &states,
                           const unsigned int    p,
                           const InterfacePoint &point) const override
          {
            return law.is_elastic(jump, states.old(p), point);
          }

          void
          keep_elastic_joint(PointStates       &states,
                             const unsigned int p) const override
          {
            states.keep(p);
          }

          void
          joint_response(const InterfaceLaw   &law,
                         const Local3         &jump,
                         PointStates          &states,
                         const unsigned int    p,
                         const InterfacePoint &point,
                         Local3               &t,
                         Local33              &D) const override
          {
            law.evaluate(jump, states.old(p), point, states.updated(p), t, D);
          }

          ConstStateView
          step_state(const PointStates &states,
                     const unsigned int p) const override
          {
            return states.updated(p);
          }

          bool
          keeps_older() const override
          {
            return false;
          }

          double
          after_step(Assembler &, const double) const override
          {
            return 0;
          }
        };

        /** IMPL-EX: extrapolated and frozen internal variables within the
         * step, the implicit update after it; the other modes of
         * set_mode(). */
        class Implex : public Integrator
        {
        public:
          bool
          brick_is_elastic(const BrickMaterial                 &material,
                           const dealii::SymmetricTensor<2, 3> &strain,
                           const PointStates                   &states,
                           const unsigned int                   p,
                           const BrickPoint &point) const override
          {
            if (mode == Mode::frozen)
              return material.is_elastic(strain, states.frozen(p), point);
            return material.is_elastic(strain, states.old(p), point) &&
                   material.is_elastic(strain, states.older(p), point);
          }

          void
          brick_response(const BrickMaterial                 &material,
                         const dealii::SymmetricTensor<2, 3> &strain,
                         PointStates                         &states,
                         const unsigned int                   p,
                         const BrickPoint                    &point,
                         dealii::SymmetricTensor<2, 3>       &stress,
                         dealii::SymmetricTensor<4, 3> *tangent) const override
          {
            // frozen: the kept state, not extrapolated
            const bool     f     = mode == Mode::frozen;
            ConstStateView a     = f ? states.frozen(p) : states.old(p);
            ConstStateView b     = f ? states.frozen(p) : states.older(p);
            const double   ratio = f ? 0. : this->ratio;
            if (tangent)
              material.evaluate_extrapolated(
                strain, a, b, ratio, point, stress, *tangent);
            else
              material.extrapolated_stress(strain, a, b, ratio, point, stress);
          }

          bool
          joint_is_elastic(const InterfaceLaw   &law,
                           const Local3         &jump,
                           const PointStates    &states,
                           const unsigned int    p,
                           const InterfacePoint &point) const override
          {
            if (mode == Mode::frozen)
              return law.is_elastic(jump, states.frozen(p), point);
            return law.is_elastic(jump, states.old(p), point) &&
                   law.is_elastic(jump, states.older(p), point);
          }

          void
          keep_elastic_joint(PointStates &, const unsigned int) const override
          {}

          void
          joint_response(const InterfaceLaw   &law,
                         const Local3         &jump,
                         PointStates          &states,
                         const unsigned int    p,
                         const InterfacePoint &point,
                         Local3               &t,
                         Local33              &D) const override
          {
            if (mode == Mode::frozen)
              law.evaluate_extrapolated(
                jump, states.frozen(p), states.frozen(p), 0., point, t, D);
            else
              law.evaluate_extrapolated(
                jump, states.old(p), states.older(p), ratio, point, t, D);
          }

          ConstStateView
          step_state(const PointStates &states,
                     const unsigned int p) const override
          {
            return mode == Mode::frozen ? states.frozen(p) : states.old(p);
          }

          bool
          keeps_older() const override
          {
            return true;
          }

          double
          after_step(Assembler   &assembler,
                     const double time_step) const override
          {
            // (frozen: the error against the extrapolation means nothing;
            // the caller compares the update with the frozen states)
            return assembler.update_states(*this, time_step);
          }
        };
      } // namespace

      std::unique_ptr<Integrator>
      create_integrator(const IntegratorSettings &settings)
      {
        if (settings.implex)
          return std::make_unique<Implex>();
        return std::make_unique<Implicit>();
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
