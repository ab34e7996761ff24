/**
 * @file
 * The IMPL-EX integrator (`Damage integration = implex').
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
        /** IMPL-EX: extrapolated and frozen internal variables within the
         * step, the implicit update after it; the other modes of
         * set_mode(). */
        class Implex : public Integrator
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

          bool
          updates_after_step() const override
          {
            return true;
          }

          bool
          extrapolates_laws() const override
          {
            return true;
          }
        };
      } // namespace
    }   // namespace model
  }     // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_INTEGRATOR(
  masonry::brickwork::model::Implex,
  "implex",
  "IMPL-EX (Oliver, Huespe & Cante 2008): within a step the damages and "
  "plastic strains are extrapolated linearly in pseudo-time from the two "
  "last converged steps and frozen, so the step is (nearly) linear, with a "
  "positive tangent; after the step the laws are updated implicitly at the "
  "converged displacements. The step size follows `IMPL-EX damage "
  "tolerance' (never larger than the nominal step).")
