/**
 * @file
 * Brick material `damage plasticity`: effective-stress plasticity with
 * separate tension and compression damage for bricks under cyclic
 * compression.
 *
 * The formulation (documented for users in the registration text in
 * source/brickwork/laws/damage_plasticity.cc and
 * in doc/brickwork.md):
 * - effective stress s = C0 : (e - e_p), split spectrally into s+ (positive
 *   principal stresses) and s- = s - s+;
 * - equivalent effective stresses, positively homogeneous of degree one:
 *   tau_c = (sqrt(3 J2(s-)) + alpha I1(s-)) / (1 - alpha) (Lubliner et al.
 *   1989, compressive part; |s| in uniaxial compression) and tau_t = the
 *   largest principal effective stress (Rankine);
 * - uniaxial envelopes sigma(e) of the total strain e, decomposed as
 *   sigma = (1 - d) E0 (e - e_p(e)) with e_p = b (e - sigma / E0) (Birtel &
 *   Mark 2006), the damage capped at d_max and the rest taken by e_p;
 * - the explicit update of Faria, Oliver & Cervera (1998) / Petracca et al.
 *   (2022, ASDConcrete3D) in a form exact in uniaxial stress: the envelope
 *   strain reached is e = e_p(kappa_old) + tau / E0, and on loading the
 *   plastic strain grows along C0^-1 : s-+ so that the new s-+ is the trial
 *   one scaled to the envelope's effective stress; no local iterations;
 * - sigma = (1 - d_t) s+ + (1 - d_c) s-: tension damage does not act on
 *   closed cracks (stiffness recovery), unloading goes with (1 - d) E0
 *   towards the plastic strain;
 * - softening regularised with the fracture energies and the element's
 *   characteristic length (crack band);
 * - optional viscous regularisation of both damages.
 * The tangent is the central-difference derivative of this stress update
 * (consistent with it to O(h^2)); cells that stay elastic use C0.
 *
 * Options (off by default, so the law above is unchanged):
 * - `Tension-compression interaction': the nominal utilisations u_c =
 *   (1 - d_c) tau_c / f_c, u_t = (1 - d_t) tau_t / f_t and m = min(u_c,
 *   u_t, 1/2); both measures are divided by 1 - m. Where compression
 *   dominates (u_c >= u_t) the compressive criterion is tau_c / T_c + u_t
 *   <= 1, Lee & Fenves' beta <s_max> term with beta = T_c / f_t, and the
 *   tensile one u_t <= 1/2 is not reached first; where tension dominates,
 *   symmetrically. A unit fails on t / f_t + s / f_c = 1 in the mode that
 *   dominates, pure tension never touches the compressive state and pure
 *   compression never the tensile one. The return scales s- (or s+) by the
 *   k that brings the non-homogeneous measure k tau / (1 - min(k a, M))
 *   onto the envelope's threshold (scale_onto());
 * - `Confinement coefficient' k: Lubliner's gamma <-s_max> term, gamma =
 *   k (1 - alpha) - (1 + 2 alpha), when all principal stresses are
 *   compressive, so that |sigma_1| = f_c + k p under (-sigma_1, -p, -p);
 * - `Compressive softening' = false: the envelope stays at f_c after its
 *   peak (plugin `mortar', which only changes the defaults);
 * - `Cracked compression softening' c: the compressive measure is also
 *   divided by beta = min(1, 1 / (0.8 + c kappa_t)), kappa_t the tensile
 *   envelope strain at the start of the step (Vecchio & Collins 1986,
 *   c = 170: a cracked point peaks at beta f_c in compression), bounded
 *   below by `Cracked compression residual ratio' beta_r;
 * - `Tensile plastic flow' = crack: the tensile plastic (crack) strain grows
 *   along n1 n1 (one crack normal to the largest principal effective
 *   stress; s+ / tau_t under multiaxial tension) instead of C0^-1 : s+,
 *   with the envelope strain from a scalar root search (crack_return()),
 *   so that an opening crack no longer carries the Poisson contraction
 *   -nu eps_1 into the directions parallel to it. That flow also lowers
 *   the other principal effective stresses (by lambda per unit crack
 *   strain), which can push s- outside the compressive envelope just
 *   returned to; the compressive and tensile returns are then repeated,
 *   from the envelope strains reached, until neither acts (at most 20
 *   passes), so that the returned state is inside both envelopes. The
 *   crack return's measure is the signed largest principal value, so that
 *   a crack whose envelope has softened to T ~ 0 opens only until s1 = T;
 * - `Plastic Poisson's ratio' nu_p: the compressive plastic strain grows
 *   along C_p^-1 : s- (compliance with E0, nu_p) instead of C0^-1 : s-,
 *   with the multiplier from a scalar root search (flow()); a confined
 *   mortar keeps expanding laterally only with nu_p > p / (|sigma_1| + p);
 * - `Nonlocal length' R: the measures tau_t and tau_c, wherever they enter
 *   (the returns, the interaction's utilisations), are multiplied by
 *   BrickPoint::tensile_factor and compressive_factor, which the model sets
 *   to the ratios of the nonlocal averages of the trial measures over a
 *   sphere of radius R within the unit to their local values
 *   (model/nonlocal.h); at the trial state the law sees the averaged
 *   measures, during the return they scale with the local ones.
 */
