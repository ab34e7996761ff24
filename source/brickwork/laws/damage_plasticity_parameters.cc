/**
 * @file
 * Brick material `damage plasticity': its entries, their parsing, its
 * state variables and derived values (the law itself:
 * damage_plasticity.cc and damage_plasticity_measures.cc; the class:
 * include/masonry/brickwork/laws/damage_plasticity.h).
 */
#include <masonry/brickwork/laws/damage_plasticity.h>
#include <masonry/core/parameters.h>
#include <masonry/core/plugins.h>

#include <sstream>
#include <string>

namespace masonry
{
  namespace brickwork
  {
    namespace
    {
      /** Declare the elastic constants E0 (Pa) and nu. */
      void
      declare_elastic_entries(dealii::ParameterHandler       &prm,
                              const DamagePlasticityDefaults &defaults)
      {
        using dealii::Patterns::Double;
        // up to 1e15 Pa: practically rigid bricks (used by the checks)
        declare_ranged_entry(prm,
                             "Young's modulus",
                             defaults.E,
                             {0, 1e15, "Pa"},
                             std::string("Initial Young's modulus E0 of the ") +
                               defaults.what + ", Pa (> 0).");
        prm.declare_entry("Poisson's ratio",
                          defaults.nu,
                          Double(-1, 0.5),
                          "Poisson's ratio (dimensionless, -1 < nu < 0.5).");
      }

      /** Declare the compressive envelope: its strength (Pa; uniaxial or
       * normalised), elastic limit, strain at the peak, crushing energy (J/m^2)
       * and plastic share. */
      void
      declare_compression_entries(dealii::ParameterHandler       &prm,
                                  const DamagePlasticityDefaults &defaults)
      {
        using dealii::Patterns::Double;
        declare_ranged_entry(
          prm,
          "Compressive strength",
          defaults.f_c,
          {0, 1e9, "Pa"},
          "Compressive strength, Pa (> 0): with `Compressive strength "
          "definition' = uniaxial (the default) the uniaxial strength f_c of "
          "the material, the peak of the compressive envelope; with "
          "`normalised' the normalised compressive strength f_b of a unit "
          "(EN 772-1: the mean strength of the tested units times the shape "
          "factor, referred to a 100 mm cube-equivalent; the f_b of "
          "Eurocode 6), from which the law's uniaxial strength is derived.");
        prm.declare_entry(
          "Compressive strength definition",
          "uniaxial",
          dealii::Patterns::Selection("uniaxial|normalised"),
          "What `Compressive strength' is: `uniaxial' (the strength f_c of "
          "the material in uniaxial compression) or `normalised' (the "
          "normalised unit strength f_b of EN 772-1, what a laboratory "
          "reports for a masonry unit: the strength of a 100 mm "
          "cube-equivalent between steel platens, whose restraint raises "
          "it above the uniaxial strength; this law does not add that "
          "restraint, so f_c = `Uniaxial to normalised strength ratio' x "
          "f_b, printed as the derived value "
          "`uniaxial_compressive_strength').");
        prm.declare_entry(
          "Uniaxial to normalised strength ratio",
          "0.8",
          Double(0, 1),
          "f_c / f_b with `Compressive strength definition' = normalised "
          "(dimensionless, 0 < ratio <= 1). 0.8: the ratio of cylinder to "
          "cube strength of concrete (EN 1992-1-1 strength classes, e.g. "
          "C20/25, C40/50), taken for fired-clay units for want of a "
          "clay-unit value (assumed; see doc/references-brickwork-"
          "strength.md).");
        prm.declare_entry(
          "Elastic limit ratio",
          "0.4",
          Double(0, 1),
          "Stress at the end of the linear part of the compressive "
          "envelope over f_c (dimensionless, 0 < ratio < 1).");
        declare_ranged_entry(
          prm,
          "Strain at peak",
          defaults.eps_c,
          {0, 1, "(dimensionless)"},
          "Total strain eps_c at the compressive peak (dimensionless, at "
          "least f_c / E0). Between the elastic limit e0 = ratio f_c / E0 "
          "and eps_c the envelope is sigma = f_c0 + (f_c - f_c0) (k x - "
          "x^2) / (1 + (k - 2) x), x = (e - e0) / (eps_c - e0), k = E0 "
          "(eps_c - e0) / (f_c - f_c0): slope E0 at e0, zero at the peak "
          "(the CEB-FIP/Sargin shape).");
        declare_ranged_entry(
          prm,
          "Compressive fracture energy",
          "20000",
          {0, 1e7, "N/m"},
          "Crushing energy G_c, J/m^2 (> 0): after the peak sigma = f_c "
          "exp(-(e - eps_c) / w_c) with w_c = G_c / (f_c l), so that the "
          "area under the softening branch times the element's "
          "characteristic length l (the cube root of its volume; a mortar "
          "cell of the detailed model: its size across the layer) is G_c.");
        prm.declare_entry(
          "Plastic strain ratio",
          "0.7",
          Double(0, 1),
          "Share b_c of the inelastic strain e - sigma / E0 that is plastic "
          "on the compressive envelope (dimensionless, 0 <= b_c < 1): "
          "e_p = b_c (e - sigma / E0); the rest is damage, d_c = 1 - sigma "
          "/ (E0 (e - e_p)), so unloading follows (1 - d_c) E0 to e_p.");
      }

