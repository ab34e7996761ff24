/**
 * @file
 * Interface law `bilinear': the mixed-mode cohesive law of Camanho and
 * Davila.
 */
#include <masonry/brickwork/interface_law.h>
#include <masonry/core/parameters.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace masonry
{
  namespace brickwork
  {
    /**
     * Bilinear mixed-mode cohesive law (Camanho & Davila 2002, with
     * separate normal and shear penalties): quadratic onset, linear
     * softening in the mixed-mode opening, Benzeggagh-Kenane energy.
     */
    class BilinearInterface : public InterfaceLaw
    {
    public:
      /**
       * The state: the damage acting on the tractions (after the viscous
       * regularisation) and the damage of the law without viscosity (the
       * envelope reached).
       */
      enum StateIndex : unsigned int
      {
        damage_index          = 0,
        damage_inviscid_index = 1
      };

      std::vector<StateVariable>
      state_variables() const override
      {
        return {{"damage", 1}, {"damage_inviscid", 1}};
      }

      std::vector<std::string>
      reported_quantities() const override
      {
        return {"damage"};
      }

      void
      report(ConstStateView            state,
             dealii::ArrayView<double> values) const override
      {
        values[0] = state[damage_index];
      }

      std::vector<std::string>
      damage_names() const override
      {
        return {"damage"};
      }

      void
      damages(ConstStateView            state,
              dealii::ArrayView<double> values) const override
      {
        values[0] = state[damage_index];
      }

      static void
      declare_parameters(dealii::ParameterHandler &prm)
      {
        declare_ranged_entry(prm,
                             "Tensile strength",
                             "0.2e6",
                             {0, 1e9, "Pa"},
                             "Tensile strength f_t of the joint, Pa (> 0); "
                             "typical 0.16-0.25 MPa.");
        declare_ranged_entry(prm,
                             "Cohesion",
                             "0.28e6",
                             {0, 1e9, "Pa"},
                             "Shear strength (cohesion) c of the joint, Pa "
                             "(> 0); typical 1.4 f_t.");
        declare_ranged_entry(prm,
                             "Mode I fracture energy",
                             "15",
                             {0, 1e6, "N/m"},
                             "Fracture energy G_I in pure opening, J/m^2 = "
                             "N/m (> 0, at least f_t^2 / (2 k_n)); typical "
                             "12-18 N/m.");
        declare_ranged_entry(prm,
                             "Mode II fracture energy",
                             "100",
                             {0, 1e6, "N/m"},
                             "Fracture energy G_II in pure shear, J/m^2 = N/m "
                             "(> 0, at least c^2 / (2 k_s)); typical 50-125 "
                             "N/m.");
        declare_ranged_entry(prm,
                             "BK exponent",
                             "2",
                             {0, 10, "(dimensionless)"},
                             "Exponent eta of the Benzeggagh-Kenane mixed-mode "
                             "criterion G_c = G_I + (G_II - G_I) (beta^2 / (1 "
                             "+ beta^2))^eta, beta = slip / normal opening "
                             "(dimensionless, > 0).");
        prm.declare_entry(
          "Maximum damage",
          "1",
          dealii::Patterns::Double(0, 1),
          "Cap of the damage that degrades the opening and shear "
          "stiffnesses (dimensionless, 0 < value <= 1): a fully debonded "
          "joint keeps (1 - this) of its penalties. This law has no "
          "friction, so with 1 a brick held only by debonded joints can "
          "slide freely and the tangent is singular; a cap such as 0.9999 "
          "keeps it regular (residual traction 1e-4 k delta). The damage "
          "itself (output, energy) is not capped.");
      }

      void
      parse_parameters(dealii::ParameterHandler &prm) override
      {
        d_max = prm.get_double("Maximum damage");
        AssertThrow(d_max > 0 && d_max <= 1,
                    ExcParameter("Maximum damage", "must be in (0, 1]"));
        f_t           = prm.get_double("Tensile strength");
        c             = prm.get_double("Cohesion");
        G_I           = prm.get_double("Mode I fracture energy");
        G_II          = prm.get_double("Mode II fracture energy");
        eta           = prm.get_double("BK exponent");
        auto positive = [&](const double v, const std::string &entry) {
          AssertThrow(v > 0, ExcParameter(entry, "must be positive"));
        };
        positive(f_t, "Tensile strength");
        positive(c, "Cohesion");
        positive(G_I, "Mode I fracture energy");
        positive(G_II, "Mode II fracture energy");
        positive(eta, "BK exponent");
        // the common stiffnesses are parsed before this subsection
        const double       min_I  = f_t * f_t / (2 * normal_stiffness);
        const double       min_II = c * c / (2 * shear_stiffness);
        std::ostringstream m;
        m << "must be at least f_t^2 / (2 k_n) = " << min_I
          << " J/m^2 (else the law snaps back at a point)";
        AssertThrow(G_I > min_I,
                    ExcParameter("Mode I fracture energy", m.str()));
        std::ostringstream m2;
        m2 << "must be at least c^2 / (2 k_s) = " << min_II << " J/m^2";
        AssertThrow(G_II > min_II,
                    ExcParameter("Mode II fracture energy", m2.str()));
      }

      /**
       * Damage from the opening alone (no history), with the strengths
       * multiplied by @p factor.
       */
      double
      damage(const Local3 &jump, const double factor) const
      {
        const double f_t = factor * this->f_t, c = factor * this->c;
        const double kn = normal_stiffness, ks = shear_stiffness;
        const double dn  = jump[0];
        const double ds  = std::sqrt(jump[1] * jump[1] + jump[2] * jump[2]);
        const double dnp = std::max(dn, 0.);
        const double dm  = std::sqrt(dnp * dnp + ds * ds);
        if (dm == 0)
          return 0;
        const double dn0 = f_t / kn, ds0 = c / ks;
        double       d0, k_eff, mix;
        if (dn > 0)
          {
            const double b2 = (ds / dn) * (ds / dn);
            d0 = dn0 * ds0 * std::sqrt((1 + b2) / (ds0 * ds0 + b2 * dn0 * dn0));
            k_eff = (kn + b2 * ks) / (1 + b2);
            mix   = b2 / (1 + b2);
          }
        else
          {
            d0    = ds0;
            k_eff = ks;
            mix   = 1;
          }
        const double G_c = G_I + (G_II - G_I) * std::pow(mix, eta);
        const double df  = std::max(2 * G_c / (k_eff * d0), d0 * (1 + 1e-9));
        if (dm <= d0)
          return 0;
        if (dm >= df)
          return 1;
        return df * (dm - d0) / (dm * (df - d0));
      }

      void
      evaluate(const Local3         &jump,
               ConstStateView        old_state,
               const InterfacePoint &point,
               StateView             updated_state,
               Local3               &t,
               Local33              &tangent) const override
      {
        const double old_damage          = old_state[damage_index];
        const double old_damage_inviscid = old_state[damage_inviscid_index];
        const double k[3]                = {normal_stiffness,
                                            shear_stiffness,
                                            shear_stiffness};
        const double phi                 = point.strength_factor;
        const double trial               = damage(jump, phi);
        const bool   loading             = trial > old_damage_inviscid;
        const double inviscid            = std::max(old_damage_inviscid, trial);
        updated_state[damage_inviscid_index] = inviscid;
        // viscous regularisation: d_v = (d + a d_v,old) / (1 + a)
        const double a              = viscosity > 0 && point.time_step > 0 ?
                                        viscosity / point.time_step :
                                        0.;
        const double d              = (inviscid + a * old_damage) / (1 + a);
        updated_state[damage_index] = d;
        // no damage of the normal stiffness in compression
        const double dc   = std::min(d, d_max);
        const double f[3] = {jump[0] > 0 ? 1 - dc : 1., 1 - dc, 1 - dc};
        for (unsigned int i = 0; i < 3; ++i)
          {
            t[i] = f[i] * k[i] * jump[i];
            for (unsigned int j = 0; j < 3; ++j)
              tangent[i][j] = (i == j ? f[i] * k[i] : 0);
          }
        if (loading && trial < 1 && d < d_max)
          {
            // loading: derivative of the damage by central differences
            // of the closed-form damage function
            const double scale = std::max({std::abs(jump[0]),
                                           std::abs(jump[1]),
                                           std::abs(jump[2]),
                                           f_t / normal_stiffness});
            const double h     = 1e-7 * scale;
            Local3       dd;
            for (unsigned int j = 0; j < 3; ++j)
              {
                Local3 p = jump, m = jump;
                p[j] += h;
                m[j] -= h;
                dd[j] = (damage(p, phi) - damage(m, phi)) / (2 * h) / (1 + a);
              }
            for (unsigned int i = 0; i < 3; ++i)
              if (i > 0 || jump[0] > 0)
                for (unsigned int j = 0; j < 3; ++j)
                  tangent[i][j] -= k[i] * jump[i] * dd[j];
          }
      }

      bool
      is_elastic(const Local3         &jump,
                 ConstStateView        old,
                 const InterfacePoint &point) const override
      {
        // intact and below the damage onset: evaluate() keeps d = 0 (also
        // with viscosity) and the extrapolated damage of intact states is 0
        return old[damage_index] == 0 && old[damage_inviscid_index] == 0 &&
               damage(jump, point.strength_factor) == 0;
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
        // the damage extrapolated in pseudo-time, frozen within the step:
        // the joint is linear but for the contact switch of the normal
        const double d_old = old[damage_index], d_older = older[damage_index];
        const double d =
          std::min(std::clamp(d_old + ratio * (d_old - d_older), d_old, 1.),
                   d_max);
        const double k[3] = {normal_stiffness,
                             shear_stiffness,
                             shear_stiffness};
        const double f[3] = {jump[0] > 0 ? 1 - d : 1., 1 - d, 1 - d};
        for (unsigned int i = 0; i < 3; ++i)
          {
            t[i] = f[i] * k[i] * jump[i];
            for (unsigned int j = 0; j < 3; ++j)
              tangent[i][j] = (i == j ? f[i] * k[i] : 0);
          }
      }

    private:
      double f_t = 0, c = 0, G_I = 0, G_II = 0, eta = 2, d_max = 1;
    };
  } // namespace brickwork
} // namespace masonry

MASONRY_REGISTER_INTERFACE_LAW(
  masonry::brickwork::BilinearInterface,
  "bilinear",
  "Bilinear mixed-mode cohesive law (Camanho-Davila): linear up to the "
  "quadratic onset (t_n/f_t)^2 + (t_s/c)^2 = 1 (t_n > 0), then linear "
  "softening of the mixed-mode opening d_m = sqrt(<d_n>^2 + d_s^2) to zero "
  "traction at the opening that dissipates the Benzeggagh-Kenane energy "
  "G_c. Damage never decreases; the normal stiffness is not damaged in "
  "compression (closing joints stay stiff). In pure mode I the dissipated "
  "energy per unit area is G_I, in pure mode II G_II.")
