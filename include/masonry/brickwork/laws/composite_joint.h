/**
 * @file
 * The composite interface model of Lourenço & Rots (1997) for the mortar
 * joints of masonry, in three dimensions: a multi-surface plasticity law
 * with a tension cut-off, Coulomb friction and an elliptical compression
 * cap, each with its own softening or hardening. The class is independent
 * of the solver's plugin interface: it maps (jump, old state) to
 * (traction, consistent tangent, new state). SI units throughout: tractions
 * in Pa, jumps in m, stiffnesses in Pa/m, fracture energies in J/m² (N/m).
 *
 * The jump and the traction are given in the joint's local frame:
 * component 0 along the normal (positive opening, positive traction in
 * tension), 1 and 2 the two slips.
 */
#ifndef masonry_brickwork_laws_composite_joint_h
#define masonry_brickwork_laws_composite_joint_h

#include <array>

namespace masonry
{
  namespace brickwork
  {
    namespace laws
    {
      /** Vectors and matrices in the local frame (normal, shear 1, 2). */
      using Vector3 = std::array<double, 3>;
      using Matrix3 = std::array<std::array<double, 3>, 3>;

      /**
       * Irreversible state of one integration point of a composite joint.
       */
      struct CompositeJointState
      {
        /**
         * Plastic jump, m (normal, shear 1, shear 2); the elastic jump is
         * the total jump minus this one.
         */
        Vector3 plastic_jump = {{0, 0, 0}};
        /**
         * Part of the normal plastic jump that is an open tensile crack, m
         * (>= 0): the accumulated tension-mode flow, which closes again
         * without traction (see CompositeJoint::Parameters::crack_closure).
         */
        double crack_opening = 0;
        /**
         * Softening variable of tension and shear, dimensionless:
         * f_t = f_t0 exp(-xi), c = c0 exp(-xi). The equivalent plastic
         * jumps of the paper are kappa_1 = xi G_I / f_t0 and
         * kappa_2 = xi G_II / c0 (coupled isotropic softening).
         */
        double xi = 0;
        /** Equivalent plastic jump of the cap, kappa_3, m. */
        double kappa_cap = 0;

        /** kappa_1 of the paper, m. */
        double
        kappa_tension(const double f_t0, const double G_I) const
        {
          return xi * G_I / f_t0;
        }
        /** kappa_2 of the paper, m. */
        double
        kappa_shear(const double c0, const double G_II) const
        {
          return xi * G_II / c0;
        }
      };

      /** Which yield surfaces the last evaluation returned to. */
      struct CompositeJointActive
      {
        bool tension = false;
        bool shear   = false;
        bool cap     = false;
        /** The crack was closed (partly or fully) without traction. */
        bool crack_closing = false;
        /** Newton iterations of the local return mapping. */
        unsigned int iterations = 0;
        /** 0: one step; n: the fallback integrated the step in n substeps
         * from the unloaded state. */
        unsigned int substeps = 0;
      };

      /**
       * Lourenço & Rots (1997) composite interface model, 3D.
       *
       * Elastic: t = diag(k_n, k_s, k_s) (u - u_p). With sigma the normal
       * traction and tau = |(t_1, t_2)| the magnitude of the shear traction:
       * - tension cut-off f1 = sigma - f_t0 exp(-xi), associated flow;
       * - Coulomb friction f2 = tau + sigma tan(phi) - c0 exp(-xi) with
       *   tan(phi) = tan(phi_0) + (tan(phi_r) - tan(phi_0)) (1 - exp(-xi)),
       *   plastic potential g2 = tau + sigma tan(psi) (dilatancy psi);
       * - coupled softening: d(xi) = sqrt((f_t0 dlambda_1 / G_I)^2 +
       *   (c0 dlambda_2 / G_II)^2), i.e. kappa_1 and kappa_2 of the paper
       *   with the quadratic combination at the corner, so that pure mode
       *   I dissipates G_I and pure mode II at zero normal stress G_II;
       * - cap f3 = C_nn sigma^2 + C_ss tau^2 + C_n sigma - sbar(kappa_3)^2,
       *   associated flow, d(kappa_3) = |d u_p| of the cap flow, and the
       *   paper's hardening/softening law sbar(kappa_3): from sbar_i to the
       *   peak sbar_p at kappa_p along sbar_i + (sbar_p - sbar_i)
       *   sqrt(2 k / k_p - k^2 / k_p^2), a parabola to sbar_m at kappa_m,
       *   then an exponential to the residual sbar_r with continuous slope.
       *
       * The shear part of every surface and potential depends on the shear
       * traction only through its magnitude and the shear stiffness is
       * isotropic, so the return keeps the direction of the trial shear
       * traction: the return mapping is solved in (sigma, tau) and mapped
       * back. Closest-point (backward Euler) return with the active set
       * chosen among {1}, {2}, {3}, {1, 2}, {2, 3} (the first admissible
       * one: positive multipliers, no violated surface), Newton with
       * line search; the tangent is the algorithmic one from the
       * converged local Jacobian (implicit function theorem). With
       * non-associated friction an admissible one-step return need not
       * exist (at the shear-cap corner of a softened cap); then the step
       * is integrated in 2, 4, ... 64 substeps from the unloaded state
       * (CompositeJointActive::substeps) and the tangent is the last
       * substep's.
       */
      class CompositeJoint
      {
      public:
        /** Material parameters, SI units. */
        struct Parameters
        {
          /** Normal penalty stiffness k_n, Pa/m. */
          double normal_stiffness = 2.5e11;
          /** Shear penalty stiffness k_s, Pa/m. */
          double shear_stiffness = 1.0e11;
          /** Tensile (bond) strength f_t0, Pa. */
          double tensile_strength = 0.25e6;
          /** Mode I fracture energy G_I, J/m². */
          double mode_I_energy = 18;
          /** Cohesion c0, Pa. */
          double cohesion = 0.35e6;
          /** Initial friction coefficient tan(phi_0). */
          double friction = 0.75;
          /** Residual friction coefficient tan(phi_r). */
          double residual_friction = 0.75;
          /** Dilatancy coefficient tan(psi) (>= 0). */
          double dilatancy = 0;
          /** Mode II fracture energy G_II, J/m² (at zero normal stress). */
          double mode_II_energy = 125;
          /** Cap peak sbar_p, Pa (C_nn = 1, C_n = 0: the compressive
           * strength of the joint). */
          double cap_strength = 10.5e6;
          /** Cap coefficient C_nn (dimensionless). */
          double cap_Cnn = 1;
          /** Cap coefficient C_ss (dimensionless). */
          double cap_Css = 9;
          /** Cap coefficient C_n, Pa. */
          double cap_Cn = 0;
          /** sbar_i / sbar_p: start of hardening. */
          double cap_initial_ratio = 1. / 3.;
          /** sbar_m / sbar_p: end of the parabolic softening. */
          double cap_middle_ratio = 1. / 2.;
          /** sbar_r / sbar_p: residual. */
          double cap_residual_ratio = 1. / 7.;
          /** Equivalent plastic jump at the peak, kappa_p, m. */
          double cap_peak_jump = 0.09e-3;
          /**
           * Compressive fracture energy G_fc, J/m²: the energy the cap
           * dissipates after its peak above the residual level,
           * G_fc = int_{kappa_p}^inf (sbar - sbar_r) dkappa_3; it fixes
           * kappa_m (see cap_middle_jump()).
           */
          double cap_energy = 5000;
          /**
           * Let an open tensile crack (the accumulated tension flow) close
           * without traction when the joint is pushed back, before contact
           * builds up compression; without it a plastic opening can only be
           * undone by crushing the cap.
           */
          bool crack_closure = true;
        };