      /** Declare the tensile envelope: its strength (Pa), fracture energy
       * (J/m^2) and plastic share. */
      void
      declare_tension_entries(dealii::ParameterHandler       &prm,
                              const DamagePlasticityDefaults &defaults)
      {
        using dealii::Patterns::Double;
        declare_ranged_entry(prm,
                             "Tensile strength",
                             defaults.f_t,
                             {0, 1e9, "Pa"},
                             "Uniaxial tensile strength f_t, Pa (> 0); linear "
                             "up to it.");
        declare_ranged_entry(
          prm,
          "Tensile fracture energy",
          defaults.G_f,
          {0, 1e6, "N/m"},
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
      }

      /** Declare the shape of the failure surface in multiaxial compression
       * (biaxial ratio, confinement), the cap and viscous regularisation (s) of
       * the damages and whether the compressive envelope softens. */
      void
      declare_surface_and_damage_entries(
        dealii::ParameterHandler       &prm,
        const DamagePlasticityDefaults &defaults)
      {
        using dealii::Patterns::Bool;
        using dealii::Patterns::Double;
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
        declare_ranged_entry(
          prm,
          "Viscosity",
          "0",
          {0, 1e6, "s"},
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
        declare_ranged_entry(
          prm,
          "Confinement coefficient",
          "0",
          {0, 100, "(dimensionless)"},
          "k in |sigma_1| = f_c + k p, the rise of the compressive strength "
          "with an equal lateral pressure p (triaxial compression, "
          "dimensionless). 0: the value of the cone alone, k0 = (1 + 2 "
          "alpha) / (1 - alpha) (1.414 for rho = 1.16); a value k >= k0 adds "
          "Lubliner's term -gamma <-s_max> of the largest principal effective "
          "stress when all three are compressive, gamma = k (1 - alpha) - (1 "
          "+ 2 alpha). Richart et al. (1928) measured k of about 4.1 for "
          "concrete (recalled, not checked against the paper).");
      }

      /** Declare the directions of the plastic flow in compression and tension
       * and how the cracks' opening enters an IMPL-EX step. */
      void
      declare_flow_entries(dealii::ParameterHandler       &prm,
                           const DamagePlasticityDefaults &defaults)
      {
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
          "Tensile plastic flow",
          "elastic",
          dealii::Patterns::Selection("elastic|crack"),
          "Direction of the tensile plastic strain (the part of a crack's "
          "opening that is plastic: `Tensile plastic strain ratio', and all "
          "of it once the damage is at `Maximum damage'): `elastic' along "
          "C0^-1 : s+, as the elastic strain, so that a crack opening eps "
          "carries a lateral contraction -nu eps in the other two "
          "directions, which relieves a compression parallel to the crack "
          "by about E0 nu eps; `crack' along n n, n the direction of the "
          "largest principal effective stress (Rankine's associated flow, "
          "no lateral part: the strain of a smeared crack normal to n, an "
          "opening w over the band l is w / l n n), the envelope strain "
          "from a scalar root search. Both give the input curve in "
          "uniaxial stress.");
        prm.declare_entry(
          "IMPL-EX crack opening",
          "frozen",
          dealii::Patterns::Selection("extrapolated|frozen"),
          "With `Damage integration = implex': how the tensile plastic strain "
          "(the cracks' opening) enters a step. `frozen': kept at its last "
          "converged value within the step (6 more state values per point); "
          "the compressive flow is still extrapolated. `extrapolated': like "
          "all of the plastic strain, extrapolated from the last two steps "
          "(before 2026-11-28 the only choice). Once a crack is at `Maximum "
          "damage' its opening is set by the neighbours, and its "
          "extrapolation acts as an imposed strain that the next update "
          "takes up as opening again: a loop that grows by 8-31 % a step "
          "whatever the step length and ended the double cyclic example in "
          "a spurious collapse (doc/notes/implex-step-control.md).");
      }

      /** Declare the couplings of tension and compression at a point
       * (interaction, compression softening of cracked material) and the
       * nonlocal average of the units' measures (radius, m). */
      void
      declare_coupling_entries(dealii::ParameterHandler       &prm,
                               const DamagePlasticityDefaults &defaults)
      {
        using dealii::Patterns::Bool;
        using dealii::Patterns::Double;
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
        prm.declare_entry(
          "Nonlocal length",
          "0",
          Double(0),
          "Radius R (m, >= 0; 0: local) of the nonlocal average of a "
          "unit's equivalent stresses tau_t (the largest principal effective "
          "stress) and tau_c (the compressive measure): in the implicit "
          "update after each IMPL-EX step the trial tau_t and tau_c of every "
          "unit point where they are positive are scaled by rho = average / "
          "max(local, 1e-3 x the strength), the average taken over the "
          "points of the same unit within R, weighted by the bell function "
          "(1 - r^2 / R^2)^2 and the points' volumes (Bazant & Jirasek "
          "2002), and the law's returns and the interaction's utilisations "
          "use the scaled measures. A "
          "material length for the units' failure under the mortar's "
          "lateral push, which a pointwise criterion sees growing as the "
          "mesh resolves it. Needs `Damage integration = implex'; units "
          "only (the mortar's must be 0). No measured value: the single-leaf "
          "example's peak is within 3 % of finer meshes with 0.1 m, not with "
          "0.03 or 0.06 m (doc/notes/wallette-mesh-dependence.md).");
        prm.declare_entry(
          "Cracked compression softening",
          defaults.cracked,
          Double(0),
          "Coefficient c of the compression softening of cracked material "
          "(dimensionless, >= 0; 0: none): the compressive strength of a "
          "point is beta f_c with beta = min(1, 1 / (0.8 + c eps_1)), eps_1 "
          "the largest equivalent tensile strain it has reached (its tensile "
          "envelope strain, in uniaxial tension the strain itself; taken at "
          "the start of each step). c = 170 is the relation of Vecchio & "
          "Collins (1986, modified compression field theory) for cracked "
          "concrete, where eps_1 is the mean principal tensile strain across "
          "several cracks; here it is the strain of the cracked cell (crack "
          "band: opening / cell size), and applying it to fired-clay units "
          "is an assumption. The compressive measure is divided by beta, so "
          "the whole compressive envelope (elastic limit, peak, softening) "
          "is scaled by beta in stress; a crack that opens further while the "
          "point is compressed moves it along its envelope (plastic strain "
          "and compressive damage grow). beta < 1 once eps_1 > 0.2 / c "
          "(0.00118 for c = 170); 0.61 at 0.005, 0.24 at 0.02.");
        prm.declare_entry(
          "Cracked compression residual ratio",
          "0",
          Double(0, 1),
          "Lower bound beta_r of the factor beta of `Cracked compression "
          "softening' (dimensionless, 0 to 1; 0: none, beta falls towards 0 "
          "as the crack opens): beta = max(beta_r, min(1, 1 / (0.8 + c "
          "eps_1))), so a cracked point keeps at least beta_r f_c in "
          "compression parallel to its crack (the strut between cracks; "
          "design codes reduce a cracked strut's strength by a constant "
          "factor of about 0.5-0.6, recalled). Without it a cell whose "
          "crack keeps opening loses its whole compressive strength, and a "
          "column of cells in series with it unloads at once.");
      }
    } // namespace

