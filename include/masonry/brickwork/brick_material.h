/**
 * @file
 * Constitutive laws of the enlarged bricks (`subsection Brick material`,
 * `set Model = ...`): `elastic`, `damage plasticity` and `mortar` (the
 * same law with a mortar's defaults, for a meshed mortar layer).
 */
#ifndef masonry_brickwork_brick_material_h
#define masonry_brickwork_brick_material_h

#include <masonry/brickwork/state.h>
#include <masonry/core/plugins.h>

#include <deal.II/base/symmetric_tensor.h>

#include <array>

namespace masonry
{
  namespace brickwork
  {
    /** What a material needs to know about the point besides its strain. */
    struct BrickPoint
    {
      /**
       * Characteristic length of the element (m), its crack band: the
       * cube root of its volume; for a mortar cell of the detailed model
       * its size across the layer (doc/brickwork.md, `Crack band');
       * softening is regularised with fracture energy / this.
       */
      double characteristic_length = 1;
      /**
       * Increment of (pseudo) time of the step, s, for the viscous
       * regularisation; 0: no viscosity in this evaluation.
       */
      double time_step = 0;
      /**
       * Factor on the strengths of this brick (dimensionless, 1: the
       * nominal strengths): the random scatter of a specimen.
       */
      double strength_factor = 1;
      /**
       * Factors on the law's tensile and compressive measures
       * (dimensionless, 1: local): for a law with NonlocalMeasures and a
       * nonlocal length > 0 the model sets them, in the implicit update after
       * an IMPL-EX step, to the ratios of the nonlocal averages of
       * nonlocal_measures() around the point to their local values, so that the
       * law sees the averaged measures.
       */
      double tensile_factor = 1, compressive_factor = 1;
    };

    /**
     * Base class of brick materials. A material declares its own state
     * (state_variables(): names and sizes, stored by the model per
     * integration point as flat arrays and handed to the material as
     * views), its elastic stiffness (elastic_stiffness(), anisotropic
     * allowed: the model's elastic cell matrices use it) and what it reports
     * (reported_quantities(): cell averages in the VTU output;
     * damage_names(): largest values in curve.csv and summary.json, the
     * IMPL-EX damage error).
     */
    class BrickMaterial : public PointLaw, public plugins::InterfaceBase
    {
    public:
      /** Parameters live in `subsection Brick material`. */
      static constexpr const char *registry_section = "Brick material";
      /** The selection entry: `set Model = ...`. */
      static constexpr const char *registry_entry = "Model";
      /** Default selection: "elastic". */
      static const char *
      default_plugin();
      /** Help text of the selection entry. */
      static std::string
      selection_documentation();


      /**
       * Whether stress is a fixed linear function of strain: then the
       * assembly computes each cell matrix once and reuses it, and no
       * state is stored.
       */
      virtual bool
      is_linear() const = 0;

      /**
       * The initial (elastic) stiffness as Young's modulus (Pa) and
       * Poisson's ratio: the stiffness of a linear material.
       */
      virtual double
      youngs_modulus() const = 0;
      /** Poisson's ratio of the initial stiffness. */
      virtual double
      poissons_ratio() const = 0;

      /**
       * Stress (Pa) and algorithmic tangent d stress / d strain (Pa) at the
       * total @p strain, starting from the converged state @p old; the new
       * state goes to @p updated (kept by the caller only when the step
       * converges). The default is linear elasticity with the initial
       * stiffness.
       */
      virtual void
      evaluate(const dealii::SymmetricTensor<2, 3> &strain,
               ConstStateView                       old,
               const BrickPoint                    &point,
               StateView                            updated,
               dealii::SymmetricTensor<2, 3>       &stress,
               dealii::SymmetricTensor<4, 3>       &tangent) const;

      /**
       * Stress (Pa) and new state as evaluate(), without the tangent: the
       * IMPL-EX implicit update at the end of a step needs no tangent. The
       * default calls evaluate() and drops the tangent; a law whose tangent
       * is costly (numerical differentiation) overrides it.
       */
      virtual void
      update_state(const dealii::SymmetricTensor<2, 3> &strain,
                   ConstStateView                       old,
                   const BrickPoint                    &point,
                   StateView                            updated,
                   dealii::SymmetricTensor<2, 3>       &stress) const;

      /**
       * IMPL-EX (Oliver, Huespe & Cante 2008): stress and tangent at
       * @p strain with the internal variables extrapolated linearly in
       * pseudo-time from the two last converged states, @p old + @p ratio
       * (@p old - @p older), where @p ratio is the ratio of this step's
       * pseudo-time increment to the last one; nothing is updated. The
       * default evaluates the implicit law from @p old, which is no
       * extrapolation: a law that overrides this function says so with
       * extrapolates(), and `Damage integration = implex' refuses a
       * nonlinear law that does not.
       */
      virtual void
      evaluate_extrapolated(const dealii::SymmetricTensor<2, 3> &strain,
                            ConstStateView                       old,
                            ConstStateView                       older,
                            const double                         ratio,
                            const BrickPoint                    &point,
                            dealii::SymmetricTensor<2, 3>       &stress,
                            dealii::SymmetricTensor<4, 3>       &tangent) const;

