/**
 * @file
 * Brick material `damage plasticity`: effective-stress plasticity with
 * separate tension and compression damage for bricks under cyclic
 * compression.
 *
 * The formulation (documented for users in the registration text below and
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
 * - `Plastic Poisson's ratio' nu_p: the compressive plastic strain grows
 *   along C_p^-1 : s- (compliance with E0, nu_p) instead of C0^-1 : s-,
 *   with the multiplier from a scalar root search (flow()); a confined
 *   mortar keeps expanding laterally only with nu_p > p / (|sigma_1| + p).
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/core/parameters.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace masonry
{
  namespace brickwork
  {
    using dealii::SymmetricTensor;

    namespace
    {
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
      };

      /** Number of doubles of a State. */
      constexpr unsigned int n_state = 12;

      State
      unpack(ConstStateView v)
      {
        AssertDimension(v.size(), n_state);
        State s;
        for (unsigned int i = 0; i < 6; ++i)
          s.plastic_strain.access_raw_entry(i) = v[i];
        s.threshold_t = v[6];
        s.threshold_c = v[7];
        s.kappa_t     = v[8];
        s.kappa_c     = v[9];
        s.damage_t    = v[10];
        s.damage_c    = v[11];
        return s;
      }

      void
      pack(const State &s, StateView v)
      {
        AssertDimension(v.size(), n_state);
        for (unsigned int i = 0; i < 6; ++i)
          v[i] = s.plastic_strain.access_raw_entry(i);
        v[6]  = s.threshold_t;
        v[7]  = s.threshold_c;
        v[8]  = s.kappa_t;
        v[9]  = s.kappa_c;
        v[10] = s.damage_t;
        v[11] = s.damage_c;
      }
    } // namespace

    /**
     * Defaults of the entries that differ between the two plugins of this
     * file (`damage plasticity` for units, `mortar` for a meshed mortar
     * layer).
     */
    struct DamagePlasticityDefaults
    {
      const char *E, *nu, *f_c, *eps_c, *f_t, *G_f, *softening, *nu_p, *what;
    };

    /** See the file documentation. */
    class DamagePlasticityBrick : public BrickMaterial
    {
    public:
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
                 "enlarged bricks"});
      }

      /** The entries, with the plugin's @p defaults. */
      static void
      declare(dealii::ParameterHandler       &prm,
              const DamagePlasticityDefaults &defaults)
      {
        using dealii::Patterns::Bool;
        using dealii::Patterns::Double;
        prm.declare_entry("Young's modulus",
                          defaults.E,
                          Double(0),
                          std::string("Initial Young's modulus E0 of the ") +
                            defaults.what + ", Pa (> 0).");
        prm.declare_entry("Poisson's ratio",
                          defaults.nu,
                          Double(-1, 0.5),
                          "Poisson's ratio (dimensionless, -1 < nu < 0.5).");
        prm.declare_entry("Compressive strength",
                          defaults.f_c,
                          Double(0),
                          "Uniaxial compressive strength f_c, Pa (> 0): the "
                          "peak of the compressive envelope.");
        prm.declare_entry(
          "Elastic limit ratio",
          "0.4",
          Double(0, 1),
          "Stress at the end of the linear part of the compressive "
          "envelope over f_c (dimensionless, 0 < ratio < 1).");
        prm.declare_entry(
          "Strain at peak",
          defaults.eps_c,
          Double(0),
          "Total strain eps_c at the compressive peak (dimensionless, at "
          "least f_c / E0). Between the elastic limit e0 = ratio f_c / E0 "
          "and eps_c the envelope is sigma = f_c0 + (f_c - f_c0) (k x - "
          "x^2) / (1 + (k - 2) x), x = (e - e0) / (eps_c - e0), k = E0 "
          "(eps_c - e0) / (f_c - f_c0): slope E0 at e0, zero at the peak "
          "(the CEB-FIP/Sargin shape).");
        prm.declare_entry(
          "Compressive fracture energy",
          "20000",
          Double(0),
          "Crushing energy G_c, J/m^2 (> 0): after the peak sigma = f_c "
          "exp(-(e - eps_c) / w_c) with w_c = G_c / (f_c l), so that the "
          "area under the softening branch times the element's "
          "characteristic length l (cube root of its volume) is G_c.");
        prm.declare_entry(
          "Plastic strain ratio",
          "0.7",
          Double(0, 1),
          "Share b_c of the inelastic strain e - sigma / E0 that is plastic "
          "on the compressive envelope (dimensionless, 0 <= b_c < 1): "
          "e_p = b_c (e - sigma / E0); the rest is damage, d_c = 1 - sigma "
          "/ (E0 (e - e_p)), so unloading follows (1 - d_c) E0 to e_p.");
        prm.declare_entry("Tensile strength",
                          defaults.f_t,
                          Double(0),
                          "Uniaxial tensile strength f_t, Pa (> 0); linear "
                          "up to it.");
        prm.declare_entry(
          "Tensile fracture energy",
          defaults.G_f,
          Double(0),
          "Fracture energy G_f, J/m^2 (> 0): after the peak sigma = f_t "
          "exp(-(e - f_t / E0) / w_t), w_t = G_f / (f_t l) - f_t / (2 "
          "E0), so that the whole area under the tension curve times l is "
          "G_f. Needs elements smaller than 2 G_f E0 / f_t^2.");
        prm.declare_entry(
          "Tensile plastic strain ratio",
          "0",
          Double(0, 1),
          "Share b_t of the inelastic tensile strain that is plastic "
          "(dimensionless, 0 <= b_t < 1; 0: cracks close completely).");
        prm.declare_entry(
          "Biaxial to uniaxial strength ratio",
          "1.16",
          Double(1, 10),
          "Equibiaxial over uniaxial compressive strength rho "
          "(dimensionless, >= 1): alpha = (rho - 1) / (2 rho - 1) in the "
          "compressive measure (sqrt(3 J2) + alpha I1) / (1 - alpha) of the "
          "negative part of the effective stress (Lubliner et al. 1989).");
        prm.declare_entry(
          "Maximum damage",
          "0.99",
          Double(0, 1),
          "Cap of both damages (dimensionless, 0 < d_max < 1): beyond it the "
          "plastic strain takes the rest of the envelope, so the stress "
          "still follows the envelope and the stiffness never vanishes.");
        prm.declare_entry(
          "Viscosity",
          "0",
          Double(0),
          "Viscous regularisation of both damages, s (>= 0; 0: none): d_v = "
          "(d + (mu / dt) d_v,old) / (1 + mu / dt) with dt the pseudo-time "
          "of the step (platen displacement increment / `Platen speed').");
        prm.declare_entry(
          "Compressive softening",
          defaults.softening,
          Bool(),
          "Whether the compressive envelope softens after its peak (true: "
          "sigma = f_c exp(-(e - eps_c) / w_c), see `Compressive fracture "
          "energy'; false: sigma = f_c beyond eps_c, perfectly plastic in "
          "compression: the material flows at its (confined) strength, the "
          "inelastic strain still split by `Plastic strain ratio').");
        prm.declare_entry(
          "Confinement coefficient",
          "0",
          Double(0),
          "k in |sigma_1| = f_c + k p, the rise of the compressive strength "
          "with an equal lateral pressure p (triaxial compression, "
          "dimensionless). 0: the value of the cone alone, k0 = (1 + 2 "
          "alpha) / (1 - alpha) (1.414 for rho = 1.16); a value k >= k0 adds "
          "Lubliner's term -gamma <-s_max> of the largest principal effective "
          "stress when all three are compressive, gamma = k (1 - alpha) - (1 "
          "+ 2 alpha). Richart et al. (1928) measured k of about 4.1 for "
          "concrete (recalled, not checked against the paper).");
        prm.declare_entry(
          "Plastic Poisson's ratio",
          defaults.nu_p,
          dealii::Patterns::Anything(),
          "Direction of the compressive plastic flow: `elastic' (the plastic "
          "strain grows along C0^-1 : s-, as the elastic strain, and the "
          "uniaxial response is exactly the input curve) or a number nu_p "
          "(dimensionless, -1 < nu_p < 1): along C_p^-1 : s- with the "
          "compliance of E0 and nu_p, so 0.5 is isochoric flow and larger "
          "values dilate. A confined layer keeps expanding laterally only "
          "if nu_p exceeds the ratio p / (|sigma_1| + p) of its stresses; "
          "with `elastic' its lateral pressure stops at p = nu |sigma_1| / "
          "(1 - nu). The peak and plateau stay on the envelope; the strain "
          "at which a point reaches them changes.");
        prm.declare_entry(
          "Tension-compression interaction",
          "false",
          Bool(),
          "Whether tension lowers the compressive strength and compression "
          "the tensile strength (true: failure on the linear envelope "
          "sigma_t / f_t + sigma_c / f_c = 1 under compression with lateral "
          "tension, the Lee-Fenves beta <s_max> term written per mode: with "
          "the utilisations u_c = (1 - d_c) tau_c / f_c and u_t = (1 - d_t) "
          "s_max / f_t and m = min(u_c, u_t, 1/2), both measures are divided "
          "by 1 - m, so a point where compression dominates fails in "
          "compression and one where tension dominates cracks, and pure "
          "tension or compression is unchanged; false: independent "
          "criteria, a square envelope).");
      }

      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        E             = prm.get_double("Young's modulus");
        nu            = prm.get_double("Poisson's ratio");
        f_c           = prm.get_double("Compressive strength");
        ratio         = prm.get_double("Elastic limit ratio");
        eps_c         = prm.get_double("Strain at peak");
        G_c           = prm.get_double("Compressive fracture energy");
        b_c           = prm.get_double("Plastic strain ratio");
        f_t           = prm.get_double("Tensile strength");
        G_f           = prm.get_double("Tensile fracture energy");
        b_t           = prm.get_double("Tensile plastic strain ratio");
        rho           = prm.get_double("Biaxial to uniaxial strength ratio");
        d_max         = prm.get_double("Maximum damage");
        mu_visc       = prm.get_double("Viscosity");
        softening     = prm.get_bool("Compressive softening");
        interaction   = prm.get_bool("Tension-compression interaction");
        k_confinement = prm.get_double("Confinement coefficient");
        {
          const std::string flow = prm.get("Plastic Poisson's ratio");
          radial_flow            = flow == "elastic";
          if (!radial_flow)
            {
              std::size_t end = 0;
              try
                {
                  nu_p = std::stod(flow, &end);
                }
              catch (...)
                {
                  end = 0;
                }
              AssertThrow(end == flow.size() && end > 0 && nu_p > -1 &&
                            nu_p < 1,
                          ExcParameter("Plastic Poisson's ratio",
                                       "must be `elastic' or a number "
                                       "strictly between -1 and 1"));
            }
        }
        auto positive = [](const double v, const char *entry) {
          AssertThrow(v > 0, ExcParameter(entry, "must be positive"));
        };
        positive(E, "Young's modulus");
        positive(f_c, "Compressive strength");
        positive(G_c, "Compressive fracture energy");
        positive(f_t, "Tensile strength");
        positive(G_f, "Tensile fracture energy");
        AssertThrow(nu > -1 && nu < 0.5,
                    ExcParameter("Poisson's ratio",
                                 "must lie strictly between -1 and 0.5"));
        AssertThrow(ratio > 0 && ratio < 1,
                    ExcParameter("Elastic limit ratio",
                                 "must lie strictly between 0 and 1"));
        AssertThrow(b_c < 1,
                    ExcParameter("Plastic strain ratio", "must be below 1"));
        AssertThrow(b_t < 1,
                    ExcParameter("Tensile plastic strain ratio",
                                 "must be below 1"));
        AssertThrow(d_max > 0 && d_max < 1,
                    ExcParameter("Maximum damage",
                                 "must lie strictly between 0 and 1"));
        std::ostringstream m;
        m << "must be at least f_c / E0 = " << f_c / E
          << " (else the envelope cannot rise from the elastic limit to "
             "the peak with a slope below E0)";
        AssertThrow(eps_c >= f_c / E * (1 + 1e-12),
                    ExcParameter("Strain at peak", m.str()));
        alpha           = (rho - 1) / (2 * rho - 1);
        const double k0 = (1 + 2 * alpha) / (1 - alpha);
        {
          std::ostringstream m;
          m << "must be 0 or at least (1 + 2 alpha) / (1 - alpha) = " << k0
            << ", the value of the compressive cone with `Biaxial to "
               "uniaxial strength ratio' = "
            << rho;
          AssertThrow(k_confinement == 0 || k_confinement >= k0 * (1 - 1e-12),
                      ExcParameter("Confinement coefficient", m.str()));
        }
        gamma  = k_confinement == 0 ?
                   0. :
                   std::max(0., k_confinement * (1 - alpha) - (1 + 2 * alpha));
        lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
        mu     = E / (2 * (1 + nu));
        C0     = elastic_stiffness();
      }

      bool
      is_linear() const override
      {
        return false;
      }

      std::vector<StateVariable>
      state_variables() const override
      {
        // the order of pack() and unpack()
        return {{"plastic_strain", 6},
                {"threshold_tension", 1},
                {"threshold_compression", 1},
                {"kappa_tension", 1},
                {"kappa_compression", 1},
                {"damage_tension", 1},
                {"damage_compression", 1}};
      }

      std::vector<std::string>
      reported_quantities() const override
      {
        return {"damage_tension", "damage_compression", "plastic_strain_norm"};
      }

      void
      report(ConstStateView            state,
             dealii::ArrayView<double> values) const override
      {
        const State s = unpack(state);
        values[0]     = s.damage_t;
        values[1]     = s.damage_c;
        values[2]     = s.plastic_strain.norm();
      }

      std::vector<std::string>
      damage_names() const override
      {
        return {"damage_tension", "damage_compression"};
      }

      void
      damages(ConstStateView            state,
              dealii::ArrayView<double> values) const override
      {
        values[0] = state[10];
        values[1] = state[11];
      }

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

      std::vector<DerivedValue>
      derived_values() const override
      {
        return {{"alpha",
                 alpha,
                 "-",
                 "(rho - 1) / (2 rho - 1) of the compressive measure "
                 "(Lubliner), rho = `Biaxial to uniaxial strength ratio'"},
                {"elastic_limit_stress",
                 ratio * f_c,
                 "Pa",
                 "`Elastic limit ratio' x `Compressive strength'"},
                {"confinement_coefficient",
                 (1 + 2 * alpha + gamma) / (1 - alpha),
                 "-",
                 "k = (1 + 2 alpha + gamma) / (1 - alpha): the rise of the "
                 "compressive measure's strength per unit of equal lateral "
                 "pressure, |sigma_1| = f_c + k p (gamma = 0 unless "
                 "`Confinement coefficient' is set)"}};
      }

      double
      poissons_ratio() const override
      {
        return nu;
      }

      void
      check_point(const BrickPoint &point) const override
      {
        const double ft    = point.strength_factor * f_t;
        const double l_max = 2 * G_f * E / (ft * ft);
        if (point.characteristic_length >= l_max)
          {
            std::ostringstream m;
            m << "is too small for elements of " << point.characteristic_length
              << " m: the tension softening needs l < 2 G_f E0 / f_t^2 = "
              << l_max << " m (refine the mesh or raise the energy)";
            AssertThrow(false,
                        ExcParameter("Tensile fracture energy", m.str()));
          }
      }

      bool
      is_elastic(const SymmetricTensor<2, 3> &strain,
                 ConstStateView               old_state,
                 const BrickPoint            &point) const override
      {
        return is_elastic(strain, unpack(old_state), point);
      }

      void
      evaluate(const SymmetricTensor<2, 3> &strain,
               ConstStateView               old_state,
               const BrickPoint            &point,
               StateView                    updated_state,
               SymmetricTensor<2, 3>       &stress,
               SymmetricTensor<4, 3>       &tangent) const override
      {
        const State old = unpack(old_state);
        State       updated;
        evaluate(strain, old, point, updated, stress, tangent);
        pack(updated, updated_state);
      }

      void
      update_state(const SymmetricTensor<2, 3> &strain,
                   ConstStateView               old_state,
                   const BrickPoint            &point,
                   StateView                    updated_state,
                   SymmetricTensor<2, 3>       &stress) const override
      {
        State updated;
        update(strain, unpack(old_state), point, updated, stress);
        pack(updated, updated_state);
      }

      void
      evaluate_extrapolated(const SymmetricTensor<2, 3> &strain,
                            ConstStateView               old,
                            ConstStateView               older,
                            const double                 ratio_t,
                            const BrickPoint &,
                            SymmetricTensor<2, 3> &stress,
                            SymmetricTensor<4, 3> &tangent) const override
      {
        extrapolated(
          strain, unpack(old), unpack(older), ratio_t, stress, &tangent);
      }

      void
      extrapolated_stress(const SymmetricTensor<2, 3> &strain,
                          ConstStateView               old,
                          ConstStateView               older,
                          const double                 ratio_t,
                          const BrickPoint &,
                          SymmetricTensor<2, 3> &stress) const override
      {
        extrapolated(
          strain, unpack(old), unpack(older), ratio_t, stress, nullptr);
      }

    private:
      /** Whether the point is intact and inside the initial elastic
       * domain. */
      bool
      is_elastic(const SymmetricTensor<2, 3> &strain,
                 const State                 &old,
                 const BrickPoint            &point) const
      {
        if (old.kappa_t != 0 || old.kappa_c != 0 || old.damage_t != 0 ||
            old.damage_c != 0 || old.plastic_strain.norm() != 0)
          return false;
        const SymmetricTensor<2, 3> s = effective(strain);
        double                      tau_t, tau_c;
        SymmetricTensor<2, 3>       plus, minus;
        split(s, plus, minus, tau_t, tau_c);
        const double phi = point.strength_factor;
        const double m   = interaction_share(tau_c, tau_t, 0, 0, phi);
        return tau_c <= phi * ratio * f_c * (1 - m) &&
               tau_t <= phi * f_t * (1 - m);
      }

      void
      evaluate(const SymmetricTensor<2, 3> &strain,
               const State                 &old,
               const BrickPoint            &point,
               State                       &updated,
               SymmetricTensor<2, 3>       &stress,
               SymmetricTensor<4, 3>       &tangent) const
      {
        update(strain, old, point, updated, stress);
        if (is_elastic(strain, old, point))
          {
            tangent = elastic_stiffness();
            return;
          }
        auto function = [&](const SymmetricTensor<2, 3> &e) {
          State                 scratch;
          SymmetricTensor<2, 3> s;
          update(e, old, point, scratch, s);
          return s;
        };
        tangent = numerical_tangent(function, strain);
      }

      /** IMPL-EX stress and (if @p tangent) tangent, see
       * evaluate_extrapolated(). */
      void
      extrapolated(const SymmetricTensor<2, 3> &strain,
                   const State                 &old,
                   const State                 &older,
                   const double                 ratio_t,
                   SymmetricTensor<2, 3>       &stress,
                   SymmetricTensor<4, 3>       *tangent) const
      {
        // damages and plastic strain extrapolated and frozen
        auto extrapolate = [&](const double d, const double d_older) {
          return std::clamp(d + ratio_t * (d - d_older), d, d_max);
        };
        const double d_t = extrapolate(old.damage_t, older.damage_t);
        const double d_c = extrapolate(old.damage_c, older.damage_c);
        const SymmetricTensor<2, 3> plastic =
          old.plastic_strain +
          ratio_t * (old.plastic_strain - older.plastic_strain);
        // stress = (1 - d_t) P(s) + (1 - d_c) (s - P(s)), s = C0 : (e - e_p)
        // with everything but e frozen, so the tangent is exact and closed:
        // ((d_c - d_t) dP/ds + (1 - d_c) I) : C0
        const SymmetricTensor<2, 3> s = effective(strain - plastic);
        SymmetricTensor<4, 3>       dP;
        const SymmetricTensor<2, 3> P =
          positive_part(s, tangent ? &dP : nullptr);
        stress = (1 - d_t) * P + (1 - d_c) * (s - P);
        if (tangent)
          *tangent =
            ((d_c - d_t) * dP + (1 - d_c) * dealii::identity_tensor<3>()) * C0;
      }

      /**
       * The compressive return with `Plastic Poisson's ratio' nu_p != nu:
       * the plastic strain grows by lambda C_p^-1 : s- (C_p the compliance
       * with E0 and nu_p), the effective stress by -lambda C0 : C_p^-1 : s-
       * = -lambda (a_d dev(s-) + a_v vol(s-)), a_d = (1 + nu_p) / (1 + nu),
       * a_v = (1 - 2 nu_p) / (1 - 2 nu); lambda is the root of "compressive
       * measure of the new effective stress (with the interaction, if on,
       * at the new damage 1 - @p intact_c) = @p T" on (0, 1 / a_d), where
       * the deviator vanishes (false position, Illinois). On return @p plus,
       * @p minus, @p tau_t and @p tau_c are those of the new effective
       * stress.
       */
      void
      flow(SymmetricTensor<2, 3> &minus,
           const double           intact_c,
           const double           d_t,
           const double           phi,
           const double           T,
           State                 &updated,
           SymmetricTensor<2, 3> &plus,
           double                &tau_t,
           double                &tau_c) const
      {
        const double                a_d = (1 + nu_p) / (1 + nu);
        const double                a_v = (1 - 2 * nu_p) / (1 - 2 * nu);
        const SymmetricTensor<2, 3> I   = dealii::unit_symmetric_tensor<3>();
        const SymmetricTensor<2, 3> G =
          a_d * dealii::deviator(minus) + a_v * dealii::trace(minus) / 3 * I;
        const SymmetricTensor<2, 3> s0 = plus + minus;
        SymmetricTensor<2, 3>       p, m;
        double                      tt, tc;
        auto                        excess = [&](const double lambda) {
          split(s0 - lambda * G, p, m, tt, tc);
          const double share =
            interaction_share(tc, tt, 1 - intact_c, d_t, phi);
          return tc / (1 - share) - T;
        };
        double a = 0, b = 1 / a_d, fa = excess(a), fb = excess(b);
        // on (or by round-off inside) the threshold already: no flow; the
        // threshold out of reach along the flow: as far as it goes
        double lambda = fa <= 0 ? 0. : b;
        if (fa > 0 && fb < 0)
          for (unsigned int it = 0, side = 2; it < 100; ++it)
            {
              lambda         = (a * fb - b * fa) / (fb - fa);
              const double f = excess(lambda);
              if (std::abs(f) <= 1e-12 * T)
                break;
              if (f > 0)
                {
                  a = lambda, fa = f;
                  if (side == 0)
                    fb /= 2;
                  side = 0;
                }
              else
                {
                  b = lambda, fb = f;
                  if (side == 1)
                    fa /= 2;
                  side = 1;
                }
            }
        updated.plastic_strain +=
          lambda *
          ((1 + nu_p) / E * minus - nu_p / E * dealii::trace(minus) * I);
        split(s0 - lambda * G, plus, minus, tau_t, tau_c);
      }

      /** C0 : e. */
      SymmetricTensor<2, 3>
      effective(const SymmetricTensor<2, 3> &e) const
      {
        return lambda * dealii::trace(e) * dealii::unit_symmetric_tensor<3>() +
               2 * mu * e;
      }

      /** C0^-1 : s. */
      SymmetricTensor<2, 3>
      compliance(const SymmetricTensor<2, 3> &s) const
      {
        return (1 + nu) / E * s -
               nu / E * dealii::trace(s) * dealii::unit_symmetric_tensor<3>();
      }

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
                    double                      *largest = nullptr) const
      {
        SymmetricTensor<2, 3> P;
        if (derivative)
          *derivative = 0;
        if (largest)
          *largest = 0;
        if (s.norm() == 0)
          return P;
        const double delta = 1e-3 * f_t;
        auto         h     = [&](const double x) {
          return x <= 0     ? 0. :
                             x >= delta ? x :
                                          x * x * (2 / delta - x / (delta * delta));
        };
        auto slope = [&](const double x) {
          return x <= 0     ? 0. :
                 x >= delta ? 1. :
                              x * (4 - 3 * x / delta) / delta;
        };
        const auto eig = dealii::eigenvectors(s);
        if (largest)
          *largest = std::max(eig[0].first, 0.);
        SymmetricTensor<2, 3> M[3];
        for (unsigned int i = 0; i < 3; ++i)
          {
            M[i] = dealii::symmetrize(
              dealii::outer_product(eig[i].second, eig[i].second));
            P += h(eig[i].first) * M[i];
          }
        if (derivative)
          {
            const double scale =
              std::max(std::abs(eig[0].first), std::abs(eig[2].first));
            for (unsigned int i = 0; i < 3; ++i)
              {
                *derivative +=
                  slope(eig[i].first) * dealii::outer_product(M[i], M[i]);
                for (unsigned int j = i + 1; j < 3; ++j)
                  {
                    const double a = eig[i].first, b = eig[j].first;
                    const double theta = std::abs(a - b) <= 1e-10 * scale ?
                                           0.5 * (slope(a) + slope(b)) :
                                           (h(a) - h(b)) / (a - b);
                    const SymmetricTensor<2, 3> G = dealii::symmetrize(
                      dealii::outer_product(eig[i].second, eig[j].second));
                    *derivative += 2 * theta * dealii::outer_product(G, G);
                  }
              }
          }
        return P;
      }

      /** Spectral split of @p s and the equivalent stresses. */
      void
      split(const SymmetricTensor<2, 3> &s,
            SymmetricTensor<2, 3>       &plus,
            SymmetricTensor<2, 3>       &minus,
            double                      &tau_t,
            double                      &tau_c) const
      {
        plus            = positive_part(s, nullptr, &tau_t);
        minus           = s - plus;
        const double I1 = dealii::trace(minus);
        const double J2 =
          0.5 * dealii::deviator(minus).norm() * dealii::deviator(minus).norm();
        // Lubliner's -gamma <-s_max>: the largest principal value of s- is
        // negative only when all three principal stresses are compressive
        const double s_max = gamma > 0 ? dealii::eigenvalues(minus)[0] : 0.;
        tau_c              = std::max(0.,
                         (std::sqrt(3 * J2) + alpha * I1 +
                          gamma * std::min(s_max, 0.)) /
                           (1 - alpha));
      }

      /**
       * The share m = min(u_c, u_t, 1/2) of the tension-compression
       * interaction: u_c = (1 - @p d_c) @p tau_c / f_c and u_t = (1 - @p d_t)
       * @p tau_t / f_t are the nominal utilisations of the two strengths
       * (scaled by the point's strength factor @p phi); both equivalent
       * stresses are divided by 1 - m. 0 when the interaction is off.
       */
      double
      interaction_share(const double tau_c,
                        const double tau_t,
                        const double d_c,
                        const double d_t,
                        const double phi) const
      {
        if (!interaction)
          return 0.;
        return std::min({(1 - d_c) * tau_c / (phi * f_c),
                         (1 - d_t) * tau_t / (phi * f_t),
                         0.5});
      }

      /**
       * The factor k in (0, 1] that scales the part @p tau (its measure) of
       * the effective stress onto the threshold @p T when the measure is
       * g(k) = k tau / (1 - min(k a, M)): a is the utilisation of this
       * mode per unit of k, M = min(other utilisation, 1/2). g is continuous
       * and increasing; on the branch k a >= M, k = T (1 - M) / tau, else
       * k tau = T (1 - k a).
       */
      static double
      scale_onto(const double tau, const double a, const double M, double T)
      {
        const double k_high = T * (1 - M) / tau;
        const double k      = k_high * a >= M ? k_high : T / (tau + T * a);
        return std::clamp(k, 0., 1.);
      }

      /** The compressive envelope at total strain @p e. */
      EnvelopePoint
      compression(const double e, const double l, const double phi) const
      {
        const double  fc = phi * f_c, f0 = ratio * fc, e0 = f0 / E;
        const double  ec = phi * eps_c;
        EnvelopePoint p;
        if (e <= e0)
          {
            p.stress = E * e;
            return p;
          }
        if (e <= ec)
          {
            const double x = (e - e0) / (ec - e0);
            const double k = E * (ec - e0) / (fc - f0);
            p.stress = f0 + (fc - f0) * (k * x - x * x) / (1 + (k - 2) * x);
          }
        else
          p.stress = softening ? fc * std::exp(-(e - ec) * fc * l / G_c) : fc;
        decompose(e, b_c, p);
        return p;
      }

      /** The tensile envelope at total strain @p e. */
      EnvelopePoint
      tension(const double e, const double l, const double phi) const
      {
        const double  ft = phi * f_t, e0 = ft / E;
        EnvelopePoint p;
        if (e <= e0)
          {
            p.stress = E * e;
            return p;
          }
        const double w = G_f / (ft * l) - ft / (2 * E);
        p.stress       = ft * std::exp(-(e - e0) / w);
        decompose(e, b_t, p);
        return p;
      }

      /** Plastic strain and damage of an envelope point (damage capped). */
      void
      decompose(const double e, const double b, EnvelopePoint &p) const
      {
        p.plastic = b * (e - p.stress / E);
        p.damage  = 1 - p.stress / (E * (e - p.plastic));
        if (p.damage > d_max)
          {
            p.damage  = d_max;
            p.plastic = e - p.stress / ((1 - d_max) * E);
          }
        p.damage = std::max(p.damage, 0.);
      }

      /** The stress update (see the file documentation). */
      void
      update(const SymmetricTensor<2, 3> &strain,
             const State                 &old,
             const BrickPoint            &point,
             State                       &updated,
             SymmetricTensor<2, 3>       &stress) const
      {
        const double phi = point.strength_factor;
        const double l   = point.characteristic_length;
        updated          = old;
        SymmetricTensor<2, 3> plus, minus;
        double                tau_t, tau_c;
        split(
          effective(strain - old.plastic_strain), plus, minus, tau_t, tau_c);
        double d_t = old.kappa_t > 0 ? tension(old.kappa_t, l, phi).damage : 0.;
        double d_c =
          old.kappa_c > 0 ? compression(old.kappa_c, l, phi).damage : 0.;
        // compression: the envelope strain this trial state corresponds to
        {
          const double m   = interaction_share(tau_c, tau_t, d_c, d_t, phi);
          const double tau = tau_c / (1 - m);
          const double p_old =
            old.kappa_c > 0 ? compression(old.kappa_c, l, phi).plastic : 0.;
          const double e = p_old + tau / E;
          if (e > old.kappa_c && e > ratio * phi * f_c / E && tau_c > 0)
            {
              const EnvelopePoint env = compression(e, l, phi);
              const double        T   = E * (e - env.plastic);
              const double        s =
                interaction ?
                         scale_onto(tau_c,
                             (1 - env.damage) * tau_c / (phi * f_c),
                             std::min((1 - d_t) * tau_t / (phi * f_t), 0.5),
                             T) :
                         T / tau_c;
              if (radial_flow)
                {
                  updated.plastic_strain += (1 - s) * compliance(minus);
                  minus *= s;
                  tau_c *= s;
                }
              else
                flow(minus,
                     1 - env.damage,
                     d_t,
                     phi,
                     T,
                     updated,
                     plus,
                     tau_t,
                     tau_c);
              updated.kappa_c     = e;
              updated.threshold_c = T;
              d_c                 = env.damage;
            }
        }
        {
          const double m   = interaction_share(tau_c, tau_t, d_c, d_t, phi);
          const double tau = tau_t / (1 - m);
          const double p_old =
            old.kappa_t > 0 ? tension(old.kappa_t, l, phi).plastic : 0.;
          const double e = p_old + tau / E;
          if (e > old.kappa_t && e > phi * f_t / E && tau_t > 0)
            {
              const EnvelopePoint env = tension(e, l, phi);
              const double        T   = E * (e - env.plastic);
              const double        s =
                interaction ?
                         scale_onto(tau_t,
                             (1 - env.damage) * tau_t / (phi * f_t),
                             std::min((1 - d_c) * tau_c / (phi * f_c), 0.5),
                             T) :
                         T / tau_t;
              updated.plastic_strain += (1 - s) * compliance(plus);
              plus *= s;
              updated.kappa_t     = e;
              updated.threshold_t = T;
              d_t                 = env.damage;
            }
        }
        // viscous regularisation
        const double a =
          mu_visc > 0 && point.time_step > 0 ? mu_visc / point.time_step : 0.;
        updated.damage_t =
          std::max((d_t + a * old.damage_t) / (1 + a), old.damage_t);
        updated.damage_c =
          std::max((d_c + a * old.damage_c) / (1 + a), old.damage_c);
        stress = (1 - updated.damage_t) * plus + (1 - updated.damage_c) * minus;
      }

      /** Central differences of @p function at @p strain. */
      template <class Function>
      SymmetricTensor<4, 3>
      numerical_tangent(const Function              &function,
                        const SymmetricTensor<2, 3> &strain) const
      {
        const double          h = 1e-7 * std::max(strain.norm(), f_t / E);
        SymmetricTensor<4, 3> C;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            {
              SymmetricTensor<2, 3> p = strain, m = strain;
              p[i][j] += h;
              m[i][j] -= h;
              // a shear component moves e_ij and e_ji together
              const SymmetricTensor<2, 3> ds =
                (function(p) - function(m)) / (2 * h * (i == j ? 1 : 2));
              for (unsigned int k = 0; k < 3; ++k)
                for (unsigned int n = k; n < 3; ++n)
                  C[k][n][i][j] = ds[k][n];
            }
        return C;
      }

      double E = 10e9, nu = 0.15, f_c = 20e6, ratio = 0.4, eps_c = 0.004;
      double G_c = 20000, b_c = 0.7, f_t = 2e6, G_f = 80, b_t = 0;
      double rho = 1.16, d_max = 0.99, mu_visc = 0;
      double alpha = 0, lambda = 0, mu = 0;
      /** `Compressive softening', `Tension-compression interaction'. */
      bool softening = true, interaction = false;
      /** `Plastic Poisson's ratio': elastic (radial) or nu_p. */
      bool   radial_flow = true;
      double nu_p        = 0.15;
      /** `Confinement coefficient' and Lubliner's gamma from it. */
      double k_confinement = 0, gamma = 0;
      /** The initial stiffness. */
      SymmetricTensor<4, 3> C0;
    };

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