#ifndef masonry_brickwork_laws_damage_plasticity_h
#define masonry_brickwork_laws_damage_plasticity_h

#include <masonry/brickwork/brick_material.h>

#include <string>

namespace masonry
{
  namespace brickwork
  {
    using dealii::SymmetricTensor;

    /**
     * Defaults of the entries that differ between the two plugins of this
     * file (`damage plasticity` for units, `mortar` for a meshed mortar
     * layer).
     */
    struct DamagePlasticityDefaults
    {
      const char *E, *nu, *f_c, *eps_c, *f_t, *G_f, *softening, *nu_p, *what;
      /** `Cracked compression softening'. */
      const char *cracked = "0";
    };


    /** See the file documentation. */
    class DamagePlasticityBrick : public BrickMaterial,
                                  public MaterialStrengths,
                                  public NonlocalMeasures
    {
    public:
      /** A point of a uniaxial envelope. */
      struct EnvelopePoint
      {
        /** Stress (Pa, positive), plastic strain, damage. */
        double stress = 0, plastic = 0, damage = 0;
      };

      /**
       * The state of a point as this law uses it; the model stores it as
       * the flat array of state_variables() (pack(), unpack()).
       */
      struct State
      {
        /** Plastic strain (dimensionless). */
        SymmetricTensor<2, 3> plastic_strain;
        /** Damage thresholds in tension and compression (effective stress,
         * Pa). */
        double threshold_t = 0, threshold_c = 0;
        /** Equivalent plastic strains reached on the two envelopes. */
        double kappa_t = 0, kappa_c = 0;
        /** Damage in tension and compression (0 intact to 1), after the
         * viscous regularisation. */
        double damage_t = 0, damage_c = 0;
        /** The part of plastic_strain that the cracks' opening added
         * (tensile flow; dimensionless): with `IMPL-EX crack opening' =
         * frozen, IMPL-EX extrapolates only the rest (a state variable only
         * then). */
        SymmetricTensor<2, 3> crack_strain;
      };

      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        declare(prm,
                {"10e9",
                 "0.15",
                 "20e6",
                 "0.004",
                 "2e6",
                 "80",
                 "true",
                 "elastic",
                 "enlarged bricks",
                 "0"});
      }

      /** The entries, with the plugin's @p defaults. */
      static void
      declare(dealii::ParameterHandler       &prm,
              const DamagePlasticityDefaults &defaults);

      void
      parse_parameters(dealii::ParameterHandler &prm) override;

      bool
      is_linear() const override
      {
        return false;
      }

      /** IMPL-EX: evaluate_extrapolated() extrapolates the damages and the
       * plastic strain. */
      bool
      extrapolates() const override
      {
        return true;
      }

      std::vector<StateVariable>
      state_variables() const override;

      std::vector<std::string>
      reported_quantities() const override
      {
        return {"damage_tension", "damage_compression", "plastic_strain_norm"};
      }

      void
      report(ConstStateView            state,
             dealii::ArrayView<double> values) const override;

      std::vector<std::string>
      damage_names() const override
      {
        return {"damage_tension", "damage_compression"};
      }

