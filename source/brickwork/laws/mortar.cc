/**
 * @file
 * Brick material `mortar': the law of `damage plasticity' with the
 * defaults of a bed-joint mortar, for the mortar layer of the detailed
 * model.
 */
#include <masonry/brickwork/laws/damage_plasticity.h>

namespace masonry
{
  namespace brickwork
  {

    /**
     * The same law with the defaults of a bed-joint mortar and compressive
     * softening off: the `mortar` plugin for a mortar layer meshed with
     * hexahedra, which under the units is in triaxial compression and must
     * flow at its confined strength f_m + k p instead of softening at f_m.
     */
    class MortarMaterial : public DamagePlasticityBrick
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        declare(prm,
                {"1e9",
                 "0.2",
                 "5e6",
                 "0.01",
                 "0.5e6",
                 "10",
                 "false",
                 "0.5",
                 "mortar"});
      }
    };
  } // namespace brickwork
} // namespace masonry


MASONRY_REGISTER_BRICK_MATERIAL(
  masonry::brickwork::MortarMaterial,
  "mortar",
  "The law of `damage plasticity' for a mortar layer meshed with "
  "hexahedra, with a mortar's defaults (E0 = 1 GPa, nu = 0.2, f_c = f_m = 5 "
  "MPa, eps_c = 0.01, f_t = 0.5 MPa, G_f = 10 J/m^2, isochoric flow "
  "`Plastic Poisson's ratio' = 0.5; assumed typical values, not from a "
  "source) and `Compressive softening' = false: under "
  "the units the layer is in triaxial compression and flows at its "
  "confined strength |sigma_1| = f_m + k p (`Confinement coefficient' k) "
  "without softening.")