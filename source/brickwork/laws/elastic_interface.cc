/**
 * @file
 * Interface law `elastic': linear joints.
 */
#include <masonry/brickwork/interface_law.h>

namespace masonry
{
  namespace brickwork
  {
    /** Linear joints: t = diag(k_n, k_s, k_s) [u]. */
    class ElasticInterface : public InterfaceLaw
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &)
      {}

      void
      evaluate(const Local3 &jump,
               ConstStateView,
               const InterfacePoint &,
               StateView,
               Local3  &t,
               Local33 &tangent) const override
      {
        const double k[3] = {normal_stiffness,
                             shear_stiffness,
                             shear_stiffness};
        for (unsigned int i = 0; i < 3; ++i)
          {
            t[i] = k[i] * jump[i];
            for (unsigned int j = 0; j < 3; ++j)
              tangent[i][j] = (i == j ? k[i] : 0);
          }
      }

      bool
      is_linear() const override
      {
        return true;
      }
    };
  } // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_INTERFACE_LAW(masonry::brickwork::ElasticInterface,
                               "elastic",
                               "Linear joints: traction = diag(k_n, k_s, "
                               "k_s) x opening; never damage.")
