/**
 * @file
 * Brick material `damage plasticity': the stress measures it is built on
 * (the effective stress and its compliance, the spectral split of the
 * effective stress into its positive and negative parts with the tensile
 * and compressive measures, the tension-compression interaction, the
 * cracked-compression factor) and the uniaxial envelopes in compression and
 * tension with their split into plastic strain and damage (the stress
 * update, the returns and the tangents: damage_plasticity.cc; the
 * formulation: the documentation of
 * include/masonry/brickwork/laws/damage_plasticity.h).
 */
#include <masonry/brickwork/laws/damage_plasticity.h>

#include <algorithm>
#include <cmath>

namespace masonry
{
  namespace brickwork
  {
    SymmetricTensor<2, 3>
    DamagePlasticityBrick::effective(const SymmetricTensor<2, 3> &e) const
    {
      return lambda * dealii::trace(e) * dealii::unit_symmetric_tensor<3>() +
             2 * mu * e;
    }

    SymmetricTensor<2, 3>
    DamagePlasticityBrick::compliance(const SymmetricTensor<2, 3> &s) const
    {
      return (1 + nu) / E * s -
             nu / E * dealii::trace(s) * dealii::unit_symmetric_tensor<3>();
    }

    namespace
    {
      /** Whether every principal value of @p s is below @p bound (<= 0):
       * whether s - bound I is negative definite, by Sylvester's criterion
       * (the leading principal minors of bound I - s all positive). */
      bool
      all_principal_values_below(const SymmetricTensor<2, 3> &s,
                                 const double                 bound)
      {
        const double a00 = bound - s[0][0], a11 = bound - s[1][1],
                     a22 = bound - s[2][2];
        const double a01 = -s[0][1], a02 = -s[0][2], a12 = -s[1][2];
        if (a00 <= 0)
          return false;
        const double minor2 = a00 * a11 - a01 * a01;
        if (minor2 <= 0)
          return false;
        return a00 * (a11 * a22 - a12 * a12) - a01 * (a01 * a22 - a12 * a02) +
                 a02 * (a01 * a12 - a11 * a02) >
               0;
      }
    } // namespace

    SymmetricTensor<2, 3>
    DamagePlasticityBrick::positive_part(const SymmetricTensor<2, 3> &s,
                                         SymmetricTensor<4, 3> *derivative,
                                         double                *largest) const
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
        return x <= 0 ? 0. : x >= delta ? 1. : x * (4 - 3 * x / delta) / delta;
      };
      // all three principal stresses clearly compressive: P = 0 and its
      // derivative 0 exactly, as the sum below would give (h and its slope
      // vanish at x <= 0; the margin keeps the sign of the largest
      // eigenvalue beyond the round-off of either computation). Told by
      // the leading minors, without the eigenvalues, whose closed form
      // (arccos, cos) cost more than the rest of this function
      if (all_principal_values_below(s, -1e-6 * s.norm()))
        return P;
      // (deal.II's QL: its `hybrid' method, analytical, is cheaper, but
      // its eigenvectors of nearly equal principal stresses made Newton
      // stall in a cracked cyclic wallette, tests/brickwork_unloading_floor)
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

    void
    DamagePlasticityBrick::split(const SymmetricTensor<2, 3> &s,
                                 SymmetricTensor<2, 3>       &plus,
                                 SymmetricTensor<2, 3>       &minus,
                                 double                      &tau_t,
                                 double                      &tau_c,
                                 const double                 rho_t,
                                 const double                 rho_c) const
    {
      plus = positive_part(s, nullptr, &tau_t);
      tau_t *= rho_t;
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
      tau_c *= rho_c;
    }

    double
    DamagePlasticityBrick::interaction_share(const double tau_c,
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

    double
    DamagePlasticityBrick::cracked_compression_factor(const double eps_1) const
    {
      if (c_cracked == 0 || eps_1 <= 0)
        return 1.;
      return std::max(beta_residual,
                      std::min(1., 1 / (0.8 + c_cracked * eps_1)));
    }

    double
    DamagePlasticityBrick::scale_onto(const double tau,
                                      const double a,
                                      const double M,
                                      double       T)
    {
      const double k_high = T * (1 - M) / tau;
      const double k      = k_high * a >= M ? k_high : T / (tau + T * a);
      return std::clamp(k, 0., 1.);
    }

    DamagePlasticityBrick::EnvelopePoint
    DamagePlasticityBrick::compression(const double e,
                                       const double l,
                                       const double phi) const
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
          p.stress       = f0 + (fc - f0) * (k * x - x * x) / (1 + (k - 2) * x);
        }
      else
        p.stress = softening ? fc * std::exp(-(e - ec) * fc * l / G_c) : fc;
      decompose(e, b_c, p);
      return p;
    }

    DamagePlasticityBrick::EnvelopePoint
    DamagePlasticityBrick::tension(const double e,
                                   const double l,
                                   const double phi) const
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

    void
    DamagePlasticityBrick::decompose(const double   e,
                                     const double   b,
                                     EnvelopePoint &p) const
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
  } // namespace brickwork
} // namespace masonry