        /** Check the parameters; throws std::invalid_argument with a
         * one-line message naming the offending parameter. */
        explicit CompositeJoint(const Parameters &parameters);

        /** The parameters. */
        const Parameters &
        parameters() const
        {
          return p;
        }

        /**
         * Traction @p t (Pa), algorithmic tangent @p tangent = dt/du
         * (Pa/m) and the new state @p updated at the jump @p jump (m) from
         * the converged state @p old. @p active (optional) reports the
         * surfaces of the return.
         */
        void
        evaluate(const Vector3             &jump,
                 const CompositeJointState &old,
                 CompositeJointState       &updated,
                 Vector3                   &t,
                 Matrix3                   &tangent,
                 CompositeJointActive      *active = nullptr) const;

        /**
         * IMPL-EX (Oliver, Huespe & Cante 2008), as the brick law does it:
         * the state extrapolated linearly in pseudo-time from the two last
         * converged states, @p old + @p ratio (@p old - @p older), with the
         * crack opening, xi and kappa_3 kept from decreasing below @p old
         * and the crack opening kept >= 0.
         */
        CompositeJointState
        extrapolate(const CompositeJointState &old,
                    const CompositeJointState &older,
                    const double               ratio) const;

        /**
         * Traction and tangent with the plastic jump of @p frozen held
         * fixed (the IMPL-EX step): t = diag(k_n, k_s, k_s) (u - u_p),
         * tangent diag(k_n, k_s, k_s); an open crack (crack_opening > 0)
         * pushed into compression closes without traction first, as in
         * evaluate(), unless @p closure_gap is false: then the response is
         * linear on both sides of u_p (the IMPL-EX step of a crack that
         * opened in the last step, see CompositeInterface). Nothing is
         * updated.
         */
        void
        evaluate_frozen(const Vector3             &jump,
                        const CompositeJointState &frozen,
                        Vector3                   &t,
                        Matrix3                   &tangent,
                        const bool                 closure_gap = true) const;

        /** Cap yield value sbar(kappa_3), Pa. */
        double
        cap_yield(const double kappa) const;
        /** Its derivative d sbar / d kappa_3, Pa/m (kappa_3 > 0). */
        double
        cap_yield_slope(const double kappa) const;
        /** kappa_m, m, from G_fc and the ratios. */
        double
        cap_middle_jump() const
        {
          return kappa_m;
        }

        /**
         * Penalty stiffnesses of a joint of thickness @p h_m (m) between
         * enlarged units (Lourenço & Rots 1997): k_n = E_b E_m / (h_m (E_b -
         * E_m)), k_s = G_b G_m / (h_m (G_b - G_m)), G = E / (2 (1 + nu));
         * moduli in Pa, result in Pa/m. Throws std::invalid_argument if the
         * unit is not stiffer than the mortar.
         */
        static std::array<double, 2>
        penalties(const double E_b,
                  const double nu_b,
                  const double E_m,
                  const double nu_m,
                  const double h_m);

      private:
        /** One closest-point return; false if no admissible one. */
        bool
        step(const Vector3             &jump,
             const CompositeJointState &old,
             CompositeJointState       &updated,
             Vector3                   &t,
             Matrix3                   &tangent,
             CompositeJointActive      &active) const;

        Parameters p;
        double     kappa_m;
      };
    } // namespace laws
  }   // namespace brickwork
} // namespace masonry

#endif
