/**
 * @file
 * Brick material `elastic': isotropic linear elasticity.
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/core/parameters.h>

namespace masonry
{
  namespace brickwork
  {
    /** Isotropic linear elasticity. */
    class ElasticBrick : public BrickMaterial
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        declare_ranged_entry(prm,
                             "Young's modulus",
                             "10e9",
                             {0, 1e15, "Pa"},
                             "Young's modulus of the bricks, Pa (> 0).");
        prm.declare_entry("Poisson's ratio",
                          "0.15",
                          dealii::Patterns::Double(-1, 0.5),
                          "Poisson's ratio of the bricks (dimensionless, "
                          "-1 < nu < 0.5).");
      }

      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        E  = prm.get_double("Young's modulus");
        nu = prm.get_double("Poisson's ratio");
        AssertThrow(E > 0, ExcParameter("Young's modulus", "must be positive"));
        AssertThrow(nu > -1 && nu < 0.5,
                    ExcParameter("Poisson's ratio",
                                 "must lie strictly between -1 and 0.5"));
      }

      bool
      is_linear() const override
      {
        return true;
      }

      double
      youngs_modulus() const override
      {
        return E;
      }

      double
      poissons_ratio() const override
      {
        return nu;
      }

    private:
      double E = 10e9, nu = 0.15;
    };
  } // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_BRICK_MATERIAL(masonry::brickwork::ElasticBrick,
                                "elastic",
                                "Isotropic linear elastic bricks: each cell "
                                "matrix is computed once and reused.")
