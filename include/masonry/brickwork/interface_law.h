/**
 * @file
 * Traction–separation laws of the zero-thickness joints between enlarged
 * bricks (`subsection Interface law`, `set Law = ...`).
 */
#ifndef masonry_brickwork_interface_law_h
#define masonry_brickwork_interface_law_h

#include <masonry/brickwork/state.h>
#include <masonry/core/plugins.h>

#include <array>

namespace masonry
{
  namespace brickwork
  {
    /** What a law needs to know about the point besides its opening. */
    struct InterfacePoint
    {
      /**
       * Factor on the strengths of this joint (dimensionless, 1: the
       * nominal strengths): the random scatter of a specimen.
       */
      double strength_factor = 1;
      /**
       * Increment of (pseudo) time of the step, s, for the viscous
       * regularisation; 0: no viscosity in this evaluation.
       */
      double time_step = 0;
    };

    /** Vectors and matrices in the local frame (normal, shear 1, shear 2). */
    using Local3  = std::array<double, 3>;
    using Local33 = std::array<std::array<double, 3>, 3>;

    /**
     * Penalty stiffness of a joint of thickness @p h_m (m) whose mortar and
     * unit moduli (Pa) are @p E_m and @p E_u when the bricks are enlarged
     * (Lourenço & Rots 1997): k = E_u E_m / (h_m (E_u − E_m)), Pa/m. The same
     * formula gives the shear stiffness from the shear moduli.
     */
    double
    lourenco_rots_stiffness(const double E_u,
                            const double E_m,
                            const double h_m);

    /**
     * Base class of interface laws. The opening (jump of the displacement
     * from the lower-coordinate brick to the other) is given in the local
     * frame: component 0 along the normal (positive opening), 1 and 2 the
     * slips. Like a brick material, a law declares its own state
     * variables, elastic tangent and reported quantities.
     */
    class InterfaceLaw : public PointLaw, public plugins::InterfaceBase
    {
    public:
      /** Parameters live in `subsection Interface law`. */
      static constexpr const char *registry_section = "Interface law";
      /** The selection entry: `set Law = ...`. */
      static constexpr const char *registry_entry = "Law";
      /** Default selection: "bilinear". */
      static const char *
      default_plugin();
      /** Help text of the selection entry. */
      static std::string
      selection_documentation();
      /** Entries shared by all laws: the penalty stiffnesses. */
      static void
      declare_common_parameters(dealii::ParameterHandler &prm);

      /** Read the penalty stiffnesses. */
      void
      parse_common_parameters(dealii::ParameterHandler &prm) override;

      /**
       * Traction @p t (Pa) and consistent tangent @p tangent (Pa/m) for the
       * opening @p jump (m), starting from the converged @p old state at
       * @p point; @p updated receives the new state (accepted by the
       * caller only when the load step converges).
       */
      virtual void
      evaluate(const Local3         &jump,
               ConstStateView        old,
               const InterfacePoint &point,
               StateView             updated,
               Local3               &t,
               Local33              &tangent) const = 0;

      /**
       * IMPL-EX: traction and tangent at @p jump with the damage
       * extrapolated from the two last converged states, @p old + @p ratio
       * (@p old - @p older), not updated. The default evaluates the
       * implicit law from @p old, which is no extrapolation: a law that
       * overrides this function says so with extrapolates(), and
       * `Damage integration = implex' refuses a nonlinear law that does
       * not.
       */
      virtual void
      evaluate_extrapolated(const Local3         &jump,
                            ConstStateView        old,
                            ConstStateView        older,
                            const double          ratio,
                            const InterfacePoint &point,
                            Local3               &t,
                            Local33              &tangent) const;

      /**
       * Whether evaluate() at @p jump from @p old would give exactly the
       * initial elastic response (traction = diag(k_n, k_s, k_s) jump, that
       * tangent, state unchanged), and evaluate_extrapolated() from @p old
       * and an equally intact older state too. The assembly then uses the
       * interface's cached elastic matrix. The default: is_linear().
       */
      virtual bool
      is_elastic(const Local3         &jump,
                 ConstStateView        old,
                 const InterfacePoint &point) const;

      /**
       * The initial (elastic) tangent in the local frame, Pa/m: used for
       * the cached elastic matrices of intact joints. The default:
       * diag(k_n, k_s, k_s).
       */
      virtual Local33
      elastic_tangent() const;

      /** Whether the law is linear (tangent independent of the state). */
      virtual bool
      is_linear() const
      {
        return false;
      }

      /**
       * Whether the law extrapolates its damage in evaluate_extrapolated()
       * (IMPL-EX). `Damage integration = implex' stops before the first
       * step with a one-line error naming the law's selection entry when a
       * nonlinear law does not (see BrickMaterial::extrapolates()). False
       * by default; a linear law needs none.
       */
      virtual bool
      extrapolates() const
      {
        return false;
      }

      /** Normal penalty stiffness, Pa/m. */
      double normal_stiffness = 0;
      /** Shear penalty stiffness, Pa/m. */
      double shear_stiffness = 0;
      /** Viscosity of the damage regularisation, s (0: none). */
      double viscosity = 0;
    };
  } // namespace brickwork
} // namespace masonry

/** Register an interface law (one line in its .cc file). */
#define MASONRY_REGISTER_INTERFACE_LAW(classname, name, description) \
  MASONRY_REGISTER_PLUGIN(masonry::brickwork::InterfaceLaw,          \
                          classname,                                 \
                          name,                                      \
                          description)

#endif
