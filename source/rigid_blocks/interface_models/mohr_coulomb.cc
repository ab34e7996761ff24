/**
 * @file
 * The joint model `mohr coulomb' of the rigid blocks.
 */
#include <masonry/core/parameters.h>
#include <masonry/rigid_blocks/interface_model.h>

#include <cmath>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace
    {
      /**
       * Mohr–Coulomb with tension cut-off and linear compression cap,
       * associative.
       */
      class MohrCoulomb : public InterfaceModel
      {
      public:
        static void
        declare_parameters(dealii::ParameterHandler &prm)
        {
          declare_ranged_entry(prm,
                               "Cohesion",
                               "0",
                               {0, 1e9, "Pa"},
                               "Cohesion c of the joints, Pa: the shear "
                               "strength at zero normal stress.");
          declare_ranged_entry(prm,
                               "Friction coefficient",
                               "0.5",
                               {0, 10, "(dimensionless)"},
                               "tan φ of the joints, dimensionless. The flow "
                               "rule is associative: sliding comes with an "
                               "opening of tan φ per unit slip (dilatancy), so "
                               "sliding collapse loads are upper bounds of "
                               "those with non-associative friction.");
          declare_ranged_entry(prm,
                               "Tensile strength",
                               "0",
                               {0, 1e9, "Pa"},
                               "Tension cut-off f_t, Pa: the largest normal "
                               "tensile stress. The joint opens at no more "
                               "than min(f_t, c / tan φ) per unit area.");
          declare_ranged_entry(prm,
                               "Compressive strength",
                               "0",
                               {0, 1e9, "Pa"},
                               "Compression cap f_c, Pa: the largest normal "
                               "compressive stress (a plane σ_n ≥ −f_c). 0 "
                               "means no cap (infinitely strong in "
                               "compression).");
          prm.declare_entry("Shear directions",
                            "8",
                            dealii::Patterns::Integer(4, 360),
                            "Number m of planes that linearise the Coulomb "
                            "cone |τ| ≤ c − σ_n tan φ, at shear directions "
                            "2πk/m in the interface plane (a polygon that "
                            "circumscribes the cone, so shear strength is "
                            "overestimated by at most 1/cos(π/m) − 1 "
                            "between the directions). A multiple of 4 "
                            "includes the directions across the thickness "
                            "and along the edge exactly. Dimensionless.");
        }

        void
        parse_parameters(dealii::ParameterHandler &prm) override
        {
          const double       c       = prm.get_double("Cohesion");
          const double       tan_phi = prm.get_double("Friction coefficient");
          const double       f_t     = prm.get_double("Tensile strength");
          const double       f_c     = prm.get_double("Compressive strength");
          const unsigned int m       = prm.get_integer("Shear directions");
          for (const double v : {c, tan_phi, f_t, f_c})
            AssertThrow(std::isfinite(v),
                        ExcParameter("Cohesion",
                                     "the strengths must be finite"));
          planes.clear();
          planes.push_back({dealii::Tensor<1, 3>({1., 0., 0.}), f_t});
          for (unsigned int k = 0; k < m; ++k)
            {
              const double theta = 2 * M_PI * k / m;
              // exact zeros on the axes keep the LP free of round-off
              double ca = std::cos(theta), sa = std::sin(theta);
              if (std::abs(ca) < 1e-14)
                ca = 0;
              if (std::abs(sa) < 1e-14)
                sa = 0;
              planes.push_back({dealii::Tensor<1, 3>({tan_phi, ca, sa}), c});
            }
          if (f_c > 0)
            planes.push_back({dealii::Tensor<1, 3>({-1., 0., 0.}), f_c});
        }

        const std::vector<YieldPlane> &
        yield_planes() const override
        {
          return planes;
        }

      private:
        std::vector<YieldPlane> planes;
      };
    } // namespace
  }   // namespace rigid_blocks
} // namespace masonry

MASONRY_REGISTER_INTERFACE_MODEL(
  masonry::rigid_blocks::MohrCoulomb,
  "mohr coulomb",
  "Mohr-Coulomb joints with a tension cut-off and a linear compression "
  "cap, associative flow rule (the seed paper's Bothwell example): planes "
  "σ_n ≤ f_t, τ·e_k + σ_n tan φ ≤ c (m shear directions e_k) and "
  "−σ_n ≤ f_c; dissipation linear in the plastic multipliers.")
