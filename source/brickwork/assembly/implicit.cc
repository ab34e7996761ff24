/**
 * @file
 * The implicit integrator (`Damage integration = implicit').
 */
#include "integrator.h"

namespace masonry
{
  namespace brickwork
  {
    namespace model
    {
      namespace
      {
        /** The law's algorithmic tangent at the trial state; the states
         * of the step are updated in every evaluation. */
        class Implicit : public Integrator
        {
        public:
          static void
          declare_parameters(dealii::ParameterHandler &)
          {}

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

          bool
          updates_after_step() const override
          {
            return false;
          }
        };
      } // namespace
    }   // namespace model
  }     // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_INTEGRATOR(
  masonry::brickwork::model::Implicit,
  "implicit",
  "The brick and joint laws are integrated implicitly (Newton with their "
  "algorithmic tangents).")