      void
      damages(ConstStateView            state,
              dealii::ArrayView<double> values) const override;

      double
      youngs_modulus() const override
      {
        return E;
      }

      double
      compressive_strength() const override
      {
        return f_c;
      }

      double
      tensile_strength() const override
      {
        return f_t;
      }

      double
      tensile_fracture_energy() const override
      {
        return G_f;
      }

      double
      nonlocal_length() const override
      {
        return nonlocal_radius;
      }

      /** tau_t and tau_c of the trial effective stress C0 : (strain -
       * e_p,old). */
      std::array<double, 2>
      nonlocal_measures(const SymmetricTensor<2, 3> &strain,
                        ConstStateView               old_state,
                        const BrickPoint            &point) const override;

      std::vector<DerivedValue>
      derived_values() const override;

      double
      poissons_ratio() const override
      {
        return nu;
      }

      void
      check_point(const BrickPoint &point) const override;

      bool
      is_elastic(const SymmetricTensor<2, 3> &strain,
                 ConstStateView               old_state,
                 const BrickPoint            &point) const override;

      void
      evaluate(const SymmetricTensor<2, 3> &strain,
               ConstStateView               old_state,
               const BrickPoint            &point,
               StateView                    updated_state,
               SymmetricTensor<2, 3>       &stress,
               SymmetricTensor<4, 3>       &tangent) const override;

      void
      update_state(const SymmetricTensor<2, 3> &strain,
                   ConstStateView               old_state,
                   const BrickPoint            &point,
                   StateView                    updated_state,
                   SymmetricTensor<2, 3>       &stress) const override;

      void
      evaluate_extrapolated(const SymmetricTensor<2, 3> &strain,
                            ConstStateView               old,
                            ConstStateView               older,
                            const double                 ratio_t,
                            const BrickPoint &,
                            SymmetricTensor<2, 3> &stress,
                            SymmetricTensor<4, 3> &tangent) const override;

      void
      extrapolated_stress(const SymmetricTensor<2, 3> &strain,
                          ConstStateView               old,
                          ConstStateView               older,
                          const double                 ratio_t,
                          const BrickPoint &,
                          SymmetricTensor<2, 3> &stress) const override;

    private:
      /** Whether the point is intact and inside the initial elastic
       * domain. */
      bool
      is_elastic(const SymmetricTensor<2, 3> &strain,
                 const State                 &old,
                 const BrickPoint            &point) const;

      void
      evaluate(const SymmetricTensor<2, 3> &strain,
               const State                 &old,
               const BrickPoint            &point,
               State                       &updated,
               SymmetricTensor<2, 3>       &stress,
               SymmetricTensor<4, 3>       &tangent) const;

      /** IMPL-EX stress and (if @p tangent) tangent, see
       * evaluate_extrapolated(). */
      void
      extrapolated(const SymmetricTensor<2, 3> &strain,
                   const State                 &old,
                   const State                 &older,
                   const double                 ratio_t,
                   SymmetricTensor<2, 3>       &stress,
                   SymmetricTensor<4, 3>       *tangent) const;

      /**
       * The compressive return with `Plastic Poisson's ratio' nu_p != nu:
       * the plastic strain grows by lambda C_p^-1 : s- (C_p the compliance
       * with E0 and nu_p), the effective stress by -lambda C0 : C_p^-1 : s-
       * = -lambda (a_d dev(s-) + a_v vol(s-)), a_d = (1 + nu_p) / (1 + nu),
       * a_v = (1 - 2 nu_p) / (1 - 2 nu); lambda is the root of "compressive
       * measure of the new effective stress (with the interaction, if on,
       * at the new damage 1 - @p intact_c) = @p T" on (0, 1 / a_d), where
       * the deviator vanishes (false position, Illinois). On return @p
       * plus,
       * @p minus, @p tau_t and @p tau_c are those of the new effective
       * stress.
       */
      void
      flow(SymmetricTensor<2, 3> &minus,
           const double           intact_c,
           const double           d_t,
           const double           phi,
           const double           rho_t,
           const double           rho_c,
           const double           T,
           State                 &updated,
           SymmetricTensor<2, 3> &plus,
           double                &tau_t,
           double                &tau_c) const;

