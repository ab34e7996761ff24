/**
 * @file
 * Brick material `damage plasticity': the stress update, the IMPL-EX
 * stress and the tangents (the formulation: the documentation of
 * include/masonry/brickwork/laws/damage_plasticity.h; the stress measures,
 * the spectral split and the envelopes: damage_plasticity_measures.cc; the
 * entries: damage_plasticity_parameters.cc; the `mortar' plugin:
 * mortar.cc).
 */
#include <masonry/brickwork/laws/damage_plasticity.h>

#include <algorithm>
#include <cmath>

namespace masonry
{
  namespace brickwork
  {
    namespace
    {
      using State = DamagePlasticityBrick::State;

      /** Number of doubles of a State; with `IMPL-EX crack opening' =
       * frozen, 6 more for the crack strain. */
      constexpr unsigned int n_state = 12, n_crack = 6;

      /** Largest number of compressive and tensile returns in turn in one
       * update with `Tensile plastic flow' = crack (see update()). */
      constexpr unsigned int max_passes = 20;

      /**
       * Root of @p f in [a, b] with f(a) = fa > 0 > f(b) = fb by false
       * position with the Illinois modification (the retained end's value
       * halved when the same end moves twice in a row): stops once |f| <=
       * @p f_tol, the bracket is narrower than @p x_rel_tol b, or after
       * @p max_it evaluations; returns the last iterate.
       */
      template <typename F>
      double
      illinois_root(const F           &f,
                    double             a,
                    double             b,
                    double             fa,
                    double             fb,
                    const double       f_tol,
                    const double       x_rel_tol,
                    const unsigned int max_it)
      {
        double x = b;
        for (unsigned int it = 0, side = 2; it < max_it; ++it)
          {
            x              = (a * fb - b * fa) / (fb - fa);
            const double y = f(x);
            if (std::abs(y) <= f_tol || b - a <= x_rel_tol * b)
              break;
            if (y > 0)
              {
                a = x, fa = y;
                if (side == 0)
                  fb /= 2;
                side = 0;
              }
            else
              {
                b = x, fb = y;
                if (side == 1)
                  fa /= 2;
                side = 1;
              }
          }
        return x;
      }

      State
      unpack(ConstStateView v)
      {
        Assert(v.size() == n_state || v.size() == n_state + n_crack,
               dealii::ExcInternalError());
        State s;
        for (unsigned int i = 0; i < 6; ++i)
          s.plastic_strain.access_raw_entry(i) = v[i];
        s.threshold_t = v[6];
        s.threshold_c = v[7];
        s.kappa_t     = v[8];
        s.kappa_c     = v[9];
        s.damage_t    = v[10];
        s.damage_c    = v[11];
        if (v.size() > n_state)
          for (unsigned int i = 0; i < n_crack; ++i)
            s.crack_strain.access_raw_entry(i) = v[n_state + i];
        return s;
      }

      void
      pack(const State &s, StateView v)
      {
        Assert(v.size() == n_state || v.size() == n_state + n_crack,
               dealii::ExcInternalError());
        for (unsigned int i = 0; i < 6; ++i)
          v[i] = s.plastic_strain.access_raw_entry(i);
        v[6]  = s.threshold_t;
        v[7]  = s.threshold_c;
        v[8]  = s.kappa_t;
        v[9]  = s.kappa_c;
        v[10] = s.damage_t;
        v[11] = s.damage_c;
        if (v.size() > n_state)
          for (unsigned int i = 0; i < n_crack; ++i)
            v[n_state + i] = s.crack_strain.access_raw_entry(i);
      }
    } // namespace

