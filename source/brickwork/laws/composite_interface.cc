/**
 * @file
 * Interface law `composite`: the Lourenço & Rots (1997) composite joint
 * (brickwork::laws::CompositeJoint) as a plugin of the wallette model.
 */
#include <masonry/brickwork/brick_material.h>
#include <masonry/brickwork/interface_law.h>
#include <masonry/brickwork/laws/composite_joint.h>
#include <masonry/core/parameters.h>
#include <masonry/core/plugins.h>

#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "splitting.h"

namespace masonry
{
  namespace brickwork
  {
    namespace
    {
      using laws::CompositeJoint;
      using laws::CompositeJointState;

      /** State layout: plastic jump (3), crack opening, xi, kappa_3. */
      constexpr unsigned int n_state = 6;

      CompositeJointState
      unpack(ConstStateView s)
      {
        CompositeJointState c;
        for (unsigned int i = 0; i < 3; ++i)
          c.plastic_jump[i] = s[i];
        c.crack_opening = s[3];
        c.xi            = s[4];
        c.kappa_cap     = s[5];
        return c;
      }

      void
      pack(const CompositeJointState &c, StateView s)
      {
        for (unsigned int i = 0; i < 3; ++i)
          s[i] = c.plastic_jump[i];
        s[3] = c.crack_opening;
        s[4] = c.xi;
        s[5] = c.kappa_cap;
      }
    } // namespace