      /**
       * The tensile return with `Tensile plastic flow' = crack: the plastic
       * (crack) strain grows along N = n1 n1, n1 the direction of the
       * largest principal effective stress (Rankine's associated flow, no
       * lateral part), by p(e) - @p p_old (p the tensile
       * envelope's plastic strain), so that the effective stress moves by
       * -(p(e) - p_old) C0 : N; e, returned, is the root of "tensile
       * measure (with the interaction, at the new tensile damage and the
       * compressive damage @p d_c) = T(e) = E0 (e - p(e))" above
       * max(@p kappa_old, f_t / E0) (false position, Illinois). In
       * uniaxial stress this is the input curve, as with the elastic
       * flow; under lateral compression the crack opening no longer
       * carries the Poisson contraction -nu of C0^-1 : s+ into the other
       * directions, which relieved the compression parallel to the crack
       * by E0 nu times the opening strain. On return @p plus, @p minus,
       * @p tau_t and @p tau_c are those of the new effective stress.
       */
      double
      crack_return(const double           e_trial,
                   const double           kappa_old,
                   const double           p_old,
                   const double           d_c,
                   const double           l,
                   const double           phi,
                   const double           rho_t,
                   const double           rho_c,
                   State                 &updated,
                   SymmetricTensor<2, 3> &plus,
                   SymmetricTensor<2, 3> &minus,
                   double                &tau_t,
                   double                &tau_c) const;

      /** C0 : e. */
      SymmetricTensor<2, 3>
      effective(const SymmetricTensor<2, 3> &e) const;

      /** C0^-1 : s. */
      SymmetricTensor<2, 3>
      compliance(const SymmetricTensor<2, 3> &s) const;

      /**
       * The positive part P(s) = sum h(s_i) n_i (x) n_i of @p s, where h is
       * <x>+ blended over (0, delta = 0.001 f_t) by 2 x^2 / delta - x^3 /
       * delta^2 (C1, exact outside the band): a principal stress that is
       * zero at equilibrium (the free lateral directions of uniaxial
       * loading) sits at the kink of the split, where Newton with a
       * discontinuous tangent stalls. @p largest, if given, receives the
       * largest principal value's positive part <s_1>+. If @p derivative
       * is given, it receives dP/ds:
       * sum h'(s_i) M_i (x) M_i + sum_{i<j} 2 theta_ij G_ij (x) G_ij, with
       * M_i = n_i (x) n_i, G_ij = sym(n_i (x) n_j) and theta_ij the divided
       * difference (h(s_i) - h(s_j)) / (s_i - s_j) (the mean slope for
       * equal principal values).
       */
      SymmetricTensor<2, 3>
      positive_part(const SymmetricTensor<2, 3> &s,
                    SymmetricTensor<4, 3>       *derivative,
                    double                      *largest = nullptr) const;

      /** Spectral split of @p s and the equivalent stresses, times @p rho_t
       * and @p rho_c (BrickPoint::tensile_factor, compressive_factor). */
      void
      split(const SymmetricTensor<2, 3> &s,
            SymmetricTensor<2, 3>       &plus,
            SymmetricTensor<2, 3>       &minus,
            double                      &tau_t,
            double                      &tau_c,
            const double                 rho_t = 1,
            const double                 rho_c = 1) const;

      /**
       * The share m = min(u_c, u_t, 1/2) of the tension-compression
       * interaction: u_c = (1 - @p d_c) @p tau_c / f_c and u_t = (1 - @p
       * d_t)
       * @p tau_t / f_t are the nominal utilisations of the two strengths
       * (scaled by the point's strength factor @p phi); both equivalent
       * stresses are divided by 1 - m. 0 when the interaction is off.
       */
      double
      interaction_share(const double tau_c,
                        const double tau_t,
                        const double d_c,
                        const double d_t,
                        const double phi) const;

      /**
       * The factor k in (0, 1] that scales the part @p tau (its measure) of
       * the effective stress onto the threshold @p T when the measure is
       * g(k) = k tau / (1 - min(k a, M)): a is the utilisation of this
       * mode per unit of k, M = min(other utilisation, 1/2). g is
       * continuous and increasing; on the branch k a >= M, k = T (1 - M) /
       * tau, else k tau = T (1 - k a).
       */
      static double
      scale_onto(const double tau, const double a, const double M, double T);

