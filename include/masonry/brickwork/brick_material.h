/**
 * @file
 * Constitutive laws of the enlarged bricks (`subsection Brick material`,
 * `set Model = ...`): `elastic` and `damage plasticity`.
 */
#ifndef masonry_brickwork_brick_material_h
#define masonry_brickwork_brick_material_h

#include <masonry/core/plugins.h>

#include <deal.II/base/symmetric_tensor.h>

namespace masonry
{
  namespace brickwork
  {
    /**
     * State of a brick integration point: everything a material needs from
     * the last converged step. Materials that have no history leave it at
     * its initial values. Stored per quadrature point with deal.II's
     * CellDataStorage and written to checkpoints by serialize().
     */
    struct BrickState
    {
      /** Plastic strain (dimensionless). */
      dealii::SymmetricTensor<2, 3> plastic_strain;
      /**
       * Damage thresholds in tension and compression, as effective stress
       * (Pa); 0 until the first evaluation sets them to the initial
       * strengths.
       */
      double threshold_t = 0, threshold_c = 0;
      /** Equivalent plastic strains reached on the two envelopes. */
      double kappa_t = 0, kappa_c = 0;
      /**
       * Damage in tension and compression (0 intact to 1), after the
       * viscous regularisation when the material has one.
       */
      double damage_t = 0, damage_c = 0;

      /** Write or read the state (boost serialisation). */
      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &plastic_strain &threshold_t &threshold_c &kappa_t &kappa_c &damage_t
          &damage_c;
      }
    };

    /** What a material needs to know about the point besides its strain. */
    struct BrickPoint
    {
      /**
       * Characteristic length of the element (m): the cube root of its
       * volume; softening is regularised with fracture energy / this.
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
    };

    /** Base class of brick materials. */
    class BrickMaterial
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
      /** Entries shared by all brick materials: none. */
      static void
      declare_common_parameters(dealii::ParameterHandler &prm);

      virtual ~BrickMaterial() = default;

      /** Read the shared entries: none. */
      virtual void
      parse_common_parameters(dealii::ParameterHandler &prm);
      /** Read this material's own subsection: nothing by default. */
      virtual void
      parse_parameters(dealii::ParameterHandler &prm);

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
               const BrickState                    &old,
               const BrickPoint                    &point,
               BrickState                          &updated,
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
                   const BrickState                    &old,
                   const BrickPoint                    &point,
                   BrickState                          &updated,
                   dealii::SymmetricTensor<2, 3>       &stress) const;

      /**
       * IMPL-EX (Oliver, Huespe & Cante 2008): stress and tangent at
       * @p strain with the internal variables extrapolated linearly in
       * pseudo-time from the two last converged states, @p old + @p ratio
       * (@p old - @p older), where @p ratio is the ratio of this step's
       * pseudo-time increment to the last one; nothing is updated. The
       * default evaluates the implicit law from @p old.
       */
      virtual void
      evaluate_extrapolated(const dealii::SymmetricTensor<2, 3> &strain,
                            const BrickState                    &old,
                            const BrickState                    &older,
                            const double                         ratio,
                            const BrickPoint                    &point,
                            dealii::SymmetricTensor<2, 3>       &stress,
                            dealii::SymmetricTensor<4, 3>       &tangent) const;

      /**
       * The stress of evaluate_extrapolated() without the tangent (residual
       * assemblies: line search). The default calls evaluate_extrapolated()
       * and drops the tangent.
       */
      virtual void
      extrapolated_stress(const dealii::SymmetricTensor<2, 3> &strain,
                          const BrickState                    &old,
                          const BrickState                    &older,
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
                 const BrickState                    &old,
                 const BrickPoint                    &point) const;

      /**
       * Check that the material can be used at @p point (for example that
       * the element is small enough for the softening branch regularised
       * with its fracture energy); throws ExcParameter naming the entry to
       * change. Nothing by default.
       */
      virtual void
      check_point(const BrickPoint &point) const;

      /** The initial elastic stiffness C0 (Pa). */
      dealii::SymmetricTensor<4, 3>
      elastic_stiffness() const;
    };
  } // namespace brickwork
} // namespace masonry

/** Register a brick material (one line in its .cc file). */
#define MASONRY_REGISTER_BRICK_MATERIAL(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::brickwork::BrickMaterial,          \
                          classname,                                  \
                          name,                                       \
                          description)

#endif