    void
    DamagePlasticityBrick::declare(dealii::ParameterHandler       &prm,
                                   const DamagePlasticityDefaults &defaults)
    {
      declare_elastic_entries(prm, defaults);
      declare_compression_entries(prm, defaults);
      declare_tension_entries(prm, defaults);
      declare_surface_and_damage_entries(prm, defaults);
      declare_flow_entries(prm, defaults);
      declare_coupling_entries(prm, defaults);
    }

    void
    DamagePlasticityBrick::parse_parameters(dealii::ParameterHandler &prm)
    {
      section      = plugins::current_parse_path();
      E            = prm.get_double("Young's modulus");
      nu           = prm.get_double("Poisson's ratio");
      f_c          = prm.get_double("Compressive strength");
      f_normalised = 0;
      if (prm.get("Compressive strength definition") == "normalised")
        {
          const double r =
            prm.get_double("Uniaxial to normalised strength ratio");
          AssertThrow(r > 0,
                      ExcParameter("Uniaxial to normalised strength ratio",
                                   "must be positive"));
          f_normalised = f_c;
          f_c          = r * f_normalised;
        }
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
      c_cracked     = prm.get_double("Cracked compression softening");
      beta_residual = prm.get_double("Cracked compression residual ratio");
      crack_flow    = prm.get("Tensile plastic flow") == "crack";
      freeze_crack_opening = prm.get("IMPL-EX crack opening") == "frozen";

      nonlocal_radius = prm.get_double("Nonlocal length");
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
            AssertThrow(end == flow.size() && end > 0 && nu_p > -1 && nu_p < 1,
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

    std::vector<StateVariable>
    DamagePlasticityBrick::state_variables() const
    {
      // the order of pack() and unpack()
      std::vector<StateVariable> v = {{"plastic_strain", 6},
                                      {"threshold_tension", 1},
                                      {"threshold_compression", 1},
                                      {"kappa_tension", 1},
                                      {"kappa_compression", 1},
                                      {"damage_tension", 1},
                                      {"damage_compression", 1}};
      if (freeze_crack_opening)
        v.push_back({"crack_strain", 6});
      return v;
    }

    std::vector<DerivedValue>
    DamagePlasticityBrick::derived_values() const
    {
      std::vector<DerivedValue> values;
      if (f_normalised > 0)
        {
          values.push_back({"normalised_compressive_strength",
                            f_normalised,
                            "Pa",
                            "f_b, the input `Compressive strength' "
                            "(`Compressive strength definition' = "
                            "normalised, EN 772-1)"});
          values.push_back({"uniaxial_compressive_strength",
                            f_c,
                            "Pa",
                            "f_c = `Uniaxial to normalised strength ratio' "
                            "x f_b: the peak of the law's compressive "
                            "envelope"});
        }
      std::vector<DerivedValue> rest = {
        {"alpha",
         alpha,
         "-",
         "(rho - 1) / (2 rho - 1) of the compressive measure "
         "(Lubliner), rho = `Biaxial to uniaxial strength ratio'"},
        {"elastic_limit_stress",
         ratio * f_c,
         "Pa",
         "`Elastic limit ratio' x the uniaxial compressive strength f_c"},
        {"confinement_coefficient",
         (1 + 2 * alpha + gamma) / (1 - alpha),
         "-",
         "k = (1 + 2 alpha + gamma) / (1 - alpha): the rise of the "
         "compressive measure's strength per unit of equal lateral "
         "pressure, |sigma_1| = f_c + k p (gamma = 0 unless "
         "`Confinement coefficient' is set)"}};
      values.insert(values.end(), rest.begin(), rest.end());
      return values;
    }

    void
    DamagePlasticityBrick::check_point(const BrickPoint &point) const
    {
      const double ft    = point.strength_factor * f_t;
      const double l_max = 2 * G_f * E / (ft * ft);
      if (point.characteristic_length >= l_max)
        {
          std::ostringstream m;
          m << "is too small for elements of " << point.characteristic_length
            << " m: the tension softening needs l < 2 G_f E0 / f_t^2 = "
            << l_max << " m (refine the mesh or raise the energy)";
          // (checked while running, outside any parse path: the full path
          // tells the brick's entry from the mortar's)
          AssertThrow(false,
                      ExcParameter((section.empty() ? "" : section + "/") +
                                     "Tensile fracture energy",
                                   m.str()));
        }
    }

  } // namespace brickwork
} // namespace masonry
