/**
 * @file
 * The law of the splitting interfaces through the middle of the units
 * (`Splitting interfaces = true' in subsection Wallette): the composite
 * joint law with the unit's tensile strength and fracture energy.
 */
#ifndef masonry_brickwork_laws_splitting_h
#define masonry_brickwork_laws_splitting_h

#include <masonry/brickwork/interface_law.h>

#include <memory>
#include <string>

namespace masonry
{
  namespace brickwork
  {
    class BrickMaterial;

    /** The entries of the splitting interfaces; 0: from the brick
     * material (or derived, see make_splitting_law()). */
    struct SplittingSettings
    {
      /** Tensile strength f_t of the unit, Pa. */
      double tensile_strength = 0;
      /** Mode I fracture energy of the unit, J/m^2. */
      double fracture_energy = 0;
      /** Compressive strength f_c of the unit, Pa (for the friction). */
      double compressive_strength = 0;
      /** Normal penalty k_n, Pa/m; 0: 100 E_b / unit length. */
      double stiffness = 0;
    };

    /**
     * The splitting interfaces' law: CompositeJoint with the tension
     * cut-off f_t and G_I = G_f of the unit, Coulomb friction through the
     * unit's uniaxial strengths (c = sqrt(f_c f_t) / 2, tan(phi) = (f_c -
     * f_t) / (2 sqrt(f_c f_t))), G_II = 10 G_f, k_s = k_n / (2 (1 + nu_b)),
     * the cap out of reach (10 f_c). Values not given come from @p brick,
     * whose entries stand in @p brick_section (the full path, e.g. "Brick
     * material/Damage plasticity": an error of a value derived from them
     * names them); @p unit_length (m) scales the default penalty. Every
     * value not given is listed by derived_values().
     */
    std::unique_ptr<InterfaceLaw>
    make_splitting_law(const SplittingSettings &settings,
                       const BrickMaterial     &brick,
                       const std::string       &brick_section,
                       const double             unit_length);
  } // namespace brickwork
} // namespace masonry

#endif