MASONRY_REGISTER_BRICK_MATERIAL(
  masonry::brickwork::DamagePlasticityBrick,
  "damage plasticity",
  "Damage-plasticity for bricks under cyclic compression (Lubliner et al. "
  "1989 / Lee & Fenves 1998 measure, explicit update after Faria, Oliver & "
  "Cervera 1998 and Petracca et al. 2022): effective stress s = C0 : (e - "
  "e_p) split into positive and negative principal parts; compressive "
  "measure (sqrt(3 J2(s-)) + alpha I1(s-)) / (1 - alpha), tensile measure "
  "the largest principal s; uniaxial envelopes in compression (linear, "
  "CEB-FIP hardening to f_c at eps_c, exponential softening with G_c / l) "
  "and tension (linear to f_t, exponential softening with G_f / l), each "
  "split into plastic strain b (e - sigma / E0) and damage; on loading the "
  "plastic strain grows along C0^-1 : s-+ so that the state lands on the "
  "envelope (exact in uniaxial stress, no local iterations); stress = (1 - "
  "d_t) s+ + (1 - d_c) s-, so cracks close with the compressive stiffness "
  "and unloading follows (1 - d_c) E0 to the plastic strain. l is the cube "
  "root of the element volume (crack band). The positive part of a "
  "principal stress is blended smoothly (C1) over its first 0.1 % of f_t "
  "so that Newton converges where a principal stress is zero. Tangent: "
  "central differences of the stress update (consistent to O(h^2)); "
  "elastic points use C0. Options: `Tension-compression interaction' "
  "(failure on the linear envelope sigma_t / f_t + sigma_c / f_c = 1 under "
  "compression with lateral tension), `Confinement coefficient' (Lubliner's "
  "triaxial term), `Compressive softening' = false (perfectly plastic in "
  "compression).")