      /**
       * Whether the law extrapolates its internal variables in
       * evaluate_extrapolated() (IMPL-EX). `Damage integration = implex'
       * stops before the first step with a one-line error naming `Brick
       * material/Model' (or `Mortar material/Model') when a nonlinear law
       * does not: the default evaluate_extrapolated() would run the
       * implicit law without its tangent's extrapolation and without the
       * damage error that controls IMPL-EX's step size. False by default;
       * a linear law needs none.
       */
      virtual bool
      extrapolates() const;

      /**
       * The stress of evaluate_extrapolated() without the tangent (residual
       * assemblies: line search). The default calls evaluate_extrapolated()
       * and drops the tangent.
       */
      virtual void
      extrapolated_stress(const dealii::SymmetricTensor<2, 3> &strain,
                          ConstStateView                       old,
                          ConstStateView                       older,
                          const double                         ratio,
                          const BrickPoint                    &point,
                          dealii::SymmetricTensor<2, 3>       &stress) const;

      /**
       * Whether evaluate() at @p strain from @p old would give exactly the
       * initial elastic response (stress = C0 : strain, tangent C0, state
       * unchanged): intact, no plastic strain, inside the initial elastic
       * domain. The assembly then uses the cell's cached elastic matrix.
       * The default: is_linear().
       */
      virtual bool
      is_elastic(const dealii::SymmetricTensor<2, 3> &strain,
                 ConstStateView                       old,
                 const BrickPoint                    &point) const;

      /**
       * Check that the material can be used at @p point (for example that
       * the element is small enough for the softening branch regularised
       * with its fracture energy); throws ExcParameter naming the entry to
       * change. Nothing by default.
       */
      virtual void
      check_point(const BrickPoint &point) const;

      /**
       * The initial elastic stiffness C0 (Pa): the tangent of an intact
       * point inside the initial elastic domain, used for the cached
       * elastic cell matrices. The default is isotropic with
       * youngs_modulus() and poissons_ratio(); an anisotropic material
       * overrides it.
       */
      virtual dealii::SymmetricTensor<4, 3>
      elastic_stiffness() const;
    };

    /**
     * @name Optional capabilities of a brick material. A law that has one
     * derives from its class as well as from BrickMaterial, and the model
     * asks for it (strengths_of(), nonlocal_of()); a law without it
     * declares nothing.
     */
    /** @{ */
    /**
     * Uniaxial strengths and a tensile fracture energy: the splitting
     * interfaces' law derives its defaults from the units' (their entries
     * then need no value), and the step control's runaway guard reads the
     * largest compressive strength of the regions' laws.
     */
    class MaterialStrengths
    {
    public:
      virtual ~MaterialStrengths() = default;
      /** Uniaxial compressive strength f_c, Pa (> 0). */
      virtual double
      compressive_strength() const = 0;
      /** Uniaxial tensile strength f_t, Pa (> 0). */
      virtual double
      tensile_strength() const = 0;
      /** Mode I fracture energy G_f, J/m^2 (> 0). */
      virtual double
      tensile_fracture_energy() const = 0;
    };

    /**
     * Measures that a nonlocal average acts on (`Nonlocal length' of the
     * units' law): after an IMPL-EX step the model averages them over the
     * units within the radius and hands the ratios of the averages to the
     * local values to the law (BrickPoint::tensile_factor,
     * compressive_factor).
     */
    class NonlocalMeasures
    {
    public:
      virtual ~NonlocalMeasures() = default;
      /** Radius R (m) of the average; 0: local. */
      virtual double
      nonlocal_length() const = 0;
      /**
       * The tensile and compressive measures (Pa, >= 0) at the trial state
       * of @p strain from @p old_state.
       */
      virtual std::array<double, 2>
      nonlocal_measures(const dealii::SymmetricTensor<2, 3> &strain,
                        ConstStateView                       old_state,
                        const BrickPoint                    &point) const = 0;
    };

    /** The strengths of @p law; nullptr: it has none. */
    const MaterialStrengths *
    strengths_of(const BrickMaterial &law);
    /** The nonlocal measures of @p law; nullptr: it has none. */
    const NonlocalMeasures *
    nonlocal_of(const BrickMaterial &law);
    /** The radius of @p law's nonlocal average, m (0: local, also for a law
     * without nonlocal measures). */
    double
    nonlocal_length(const BrickMaterial &law);
    /** @} */
  } // namespace brickwork
} // namespace masonry

/** Register a brick material (one line in its .cc file). */
#define MASONRY_REGISTER_BRICK_MATERIAL(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::brickwork::BrickMaterial,          \
                          classname,                                  \
                          name,                                       \
                          description)

#endif