    /**
     * Lourenço & Rots composite interface: tension cut-off, Coulomb
     * friction and an elliptical compression cap with their softening and
     * hardening; multi-surface plasticity with its own state. See
     * laws/composite_joint.h and doc/references-brickwork-strength.md.
     */
    class CompositeInterface : public InterfaceLaw
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        using dealii::Patterns::Bool;
        using dealii::Patterns::Double;
        prm.declare_entry("Tensile strength",
                          "0.25e6",
                          Double(0),
                          "Tensile (bond) strength f_t0 of the joint, Pa "
                          "(> 0, at most Cohesion / Friction).");
        prm.declare_entry("Mode I fracture energy",
                          "18",
                          Double(0),
                          "G_I, J/m^2 = N/m (> f_t0^2 / k_n): the energy of "
                          "the exponential tension softening.");
        prm.declare_entry("Cohesion",
                          "0.35e6",
                          Double(0),
                          "Cohesion c0 of the Coulomb friction surface, Pa "
                          "(> 0).");
        prm.declare_entry("Friction",
                          "0.75",
                          Double(0),
                          "Initial friction coefficient tan(phi_0) "
                          "(dimensionless, >= 0).");
        prm.declare_entry("Residual friction",
                          "0.75",
                          Double(0),
                          "Friction coefficient tan(phi_r) once the "
                          "cohesion is gone (dimensionless, >= 0).");
        prm.declare_entry("Dilatancy",
                          "0",
                          Double(0),
                          "Dilatancy coefficient tan(psi) of the shear flow "
                          "(dimensionless, >= 0; constant).");
        prm.declare_entry("Mode II fracture energy",
                          "125",
                          Double(0),
                          "G_II, J/m^2 = N/m (> c0^2 / k_s): the energy of "
                          "the cohesion softening at zero normal stress.");
        prm.declare_entry(
          "Cap strength",
          "10.5e6",
          Double(0),
          "Peak sbar_p of the elliptical compression cap, "
          "Pa (>= Tensile strength): the compressive strength of the joint "
          "with C_nn = 1, C_n = 0.");
        prm.declare_entry("Cap Cnn",
                          "1",
                          Double(0),
                          "Cap coefficient C_nn of sigma^2 (dimensionless, "
                          "> 0).");
        prm.declare_entry("Cap Css",
                          "9",
                          Double(0),
                          "Cap coefficient C_ss of tau^2 (dimensionless, "
                          "> 0): the shear contribution to crushing.");
        prm.declare_entry("Cap Cn",
                          "0",
                          Double(),
                          "Cap coefficient C_n of sigma, Pa (centre of the "
                          "ellipse at sigma = -C_n / (2 C_nn)).");
        prm.declare_entry("Cap peak jump",
                          "0.09e-3",
                          Double(0),
                          "Equivalent plastic jump kappa_p at the cap's "
                          "peak, m (> 0).");
        prm.declare_entry(
          "Compressive fracture energy",
          "5000",
          Double(0),
          "G_fc, J/m^2 = N/m: the energy the cap dissipates after its peak "
          "above its residual sbar_p / 7; fixes kappa_m.");
        prm.declare_entry("Crack closure",
                          "true",
                          Bool(),
                          "Whether an open tensile crack closes without "
                          "traction before contact builds up compression.");
        prm.declare_entry(
          "Mortar Young's modulus",
          "0",
          Double(0),
          "E_m of the mortar, Pa; > 0: the penalties k_n = E_b E_m / (h_m "
          "(E_b - E_m)) and k_s (same with G = E / (2 (1 + nu))) replace "
          "`Normal stiffness' and `Shear stiffness' (Lourenco-Rots, enlarged "
          "units); 0: the given stiffnesses are used.");
        prm.declare_entry("Mortar Poisson's ratio",
                          "0.2",
                          Double(-1, 0.5),
                          "nu_m of the mortar (dimensionless).");
        prm.declare_entry("Unit Young's modulus",
                          "10e9",
                          Double(0),
                          "E_b of the units, Pa (> E_m) for the penalties.");
        prm.declare_entry("Unit Poisson's ratio",
                          "0.15",
                          Double(-1, 0.5),
                          "nu_b of the units (dimensionless).");
        prm.declare_entry("Joint thickness",
                          "0.010",
                          Double(0),
                          "Thickness h_m of the mortar joint, m, for the "
                          "penalties.");
      }

      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        p.tensile_strength  = prm.get_double("Tensile strength");
        p.mode_I_energy     = prm.get_double("Mode I fracture energy");
        p.cohesion          = prm.get_double("Cohesion");
        p.friction          = prm.get_double("Friction");
        p.residual_friction = prm.get_double("Residual friction");
        p.dilatancy         = prm.get_double("Dilatancy");
        p.mode_II_energy    = prm.get_double("Mode II fracture energy");
        p.cap_strength      = prm.get_double("Cap strength");
        p.cap_Cnn           = prm.get_double("Cap Cnn");
        p.cap_Css           = prm.get_double("Cap Css");
        p.cap_Cn            = prm.get_double("Cap Cn");
        p.cap_peak_jump     = prm.get_double("Cap peak jump");
        p.cap_energy        = prm.get_double("Compressive fracture energy");
        p.crack_closure     = prm.get_bool("Crack closure");
        const double E_m    = prm.get_double("Mortar Young's modulus");
        if (E_m > 0)
          {
            try
              {
                const auto k = CompositeJoint::penalties(
                  prm.get_double("Unit Young's modulus"),
                  prm.get_double("Unit Poisson's ratio"),
                  E_m,
                  prm.get_double("Mortar Poisson's ratio"),
                  prm.get_double("Joint thickness"));
                normal_stiffness = k[0];
                shear_stiffness  = k[1];
              }
            catch (const std::invalid_argument &e)
              {
                AssertThrow(false,
                            ExcParameter("Mortar Young's modulus", e.what()));
              }
          }
        penalties_derived  = E_m > 0;
        p.normal_stiffness = normal_stiffness;
        p.shear_stiffness  = shear_stiffness;
        law                = std::make_unique<CompositeJoint>(make(1.));
        // the strength scatter multiplies the strengths by up to 1.8: the
        // snap-back limits must hold there too (checked here, not in the
        // middle of an assembly)
        make(1.8);
      }

      /**
       * Set the law from @p q directly (not from a parameter file): the
       * splitting interfaces; @p derived are its derived values and
       * @p entries name, for each parameter of CompositeJoint ("Tensile
       * strength", "Cohesion", ...), the full path of the entry (or
       * entries) it was given by or derived from, for errors.
       */
      void
      configure(const CompositeJoint::Parameters         &q,
                const std::vector<DerivedValue>          &derived,
                const std::map<std::string, std::string> &entries)
      {
        p                = q;
        normal_stiffness = q.normal_stiffness;
        shear_stiffness  = q.shear_stiffness;
        given_derived    = derived;
        error_entries    = entries;
        law              = std::make_unique<CompositeJoint>(make(1.));
        make(1.8);
      }

      std::vector<DerivedValue>
      derived_values() const override
      {
        if (!error_entries.empty())
          return given_derived;
        std::vector<DerivedValue> v;
        if (penalties_derived)
          {
            v.push_back({"normal_stiffness",
                         normal_stiffness,
                         "Pa/m",
                         "k_n = E_b E_m / (h_m (E_b - E_m)) (Lourenco-Rots, "
                         "enlarged units)"});
            v.push_back({"shear_stiffness",
                         shear_stiffness,
                         "Pa/m",
                         "k_s = G_b G_m / (h_m (G_b - G_m)), G = E / (2 (1 + "
                         "nu))"});
          }
        const double sp = p.cap_strength;
        v.push_back({"cap_initial_strength",
                     p.cap_initial_ratio * sp,
                     "Pa",
                     "sbar_i = sbar_p / 3: start of the cap hardening"});
        v.push_back({"cap_middle_strength",
                     p.cap_middle_ratio * sp,
                     "Pa",
                     "sbar_m = sbar_p / 2: end of the parabolic softening"});
        v.push_back({"cap_residual_strength",
                     p.cap_residual_ratio * sp,
                     "Pa",
                     "sbar_r = sbar_p / 7: residual"});
        v.push_back({"cap_middle_jump",
                     law->cap_middle_jump(),
                     "m",
                     "kappa_m = kappa_p + G_fc / (sbar_p - sbar_r + (sbar_m "
                     "- sbar_p) / 3 + (sbar_m - sbar_r)^2 / (2 (sbar_p - "
                     "sbar_m)))"});
        return v;
      }

      std::vector<StateVariable>
      state_variables() const override
      {
        return {{"plastic_jump", 3},
                {"crack_opening", 1},
                {"softening", 1},
                {"kappa_cap", 1}};
      }

      std::vector<std::string>
      damage_names() const override
      {
        return {"bond_damage", "cap_state"};
      }

      /**
       * bond_damage = 1 - exp(-xi) (the fraction of f_t and c lost),
       * cap_state = kappa_3 / (kappa_3 + kappa_p) (0 intact, 1/2 at the
       * cap's peak).
       */
      void
      damages(ConstStateView            state,
              dealii::ArrayView<double> values) const override
      {
        values[0] = 1 - std::exp(-state[4]);
        values[1] = state[5] / (state[5] + p.cap_peak_jump);
      }

      void
      evaluate(const Local3         &jump,
               ConstStateView        old,
               const InterfacePoint &point,
               StateView             updated,
               Local3               &t,
               Local33              &tangent) const override
      {
        CompositeJointState s;
        if (point.strength_factor == 1.)
          law->evaluate(jump, unpack(old), s, t, tangent);
        else
          make(point.strength_factor)
            .evaluate(jump, unpack(old), s, t, tangent);
        pack(s, updated);
      }

      bool
      extrapolates() const override
      {
        return true;
      }

      void
      evaluate_extrapolated(const Local3  &jump,
                            ConstStateView old,
                            ConstStateView older,
                            const double   ratio,
                            const InterfacePoint &,
                            Local3  &t,
                            Local33 &tangent) const override
      {
        // A crack that opened in the last step is extrapolated to open
        // further (u_p,e > u_p), while the iterate starts from the old
        // jump: with the closure gap [u_p,e - w_e, u_p,e] the frozen
        // response would be flat (t = 0, no stiffness) there and then
        // stiff, a kink the Newton correction cannot see. Such a point is
        // frozen linear on both sides of u_p,e; a closing or resting crack
        // keeps its gap. The implicit update after the step is unchanged.
        const bool opening = old[3] > older[3];
        law->evaluate_frozen(jump,
                             law->extrapolate(unpack(old),
                                              unpack(older),
                                              ratio),
                             t,
                             tangent,
                             !opening);
      }

      bool
      is_elastic(const Local3         &jump,
                 ConstStateView        old,
                 const InterfacePoint &point) const override
      {
        for (unsigned int i = 0; i < n_state; ++i)
          if (old[i] != 0)
            return false;
        // inside all three initial surfaces (with the point's strengths)
        const double f     = point.strength_factor;
        const double sigma = normal_stiffness * jump[0];
        const double tau =
          shear_stiffness * std::sqrt(jump[1] * jump[1] + jump[2] * jump[2]);
        const double si = f * p.cap_strength * p.cap_initial_ratio;
        return sigma <= f * p.tensile_strength &&
               tau + sigma * p.friction <= f * p.cohesion &&
               p.cap_Cnn * sigma * sigma + p.cap_Css * tau * tau +
                   p.cap_Cn * sigma <=
                 si * si;
      }

    private:
      CompositeJoint
      make(const double factor) const
      {
        CompositeJoint::Parameters q = p;
        q.tensile_strength *= factor;
        q.cohesion *= factor;
        q.cap_strength *= factor;
        try
          {
            return CompositeJoint(q);
          }
        catch (const std::invalid_argument &e)
          {
            // the message names the parameter (composite joint: <name>
            // ...): an entry of this subsection of that name, or, for the
            // splitting interfaces, the entry it was given by or derived
            // from
            std::string m = e.what(), name;
            if (factor == 1.8)
              m += " (with the strengths times 1.8, the largest factor of "
                   "`Strength scatter')";
            else if (factor != 1.)
              m += " (with the strengths times " + std::to_string(factor) +
                   ", a point's factor of `Strength scatter')";
            for (const std::string candidate : {"Tensile strength",
                                                "Mode I fracture energy",
                                                "Cohesion",
                                                "Friction",
                                                "Residual friction",
                                                "Mode II fracture energy",
                                                "Cap strength",
                                                "Cap Cnn",
                                                "Cap Css",
                                                "Cap peak jump",
                                                "Compressive fracture energy",
                                                "Normal stiffness",
                                                "Shear stiffness"})
              if (name.empty() &&
                  m.rfind("composite joint: " + candidate, 0) == 0)
                name = candidate;
            if (error_entries.empty())
              AssertThrow(false,
                          ExcParameter(name.empty() ? "Composite" : name, m));
            const auto        named = error_entries.find(name);
            const std::string entry = named != error_entries.end() ?
                                        named->second :
                                        error_entries.begin()->second;
            // (a full path: not relative to the subsection being parsed)
            const plugins::ParsePathScope top_level("");
            AssertThrow(false,
                        ExcParameter(entry,
                                     "the splitting interfaces' law from it: " +
                                       m));
          }
        return CompositeJoint(p);
      }

      CompositeJoint::Parameters p;
      /** Whether k_n and k_s come from the moduli. */
      bool penalties_derived = false;
      /** configure(): the derived values and, for each parameter, the
       * entry named in its errors. */
      std::vector<DerivedValue>          given_derived;
      std::map<std::string, std::string> error_entries;
      std::unique_ptr<CompositeJoint>    law;
    };

    std::unique_ptr<InterfaceLaw>
    make_splitting_law(const SplittingSettings &s,
                       const BrickMaterial     &brick,
                       const std::string       &brick_section,
                       const double             unit_length)
    {
      std::vector<DerivedValue> derived;
      // the entry each value comes from: the Wallette's own, or the brick
      // material's it is derived from
      const auto from = [&](const double       given,
                            const std::string &wallette_entry,
                            const std::string &brick_entry) {
        return given > 0 ? "Wallette/" + wallette_entry :
                           brick_section + "/" + brick_entry;
      };
      const std::string tensile     = from(s.tensile_strength,
                                       "Splitting tensile strength",
                                       "Tensile strength"),
                        energy      = from(s.fracture_energy,
                                      "Splitting fracture energy",
                                      "Tensile fracture energy"),
                        compressive = from(s.compressive_strength,
                                           "Splitting compressive strength",
                                           "Compressive strength"),
                        stiffness   = from(s.stiffness,
                                         "Splitting stiffness",
                                         "Young's modulus");
      const std::map<std::string, std::string> entries = {
        {"Tensile strength", tensile},
        {"Mode I fracture energy", energy},
        {"Mode II fracture energy", energy},
        {"Cohesion", tensile},
        {"Friction", tensile},
        {"Residual friction", tensile},
        {"Cap strength", compressive},
        {"Compressive fracture energy", compressive},
        {"Normal stiffness", stiffness},
        {"Shear stiffness", stiffness}};
      // the brick material's strengths, if it has them
      const MaterialStrengths *strengths = strengths_of(brick);

      // a value given (> 0) or the brick material's strength `of' (printed
      // as derived; an error if the material has none)
      const auto value = [&](const double given,
                             double (MaterialStrengths::*of)() const,
                             const char        *entry,
                             const char        *name,
                             const char        *unit,
                             const std::string &how) {
        if (given > 0)
          return given;
        const double from_brick = strengths ? (strengths->*of)() : 0.;
        AssertThrow(from_brick > 0,
                    ExcParameter(entry,
                                 "must be given (> 0): the brick material "
                                 "has no such value"));
        derived.push_back({name, from_brick, unit, how});
        return from_brick;
      };
      const double f_t = value(s.tensile_strength,
                               &MaterialStrengths::tensile_strength,
                               "Splitting tensile strength",
                               "tensile_strength",
                               "Pa",
                               "the brick material's tensile strength");
      const double G_f = value(s.fracture_energy,
                               &MaterialStrengths::tensile_fracture_energy,
                               "Splitting fracture energy",
                               "mode_I_fracture_energy",
                               "J/m^2",
                               "the brick material's tensile fracture energy");
      const double f_c = value(s.compressive_strength,
                               &MaterialStrengths::compressive_strength,
                               "Splitting compressive strength",
                               "compressive_strength",
                               "Pa",
                               "the brick material's compressive strength");
      if (!(f_c > f_t))
        {
          // (full paths: not relative to the subsection being parsed)
          const plugins::ParsePathScope top_level("");
          AssertThrow(false,
                      ExcParameter(compressive,
                                   "the splitting interfaces' compressive "
                                   "strength must exceed their tensile "
                                   "strength (from `" +
                                     tensile + "')"));
        }
      const double E = brick.youngs_modulus(), nu = brick.poissons_ratio();
      CompositeJoint::Parameters q;
      q.tensile_strength = f_t;
      q.mode_I_energy    = G_f;
      // Mohr-Coulomb through the uniaxial strengths of the unit
      q.cohesion          = 0.5 * std::sqrt(f_c * f_t);
      q.friction          = (f_c - f_t) / (2 * std::sqrt(f_c * f_t));
      q.residual_friction = q.friction;
      q.dilatancy         = 0;
      q.mode_II_energy    = 10 * G_f;
      q.normal_stiffness =
        s.stiffness > 0 ? s.stiffness : 100 * E / unit_length;
      q.shear_stiffness = q.normal_stiffness / (2 * (1 + nu));
      // the cap out of reach: ten times the unit's strength, and a
      // softening that would take a metre of plastic jump
      q.cap_strength = 10 * f_c;
      {
        const double sp = q.cap_strength, sm = q.cap_middle_ratio * sp,
                     sr = q.cap_residual_ratio * sp;
        q.cap_energy =
          sp + (sm - sp) / 3. - sr + (sm - sr) * (sm - sr) / (2. * (sp - sm));
      }
      if (s.stiffness <= 0)
        derived.push_back(
          {"normal_stiffness",
           q.normal_stiffness,
           "Pa/m",
           "k_n = 100 E_b / L (L = " + std::to_string(unit_length) +
             " m, the enlarged unit's length: the interface "
             "adds 1 % to the unit's compliance)"});
      derived.push_back({"shear_stiffness",
                         q.shear_stiffness,
                         "Pa/m",
                         "k_s = k_n / (2 (1 + nu_b))"});
      derived.push_back({"cohesion",
                         q.cohesion,
                         "Pa",
                         "c = sqrt(f_c f_t) / 2 (Mohr-Coulomb through the "
                         "unit's uniaxial strengths)"});
      derived.push_back({"friction",
                         q.friction,
                         "-",
                         "tan(phi) = (f_c - f_t) / (2 sqrt(f_c f_t)) "
                         "(Mohr-Coulomb)"});
      derived.push_back({"mode_II_fracture_energy",
                         q.mode_II_energy,
                         "J/m^2",
                         "G_II = 10 G_f (assumed)"});
      derived.push_back({"cap_strength",
                         q.cap_strength,
                         "Pa",
                         "10 f_c: out of reach (the unit's crushing is the "
                         "brick material's)"});
      auto law = std::make_unique<CompositeInterface>();
      law->configure(q, derived, entries);
      return law;
    }
  } // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_INTERFACE_LAW(
  masonry::brickwork::CompositeInterface,
  "composite",
  "Lourenco & Rots (1997) composite interface: tension cut-off with "
  "exponential softening (G_I), Coulomb friction with cohesion softening "
  "(G_II) and friction from tan(phi_0) to tan(phi_r), elliptical "
  "compression cap with hardening and softening (G_fc); multi-surface "
  "plasticity with the plastic jump, the crack opening, the softening xi "
  "and kappa_3 as its state; implicit return with the algorithmic tangent, "
  "IMPL-EX with the extrapolated plastic jump.")