    template <class Function>
    SymmetricTensor<4, 3>
    DamagePlasticityBrick::numerical_tangent(
      const Function              &function,
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

    void
    DamagePlasticityBrick::report(ConstStateView            state,
                                  dealii::ArrayView<double> values) const
    {
      const State s = unpack(state);
      values[0]     = s.damage_t;
      values[1]     = s.damage_c;
      values[2]     = s.plastic_strain.norm();
    }

    void
    DamagePlasticityBrick::damages(ConstStateView            state,
                                   dealii::ArrayView<double> values) const
    {
      values[0] = state[10];
      values[1] = state[11];
    }

    bool
    DamagePlasticityBrick::is_elastic(const SymmetricTensor<2, 3> &strain,
                                      ConstStateView               old_state,
                                      const BrickPoint            &point) const
    {
      return is_elastic(strain, unpack(old_state), point);
    }

    void
    DamagePlasticityBrick::evaluate(const SymmetricTensor<2, 3> &strain,
                                    ConstStateView               old_state,
                                    const BrickPoint            &point,
                                    StateView                    updated_state,
                                    SymmetricTensor<2, 3>       &stress,
                                    SymmetricTensor<4, 3>       &tangent) const
    {
      const State old = unpack(old_state);
      State       updated;
      evaluate(strain, old, point, updated, stress, tangent);
      pack(updated, updated_state);
    }

    void
    DamagePlasticityBrick::update_state(const SymmetricTensor<2, 3> &strain,
                                        ConstStateView               old_state,
                                        const BrickPoint            &point,
                                        StateView              updated_state,
                                        SymmetricTensor<2, 3> &stress) const
    {
      State updated;
      update(strain, unpack(old_state), point, updated, stress);
      pack(updated, updated_state);
    }

    void
    DamagePlasticityBrick::evaluate_extrapolated(
      const SymmetricTensor<2, 3> &strain,
      ConstStateView               old,
      ConstStateView               older,
      const double                 ratio_t,
      const BrickPoint &,
      SymmetricTensor<2, 3> &stress,
      SymmetricTensor<4, 3> &tangent) const
    {
      extrapolated(
        strain, unpack(old), unpack(older), ratio_t, stress, &tangent);
    }

    void
    DamagePlasticityBrick::extrapolated_stress(
      const SymmetricTensor<2, 3> &strain,
      ConstStateView               old,
      ConstStateView               older,
      const double                 ratio_t,
      const BrickPoint &,
      SymmetricTensor<2, 3> &stress) const
    {
      extrapolated(
        strain, unpack(old), unpack(older), ratio_t, stress, nullptr);
    }

    std::array<double, 2>
    DamagePlasticityBrick::nonlocal_measures(
      const SymmetricTensor<2, 3> &strain,
      ConstStateView               old_state,
      const BrickPoint &) const
    {
      SymmetricTensor<2, 3> plus, minus;
      double                tau_t, tau_c;
      split(effective(strain - unpack(old_state).plastic_strain),
            plus,
            minus,
            tau_t,
            tau_c);
      return {{tau_t, tau_c}};
    }

    bool
    DamagePlasticityBrick::is_elastic(const SymmetricTensor<2, 3> &strain,
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
    DamagePlasticityBrick::evaluate(const SymmetricTensor<2, 3> &strain,
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

    void
    DamagePlasticityBrick::extrapolated(const SymmetricTensor<2, 3> &strain,
                                        const State                 &old,
                                        const State                 &older,
                                        const double                 ratio_t,
                                        SymmetricTensor<2, 3>       &stress,
                                        SymmetricTensor<4, 3> *tangent) const
    {
      // damages and plastic strain extrapolated and frozen; with `IMPL-EX
      // crack opening' = frozen the cracks' opening (crack_strain) is only
      // frozen: extrapolated, it fed itself (doc/notes/implex-step-control.md)
      auto extrapolate = [&](const double d, const double d_older) {
        return std::clamp(d + ratio_t * (d - d_older), d, d_max);
      };
      const double d_t = extrapolate(old.damage_t, older.damage_t);
      const double d_c = extrapolate(old.damage_c, older.damage_c);
      const SymmetricTensor<2, 3> plastic =
        old.plastic_strain +
        ratio_t * (freeze_crack_opening ?
                     (old.plastic_strain - older.plastic_strain) -
                       (old.crack_strain - older.crack_strain) :
                     old.plastic_strain - older.plastic_strain);
      // stress = (1 - d_t) P(s) + (1 - d_c) (s - P(s)), s = C0 : (e - e_p)
      // with everything but e frozen, so the tangent is exact and closed:
      // ((d_c - d_t) dP/ds + (1 - d_c) I) : C0
      const SymmetricTensor<2, 3> s = effective(strain - plastic);
      SymmetricTensor<4, 3>       dP;
      const SymmetricTensor<2, 3> P = positive_part(s, tangent ? &dP : nullptr);
      stress                        = (1 - d_t) * P + (1 - d_c) * (s - P);
      if (tangent)
        *tangent =
          ((d_c - d_t) * dP + (1 - d_c) * dealii::identity_tensor<3>()) * C0;
    }

    void
    DamagePlasticityBrick::flow(SymmetricTensor<2, 3> &minus,
                                const double           intact_c,
                                const double           d_t,
                                const double           phi,
                                const double           rho_t,
                                const double           rho_c,
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
        split(s0 - lambda * G, p, m, tt, tc, rho_t, rho_c);
        const double share = interaction_share(tc, tt, 1 - intact_c, d_t, phi);
        return tc / (1 - share) - T;
      };
      double a = 0, b = 1 / a_d, fa = excess(a), fb = excess(b);
      // on (or by round-off inside) the threshold already: no flow; the
      // threshold out of reach along the flow: as far as it goes
      double lambda = fa <= 0 ? 0. : b;
      if (fa > 0 && fb < 0)
        lambda = illinois_root(excess, a, b, fa, fb, 1e-12 * T, 0., 100);
      updated.plastic_strain +=
        lambda * ((1 + nu_p) / E * minus - nu_p / E * dealii::trace(minus) * I);
      split(s0 - lambda * G, plus, minus, tau_t, tau_c, rho_t, rho_c);
    }

    double
    DamagePlasticityBrick::crack_return(const double           e_trial,
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
                                        double                &tau_c) const
    {
      // the crack strain grows along N, coaxial with the effective stress:
      // d e_p = (p(e) - p_old) N, so the effective stress moves by -(p(e) -
      // p_old) C0 : N; the envelope strain e is the root of "tensile
      // measure of the new effective stress = T(e)" (in uniaxial stress:
      // the input curve). One crack, N = n1 n1 (Rankine's associated flow,
      // n1 the direction of the largest principal effective stress s1),
      // when the second principal value s2 <= nu / (1 - nu) s1: then s1
      // stays the largest and s2 drops to <= 0 by the time s1 is returned
      // to 0 (the trial lateral stresses of a point in uniaxial stress are
      // lambda dp < nu / (1 - nu) s1). Otherwise (multiaxial tension) N =
      // s+ / tau_t, the positive principal directions together
      const SymmetricTensor<2, 3> s0  = plus + minus;
      const auto                  eig = dealii::eigenvectors(s0);
      const SymmetricTensor<2, 3> N =
        eig[1].first <= nu / (1 - nu) * eig[0].first ?
          SymmetricTensor<2, 3>(dealii::symmetrize(
            dealii::outer_product(eig[0].second, eig[0].second))) :
          SymmetricTensor<2, 3>(plus * (rho_t / tau_t));
      const SymmetricTensor<2, 3> G = effective(N);
      SymmetricTensor<2, 3>       p, m;
      double                      tt, tc;
      // the measure is the largest principal value itself, also where it
      // is negative (tau_t = 0): with the envelope softened to T(e) ~ 0 the
      // clipped measure made "excess" ~ 0 on the whole stretch past the
      // root, the search took its upper end e_trial and the crack opened
      // beyond the strain that relieves s1 (by (lambda + 2 mu) / E0 - 1 of
      // it and more with the interaction), leaving a compression across
      // the opening crack that grew step by step (the runaway of the study
      // sweep, contrib/study/results-2026-11-25)
      auto excess = [&](const double e) {
        const EnvelopePoint         env = tension(e, l, phi);
        const SymmetricTensor<2, 3> s   = s0 - (env.plastic - p_old) * G;
        split(s, p, m, tt, tc, rho_t, rho_c);
        const double share = interaction_share(tc, tt, d_c, env.damage, phi);
        const double s1    = tt > 0 ? tt : rho_t * dealii::eigenvalues(s)[0];
        return s1 / (1 - share) - E * (e - env.plastic);
      };
      // the root lies below the envelope strain of the elastic flow, e_trial
      // (in uniaxial stress; the increment of the largest principal value
      // per unit plastic strain, lambda + 2 mu, exceeds E0). Under biaxial
      // tension the second principal value, lowered only by lambda per
      // unit, may become the largest before the measure is on the
      // threshold: the flow stops at e_trial (never more plastic strain
      // than the elastic flow gives) and the next step returns the rest
      // along that direction
      double a = std::max(kappa_old, phi * f_t / E), b = std::max(e_trial, a);
      double fa = excess(a), fb = excess(b);
      double e = fa <= 0 ? a : b;
      if (fa > 0 && fb < 0)
        e = illinois_root(excess, a, b, fa, fb, 1e-13 * phi * f_t, 1e-15, 200);
      const double dp = tension(e, l, phi).plastic - p_old;
      updated.plastic_strain += dp * N;
      updated.crack_strain += dp * N;
      split(s0 - dp * G, plus, minus, tau_t, tau_c, rho_t, rho_c);
      return e;
    }

    /** The point and its trial state while update() returns it onto the
     * envelopes. */
    struct DamagePlasticityBrick::Trial
    {
      /** The point's strength factor phi, its crack-band length l (m),
       * its nonlocal factors of the tensile and compressive measures and
       * the factor beta of `Cracked compression softening' (all
       * dimensionless but l). */
      double phi = 1, l = 0, rho_t = 1, rho_c = 1, beta = 1;
      /** The positive and negative parts of the effective stress, Pa. */
      SymmetricTensor<2, 3> plus, minus;
      /** Their measures tau_t and tau_c (Pa) and the tensile and
       * compressive damages of the envelopes reached. */
      double tau_t = 0, tau_c = 0, d_t = 0, d_c = 0;
    };

    double
    DamagePlasticityBrick::threshold_scale(const double tau,
                                           const double damage,
                                           const double f,
                                           const double other,
                                           const double T,
                                           const double phi) const
    {
      return interaction ? scale_onto(tau,
                                      (1 - damage) * tau / (phi * f),
                                      std::min(other, 0.5),
                                      T) :
                           T / tau;
    }

    bool
    DamagePlasticityBrick::compressive_return(Trial &t, State &updated) const
    {
      const double phi = t.phi, l = t.l, rho_t = t.rho_t, rho_c = t.rho_c;
      SymmetricTensor<2, 3> &plus = t.plus, &minus = t.minus;
      double &tau_t = t.tau_t, &tau_c = t.tau_c, &d_t = t.d_t, &d_c = t.d_c;
      const double beta    = t.beta;
      bool         crushed = false;
      const double m       = interaction_share(tau_c, tau_t, d_c, d_t, phi);
      const double tau     = tau_c / ((1 - m) * beta);
      const double p_old =
        updated.kappa_c > 0 ? compression(updated.kappa_c, l, phi).plastic : 0.;
      const double e = p_old + tau / E;
      if (e > updated.kappa_c && e > ratio * phi * f_c / E && tau_c > 0)
        {
          const EnvelopePoint env = compression(e, l, phi);
          const double        T   = E * (e - env.plastic);
          const double        s   = threshold_scale(tau_c,
                                           env.damage,
                                           f_c,
                                           (1 - d_t) * tau_t / (phi * f_t),
                                           beta * T,
                                           phi);
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
                 rho_t,
                 rho_c,
                 beta * T,
                 updated,
                 plus,
                 tau_t,
                 tau_c);
          updated.kappa_c     = e;
          updated.threshold_c = T;
          d_c                 = env.damage;
          crushed             = true;
        }
      return crushed;
    }

    bool
    DamagePlasticityBrick::tensile_return(Trial &t, State &updated) const
    {
      const double phi = t.phi, l = t.l, rho_t = t.rho_t, rho_c = t.rho_c;
      SymmetricTensor<2, 3> &plus = t.plus, &minus = t.minus;
      double &tau_t = t.tau_t, &tau_c = t.tau_c, &d_t = t.d_t, &d_c = t.d_c;
      bool    cracked  = false;
      const double m   = interaction_share(tau_c, tau_t, d_c, d_t, phi);
      const double tau = tau_t / (1 - m);
      const double p_old =
        updated.kappa_t > 0 ? tension(updated.kappa_t, l, phi).plastic : 0.;
      const double e = p_old + tau / E;
      if (e > updated.kappa_t && e > phi * f_t / E && tau_t > 0)
        {
          if (crack_flow)
            {
              const double        e_new = crack_return(e,
                                                updated.kappa_t,
                                                p_old,
                                                d_c,
                                                l,
                                                phi,
                                                rho_t,
                                                rho_c,
                                                updated,
                                                plus,
                                                minus,
                                                tau_t,
                                                tau_c);
              const EnvelopePoint env   = tension(e_new, l, phi);
              cracked                   = e_new > updated.kappa_t;
              updated.kappa_t           = e_new;
              updated.threshold_t       = E * (e_new - env.plastic);
              d_t                       = env.damage;
            }
          else
            {
              const EnvelopePoint env = tension(e, l, phi);
              const double        T   = E * (e - env.plastic);
              const double        s   = threshold_scale(tau_t,
                                               env.damage,
                                               f_t,
                                               (1 - d_c) * tau_c / (phi * f_c),
                                               T,
                                               phi);
              updated.plastic_strain += (1 - s) * compliance(plus);
              updated.crack_strain += (1 - s) * compliance(plus);
              plus *= s;
              updated.kappa_t     = e;
              updated.threshold_t = T;
              d_t                 = env.damage;
            }
        }
      return cracked;
    }

    void
    DamagePlasticityBrick::update(const SymmetricTensor<2, 3> &strain,
                                  const State                 &old,
                                  const BrickPoint            &point,
                                  State                       &updated,
                                  SymmetricTensor<2, 3>       &stress) const
    {
      Trial t;
      t.phi   = point.strength_factor;
      t.l     = point.characteristic_length;
      t.rho_t = point.tensile_factor;
      t.rho_c = point.compressive_factor;
      updated = old;
      split(effective(strain - old.plastic_strain),
            t.plus,
            t.minus,
            t.tau_t,
            t.tau_c,
            t.rho_t,
            t.rho_c);
      t.d_t = old.kappa_t > 0 ? tension(old.kappa_t, t.l, t.phi).damage : 0.;
      t.d_c =
        old.kappa_c > 0 ? compression(old.kappa_c, t.l, t.phi).damage : 0.;
      // the two returns in turn: compression, then tension. The crack flow
      // (n1 n1 or s+ / tau_t) also moves the other principal values, by
      // -lambda dp each, so it can push s- back outside the compressive
      // envelope just returned to (the elastic flow, along C0^-1 : s+,
      // moves s+ only); a compressive flow with nu_p != nu (flow()) moves
      // s+ in turn. So with `crack' both returns are repeated, from the
      // envelope strains reached, until neither acts. Left as it was, the
      // excess lambda dp (1 - d_c) of every step stayed in the returned
      // stress: a cell fully softened in compression (T_c = 0) whose crack
      // kept opening carried it, and in the walls of the study sweep such
      // cells ran away (contrib/study/results-2026-11-25)
      t.beta = cracked_compression_factor(old.kappa_t);
      for (unsigned int pass = 0; pass < max_passes; ++pass)
        {
          const bool crushed = compressive_return(t, updated);
          // after a crack return the tensile state moves only with a
          // compressive one (round-off aside)
          if (pass > 0 && !crushed)
            break;
          if (!tensile_return(t, updated))
            break;
        }
      // viscous regularisation
      const double a =
        mu_visc > 0 && point.time_step > 0 ? mu_visc / point.time_step : 0.;
      updated.damage_t =
        std::max((t.d_t + a * old.damage_t) / (1 + a), old.damage_t);
      updated.damage_c =
        std::max((t.d_c + a * old.damage_c) / (1 + a), old.damage_c);
      stress =
        (1 - updated.damage_t) * t.plus + (1 - updated.damage_c) * t.minus;
    }

  } // namespace brickwork
} // namespace masonry


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
  "and unloading follows (1 - d_c) E0 to the plastic strain. l is the "
  "cell's crack-band length: the cube root of its volume; for a mortar "
  "cell of the detailed model its size across the layer. The positive "
  "part of a "
  "principal stress is blended smoothly (C1) over its first 0.1 % of f_t "
  "so that Newton converges where a principal stress is zero. Tangent: "
  "central differences of the stress update (consistent to O(h^2)); "
  "elastic points use C0. Options: `Tension-compression interaction' "
  "(failure on the linear envelope sigma_t / f_t + sigma_c / f_c = 1 under "
  "compression with lateral tension), `Cracked compression softening' "
  "(a cracked point's compressive strength beta f_c, beta = 1 / (0.8 + c "
  "eps_1) <= 1 after Vecchio & Collins 1986), `Confinement coefficient' "
  "(Lubliner's "
  "triaxial term), `Compressive softening' = false (perfectly plastic in "
  "compression), `Tensile plastic flow' = crack (the crack strain normal "
  "to the crack only, without the Poisson part of C0^-1 : s+).")