      /**
       * The factor beta = min(1, 1 / (0.8 + c eps_1)) of `Cracked
       * compression softening' c on the compressive threshold of a point
       * whose tensile envelope strain is @p eps_1 (Vecchio & Collins
       * 1986); 1 if c = 0.
       */
      double
      cracked_compression_factor(const double eps_1) const;

      /** The compressive envelope at total strain @p e. */
      EnvelopePoint
      compression(const double e, const double l, const double phi) const;

      /** The tensile envelope at total strain @p e. */
      EnvelopePoint
      tension(const double e, const double l, const double phi) const;

      /** Plastic strain and damage of an envelope point (damage capped). */
      void
      decompose(const double e, const double b, EnvelopePoint &p) const;

      /** The point and its trial state that the returns of update() move
       * (damage_plasticity.cc). */
      struct Trial;

      /**
       * The factor that scales a measure tau (of the part s- or s+) onto
       * the threshold T: T / tau, with the interaction scale_onto() (the
       * envelope's damage, its strength f, the other part's utilisation)
       * (@p tau, @p T and @p f in Pa; @p phi: the point's strength
       * factor).
       */
      double
      threshold_scale(const double tau,
                      const double damage,
                      const double f,
                      const double other,
                      const double T,
                      const double phi) const;

      /** The compressive return of a pass of update(): if the trial's
       * compressive measure is past the envelope (its strength times
       * beta), the part s- is returned onto it (radially or by flow());
       * returns whether it was. */
      bool
      compressive_return(Trial &trial, State &updated) const;

      /** The tensile return of a pass of update(): if the trial's tensile
       * measure is past the envelope, the part s+ is returned onto it
       * (elastic flow, or crack_return() with `Tensile plastic flow' =
       * crack); returns whether a crack grew (crack flow only). */
      bool
      tensile_return(Trial &trial, State &updated) const;

      /** The stress update (see the file documentation). */
      void
      update(const SymmetricTensor<2, 3> &strain,
             const State                 &old,
             const BrickPoint            &point,
             State                       &updated,
             SymmetricTensor<2, 3>       &stress) const;

      /** Central differences of @p function at @p strain. */
      template <class Function>
      SymmetricTensor<4, 3>
      numerical_tangent(const Function              &function,
                        const SymmetricTensor<2, 3> &strain) const;

      double E = 10e9, nu = 0.15, f_c = 20e6, ratio = 0.4, eps_c = 0.004;
      /** The normalised unit strength f_b when `Compressive strength
       * definition' = normalised (f_c is then derived from it), else 0. */
      double f_normalised = 0;
      double G_c = 20000, b_c = 0.7, f_t = 2e6, G_f = 80, b_t = 0;
      /** The full path of the law's subsection (parse_parameters()), so
       * that a check made while running names its entries ("Mortar
       * material/Mortar/..."); empty for a law set up in code. */
      std::string section;
      double      rho = 1.16, d_max = 0.99, mu_visc = 0;
      double      alpha = 0, lambda = 0, mu = 0;
      /** `Cracked compression softening' c (0: off). */
      double c_cracked = 0;
      /** `Cracked compression residual ratio': the lower bound of beta. */
      double beta_residual = 0;
      /** `Compressive softening', `Tension-compression interaction'. */
      bool softening = true, interaction = false;
      /** `Plastic Poisson's ratio': elastic (radial) or nu_p. */
      bool radial_flow = true;
      /** `Tensile plastic flow' = crack. */
      bool crack_flow = false;
      /** `IMPL-EX crack opening' = frozen. */
      bool   freeze_crack_opening = false;
      double nu_p                 = 0.15;
      /** `Confinement coefficient' and Lubliner's gamma from it. */
      double k_confinement = 0, gamma = 0;
      /** `Nonlocal length' (m, 0: local). */
      double nonlocal_radius = 0;
      /** The initial stiffness. */
      SymmetricTensor<4, 3> C0;
    };
  } // namespace brickwork
} // namespace masonry

#endif
