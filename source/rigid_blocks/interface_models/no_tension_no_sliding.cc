/**
 * @file
 * The joint model `no tension no sliding' of the rigid blocks.
 */
#include <masonry/rigid_blocks/interface_model.h>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace
    {
      /**
       * Rigid, cohesionless joints that cannot slide: opening only, no
       * dissipation (seed paper eqs. 6–7).
       */
      class NoTensionNoSliding : public InterfaceModel
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &)
        {}

        void
        parse_parameters(dealii::ParameterHandler &) override
        {
          planes = {{dealii::Tensor<1, 3>({1., 0., 0.}), 0.}};
        }

        const std::vector<YieldPlane> &
        yield_planes() const override
        {
          return planes;
        }

        bool
        no_tension_no_sliding() const override
        {
          return true;
        }

      private:
        std::vector<YieldPlane> planes;
      };
    } // namespace
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_INTERFACE_MODEL(
  masonry::rigid_blocks::NoTensionNoSliding,
  "no tension no sliding",
  "Joints without tensile strength that cannot slide (seed paper eqs. "
  "6-7): a joint may open (hinge) at no cost, never interpenetrate or "
  "slide. The limit of `mohr coulomb' with c = f_t = 0 and large tan φ and "
  "f_c.")
