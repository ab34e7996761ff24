/**
 * The composite joint law (Lourenço & Rots 1997) alone, against closed
 * forms that the test computes itself:
 * - returns from a virgin joint onto each surface and corner: the traction
 *   lies on the surface whose softening/hardening parameters follow from
 *   the plastic jump u_p = u - D^-1 t (computed here from the traction),
 *   and u_p has the direction of the flow rule;
 * - pure mode I and pure mode II at zero normal stress dissipate G_I and
 *   G_II; mode II under a constant compression -s dissipates
 *   G_II (1 + s (tan phi_0 - tan phi_r) / c0) above the residual dry
 *   friction s tan phi_r (integral of the cohesion and friction
 *   softening laws), all within 1 %;
 * - the compression cap under uniaxial closing follows sbar(kappa_3) of
 *   the paper (hardening sqrt branch, parabola, exponential) at jumps
 *   u_n = -(kappa + sbar(kappa) / k_n), and dissipates its integral;
 * - an opened crack closes without traction and carries compression again
 *   from u_n = 0 with k_n;
 * - the algorithmic tangent equals central differences of the traction
 *   in every regime (elastic, tension, shear, cap hardening and
 *   softening, both corners);
 * - IMPL-EX: the extrapolated, frozen plastic jump gives t = D_e (u - u_p*);
 * - a global Newton solve (unit in series with the joint) converges in a few
 *   iterations with the algorithmic tangent;
 * - the Lourenço-Rots penalties from E_b, E_m, nu and the joint thickness.
 */
#include <masonry/brickwork/laws/composite_joint.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>

using namespace masonry::brickwork::laws;

namespace
{
  bool all_ok = true;

  void
  check(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "OK " : "FAILED ") << what << std::endl;
    all_ok = all_ok && ok;
  }

  /** Lourenço-Rots shear-wall joint values in SI (Pa, m, J/m^2). */
  CompositeJoint::Parameters
  reference()
  {
    CompositeJoint::Parameters p;
    p.normal_stiffness  = 82e9;
    p.shear_stiffness   = 36e9;
    p.tensile_strength  = 0.25e6;
    p.mode_I_energy     = 18;
    p.cohesion          = 0.35e6;
    p.friction          = 0.75;
    p.residual_friction = 0.5;
    p.dilatancy         = 0;
    p.mode_II_energy    = 125;
    p.cap_strength      = 10.5e6;
    p.cap_Css           = 9;
    p.cap_peak_jump     = 0.09e-3;
    p.cap_energy        = 5000;
    return p;
  }

  /** The paper's cap law, written out independently of the class. */
  struct CapCurve
  {
    double sp, si, sm, sr, kp, km;
    explicit CapCurve(const CompositeJoint::Parameters &p)
      : sp(p.cap_strength)
      , si(p.cap_initial_ratio * sp)
      , sm(p.cap_middle_ratio * sp)
      , sr(p.cap_residual_ratio * sp)
      , kp(p.cap_peak_jump)
    {
      // G_fc = int_{kp}^inf (sbar - sr): parabola + exponential tail
      const double per_length =
        (sp - sr) + (sm - sp) / 3. + (sm - sr) * (sm - sr) / (2 * (sp - sm));
      km = kp + p.cap_energy / per_length;
    }
    double
    operator()(const double k) const
    {
      if (k <= kp)
        return si + (sp - si) * std::sqrt(2 * k / kp - k * k / (kp * kp));
      if (k <= km)
        return sp + (sm - sp) * std::pow((k - kp) / (km - kp), 2);
      const double m = 2 * (sm - sp) / (km - kp);
      return sr + (sm - sr) * std::exp(m * (k - km) / (sm - sr));
    }
    /** int_0^k sbar, closed form. */
    double
    integral(const double k) const
    {
      const double pi = std::acos(-1.);
      if (k <= kp)
        {
          // int_0^x sqrt(2 s - s^2) ds, s = 1 - c: quarter-circle segment
          const double x = k / kp, c = 1 - x;
          const double seg =
            0.5 * (std::asin(1.) - std::asin(c) - c * std::sqrt(1 - c * c));
          return si * k + (sp - si) * kp * seg;
        }
      const double hard = si * kp + (sp - si) * kp * pi / 4;
      if (k <= km)
        {
          const double h = (k - kp) / (km - kp);
          return hard + (km - kp) * (sp * h + (sm - sp) * h * h * h / 3);
        }
      const double para = (km - kp) * (sp + (sm - sp) / 3);
      const double m    = 2 * (sm - sp) / (km - kp);
      const double tail =
        sr * (k - km) +
        (sm - sr) * (sm - sr) / m * (std::exp(m * (k - km) / (sm - sr)) - 1);
      return hard + para + tail;
    }
  };

  double
  norm3(const Vector3 &v)
  {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  }

  /** Scalar root of f on [a, b] by bisection (f(a) f(b) < 0). */
  double
  bisect(const std::function<double(double)> &f, double a, double b)
  {
    double fa = f(a);
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double m = 0.5 * (a + b), fm = f(m);
        if ((fm < 0) == (fa < 0))
          a = m, fa = fm;
        else
          b = m;
      }
    return 0.5 * (a + b);
  }

  /** u_p = u - D^-1 t. */
  Vector3
  plastic(const CompositeJoint::Parameters &p,
          const Vector3                    &u,
          const Vector3                    &t)
  {
    return {{u[0] - t[0] / p.normal_stiffness,
             u[1] - t[1] / p.shear_stiffness,
             u[2] - t[2] / p.shear_stiffness}};
  }

  /** Work per unit area of the traction along the straight path from
   * @p from to @p to in @p n steps (trapezoid), updating @p state. */
  double
  work(const CompositeJoint &law,
       CompositeJointState  &state,
       const Vector3        &from,
       const Vector3        &to,
       const unsigned int    n,
       Vector3              &t_end)
  {
    Vector3 t_prev, u_prev = from;
    Matrix3 D;
    {
      CompositeJointState s;
      law.evaluate(from, state, s, t_prev, D);
      state = s;
    }
    double W = 0;
    for (unsigned int k = 1; k <= n; ++k)
      {
        const double        a = double(k) / n;
        Vector3             u, t;
        CompositeJointState s;
        for (unsigned int i = 0; i < 3; ++i)
          u[i] = from[i] + a * (to[i] - from[i]);
        law.evaluate(u, state, s, t, D);
        for (unsigned int i = 0; i < 3; ++i)
          W += 0.5 * (t[i] + t_prev[i]) * (u[i] - u_prev[i]);
        state  = s;
        t_prev = t;
        u_prev = u;
      }
    t_end = t_prev;
    return W;
  }
  // the reference joint and the closed-form ingredients of every check
  const CompositeJoint::Parameters p = reference();
  const CompositeJoint             law(p);
  const double kn = p.normal_stiffness, ks = p.shear_stiffness;
  const double a = p.tensile_strength / p.mode_I_energy,
               b = p.cohesion / p.mode_II_energy;
  double
  tanphi(const double xi)
  {
    return p.friction +
           (p.residual_friction - p.friction) * (1 - std::exp(-xi));
  }
  const CapCurve cap(p);

  // ---------------------------------------------------------------------
  // elastic
  void
  check_elastic()
  {
    CompositeJointState  s0, s;
    Vector3              t;
    Matrix3              D;
    CompositeJointActive act;
    const Vector3        u{{1e-6, 2e-6, -1e-6}};
    law.evaluate(u, s0, s, t, D, &act);
    bool ok = !act.tension && !act.shear && !act.cap &&
              std::abs(t[0] - kn * u[0]) < 1e-6 &&
              std::abs(t[1] - ks * u[1]) < 1e-6 &&
              std::abs(t[2] - ks * u[2]) < 1e-6;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        ok = ok && std::abs(D[i][j] - (i == j ? (i == 0 ? kn : ks) : 0.)) <
                     1e-12 * kn;
    check(ok, "elastic: t = diag(k_n, k_s, k_s) u and tangent D_e");
  }

  // ---------------------------------------------------------------------
  // tension from a virgin joint in one step: sigma = f_t0 exp(-a w),
  // w = u_n - sigma / k_n
  void
  check_tension()
  {
    const double u_n       = 5 * p.tensile_strength / kn + 3e-5;
    const double sigma_ref = bisect(
      [&](const double s) {
        return s - p.tensile_strength * std::exp(-a * (u_n - s / kn));
      },
      0,
      p.tensile_strength);
    CompositeJointState  s0, s;
    Vector3              t;
    Matrix3              D;
    CompositeJointActive act;
    law.evaluate({{u_n, 0, 0}}, s0, s, t, D, &act);
    check(act.tension && !act.shear && !act.cap &&
            std::abs(t[0] - sigma_ref) < 1e-9 * p.tensile_strength &&
            t[1] == 0 && t[2] == 0,
          "tension: sigma = f_t0 exp(-f_t0 w / G_I) at the plastic opening");
  }

  // shear with friction under sigma = -0.5 MPa, slip along (3, 4) / 5:
  // tau = c0 exp(-xi) + 0.5e6 tan phi(xi), xi = b (s - tau / k_s)
  void
  check_shear()
  {
    const double sigma = -0.5e6, s_slip = 2e-4;
    const double u_n     = sigma / kn;
    const double tau_ref = bisect(
      [&](const double tau) {
        const double xi = b * (s_slip - tau / ks);
        return tau - (p.cohesion * std::exp(-xi) - sigma * tanphi(xi));
      },
      0,
      ks * s_slip);
    CompositeJointState  s0, s;
    Vector3              t;
    Matrix3              D;
    CompositeJointActive act;
    const Vector3        u{{u_n, 0.6 * s_slip, 0.8 * s_slip}};
    law.evaluate(u, s0, s, t, D, &act);
    const double tau = std::hypot(t[1], t[2]);
    check(!act.tension && act.shear && !act.cap &&
            std::abs(t[0] - sigma) < 1e-6 &&
            std::abs(tau - tau_ref) < 1e-9 * p.cohesion &&
            std::abs(t[1] * 0.8 - t[2] * 0.6) < 1e-9 * tau,
          "shear: tau = c(xi) - sigma tan phi(xi) along the slip direction, "
          "sigma unchanged (no dilatancy)");
  }

  // tension-shear corner: both surfaces with xi = sqrt((a l1)^2 + (b l2)^2),
  // l1 = u_p,n, l2 = |u_p,s|
  void
  check_tension_shear_corner()
  {
    const Vector3        u{{3e-5, 1.5e-4, 0}};
    CompositeJointState  s0, s;
    Vector3              t;
    Matrix3              D;
    CompositeJointActive act;
    law.evaluate(u, s0, s, t, D, &act);
    const Vector3 up = plastic(p, u, t);
    const double  l1 = up[0], l2 = std::hypot(up[1], up[2]);
    const double  xi  = std::hypot(a * l1, b * l2);
    const double  E   = std::exp(-xi);
    const double  tau = std::hypot(t[1], t[2]);
    check(act.tension && act.shear && !act.cap && l1 > 0 && l2 > 0 &&
            std::abs(t[0] - p.tensile_strength * E) <
              1e-9 * p.tensile_strength &&
            std::abs(tau - (p.cohesion * E - t[0] * tanphi(xi))) <
              1e-9 * p.cohesion,
          "tension-shear corner: sigma = f_t0 e^-xi, tau = c0 e^-xi - sigma "
          "tan phi(xi) with the coupled xi of both plastic jumps");
  }

  // cap alone (associated): C_nn s^2 + C_ss tau^2 = sbar(|u_p|)^2 and u_p
  // parallel to (2 C_nn sigma, 2 C_ss tau)
  void
  check_cap()
  {
    const Vector3        u{{-6e6 / kn, 0.5e6 / ks, 0}};
    CompositeJointState  s0, s;
    Vector3              t;
    Matrix3              D;
    CompositeJointActive act;
    law.evaluate(u, s0, s, t, D, &act);
    const Vector3 up  = plastic(p, u, t);
    const double  k3  = norm3(up);
    const double  tau = std::hypot(t[1], t[2]);
    const double  f3 =
      p.cap_Cnn * t[0] * t[0] + p.cap_Css * tau * tau - std::pow(cap(k3), 2);
    const double cross =
      up[0] * 2 * p.cap_Css * t[1] - up[1] * 2 * p.cap_Cnn * t[0];
    check(!act.tension && !act.shear && act.cap &&
            std::abs(f3) < 1e-9 * p.cap_strength * p.cap_strength &&
            std::abs(cross) < 1e-9 * k3 * p.cap_strength && up[0] < 0 &&
            up[1] > 0,
          "cap: C_nn sigma^2 + C_ss tau^2 = sbar(kappa_3)^2 with kappa_3 = "
          "|u_p| and associated flow");
  }

  // shear-cap corner: u_p = l2 (tan psi, 1) + l3 (2 C_nn sigma, 2 C_ss tau)
  void
  check_shear_cap_corner()
  {
    const Vector3        u{{-2e6 / kn, 3e6 / ks, 0}};
    CompositeJointState  s0, s;
    Vector3              t;
    Matrix3              D;
    CompositeJointActive act;
    law.evaluate(u, s0, s, t, D, &act);
    const Vector3 up  = plastic(p, u, t);
    const double  tau = std::hypot(t[1], t[2]);
    const double  ns = 2 * p.cap_Cnn * t[0], nt = 2 * p.cap_Css * tau;
    // up_n = l2 tan psi + l3 ns, |up_s| = l2 + l3 nt
    const double us  = std::hypot(up[1], up[2]);
    const double det = p.dilatancy * nt - ns;
    const double l2  = (up[0] * nt - us * ns) / det;
    const double l3  = (p.dilatancy * us - up[0]) / det;
    const double xi  = b * l2;
    const double k3  = l3 * std::hypot(ns, nt);
    const double f2  = tau + t[0] * tanphi(xi) - p.cohesion * std::exp(-xi);
    const double f3 =
      t[0] * t[0] + p.cap_Css * tau * tau - std::pow(cap(k3), 2);
    check(!act.tension && act.shear && act.cap && l2 > 0 && l3 > 0 &&
            std::abs(f2) < 1e-9 * p.cohesion &&
            std::abs(f3) < 1e-9 * p.cap_strength * p.cap_strength,
          "shear-cap corner: both surfaces hold with xi = c0 l2 / G_II and "
          "kappa_3 = l3 |grad f3| from the split of u_p");
  }

  // ---------------------------------------------------------------------
  // energies
  void
  check_energy_mode_I()
  {
    CompositeJointState s;
    Vector3             t;
    const double        u_end = 40 * p.mode_I_energy / p.tensile_strength;
    const double W = work(law, s, {{0, 0, 0}}, {{u_end, 0, 0}}, 20000, t) -
                     t[0] * t[0] / (2 * kn);
    check(std::abs(W / p.mode_I_energy - 1) < 0.01,
          "mode I: dissipated energy = G_I within 1 %");
  }

  void
  check_energy_mode_II()
  {
    CompositeJointState s;
    Vector3             t;
    const double        s_end = 40 * p.mode_II_energy / p.cohesion;
    const double W = work(law, s, {{0, 0, 0}}, {{0, s_end, 0}}, 20000, t) -
                     t[1] * t[1] / (2 * ks);
    check(std::abs(W / p.mode_II_energy - 1) < 0.01 && std::abs(t[0]) < 1e-6,
          "mode II at zero normal stress: dissipated energy = G_II within "
          "1 %");
  }

  void
  check_energy_mode_II_compressed()
  {
    // constant compression (u_n fixed, no dilatancy) with a stronger cap
    CompositeJoint::Parameters q = p;
    q.cap_strength               = 30e6;
    q.cap_energy                 = 20000;
    const CompositeJoint strong(q);
    const double         sig   = 2e6;
    const Vector3        start = {{-sig / kn, 0, 0}};
    const double         s_end = 40 * p.mode_II_energy / p.cohesion;
    CompositeJointState  s;
    Vector3              t;
    const double W = work(strong, s, start, {{-sig / kn, s_end, 0}}, 20000, t) -
                     t[1] * t[1] / (2 * ks);
    const double slip_p = s_end - t[1] / ks;
    const double G =
      p.mode_II_energy *
      (1 + sig * (p.friction - p.residual_friction) / p.cohesion);
    check(std::abs((W - sig * p.residual_friction * slip_p) / G - 1) < 0.01 &&
            std::abs(t[0] + sig) < 1e-3,
          "mode II under 2 MPa compression: energy above residual friction = "
          "G_II (1 + s (tan phi_0 - tan phi_r) / c0) within 1 %");
  }

  // ---------------------------------------------------------------------
  // cap curve under uniaxial closing: sigma = -sbar(kappa) at
  // u_n = -(kappa + sbar(kappa) / k_n), kappa over all three branches
  void
  check_cap_curve()
  {
    CompositeJointState s;
    double              err = 0, u_prev = 0, t_prev = 0, W = 0;
    const double        k_end = cap.km + 4 * (cap.km - cap.kp);
    const unsigned int  n     = 4000;
    for (unsigned int k = 1; k <= n; ++k)
      {
        const double        kappa = k_end * std::pow(double(k) / n, 2);
        const double        u_n   = -(kappa + cap(kappa) / kn);
        CompositeJointState s1;
        Vector3             t;
        Matrix3             D;
        law.evaluate({{u_n, 0, 0}}, s, s1, t, D);
        err = std::max(err, std::abs(t[0] + cap(kappa)) / p.cap_strength);
        W += 0.5 * (t[0] + t_prev) * (u_n - u_prev);
        u_prev = u_n;
        t_prev = t[0];
        s      = s1;
      }
    check(err < 1e-8,
          "cap: sigma = -sbar(kappa_3) on the hardening, parabolic and "
          "exponential branches (closed form)");
    const double dissipated = W - t_prev * t_prev / (2 * kn);
    check(std::abs(dissipated / cap.integral(k_end) - 1) < 0.01,
          "cap: dissipated energy = int sbar d kappa_3 within 1 %");
    check(std::abs(law.cap_middle_jump() - cap.km) < 1e-12 * cap.km &&
            std::abs(cap.integral(1e3) - cap.integral(cap.kp) -
                     cap.sr * (1e3 - cap.kp) - p.cap_energy) <
              1e-6 * p.cap_energy,
          "cap: kappa_m from G_fc = int_{kappa_p}^inf (sbar - sbar_r)");
  }

  // ---------------------------------------------------------------------
  // crack closure
  void
  check_crack_closure()
  {
    CompositeJointState s;
    Vector3             t;
    // open to xi = 2 (f_t = 0.135 f_t0)
    const double u_open = 2 * p.mode_I_energy / p.tensile_strength;
    work(law, s, {{0, 0, 0}}, {{u_open, 0, 0}}, 200, t);
    const double        w = u_open - t[0] / kn;
    Matrix3             D;
    CompositeJointState s1, s2, s3;
    Vector3             t1, t2, t3;
    law.evaluate({{0.5 * w, 0, 0}}, s, s1, t1, D);
    const bool half = std::abs(t1[0]) < 1e-9 && D[0][0] == 0;
    law.evaluate({{-1e-5, 0, 0}}, s1, s2, t2, D);
    const bool contact = std::abs(t2[0] + kn * 1e-5) < 1e-9 * kn * 1e-5 &&
                         D[0][0] == kn && s2.crack_opening == 0;
    // reopening: elastic from u_n = 0 to the softened strength
    law.evaluate({{1e-7, 0, 0}}, s2, s3, t3, D);
    const bool reopen = std::abs(t3[0] - kn * 1e-7) < 1e-9 * kn * 1e-7;
    check(half && contact && reopen,
          "crack closure: no traction while the crack closes, contact "
          "k_n u_n from u_n = 0, elastic reopening");
  }

  // ---------------------------------------------------------------------
  // IMPL-EX: the plastic jump extrapolated linearly from two converged
  // states (ratio 1: u_p* = 2 u_p,old - u_p,older) and frozen:
  // t = D_e (u - u_p*), tangent D_e; an open crack closes without traction
  void
  check_impl_ex()
  {
    CompositeJointState older, old, s;
    Vector3             t;
    Matrix3             D;
    // two converged states of a softening opening with some slip
    law.evaluate({{4e-5, 1e-5, 0}}, CompositeJointState(), older, t, D);
    law.evaluate({{5e-5, 1.2e-5, 0}}, older, old, t, D);
    const CompositeJointState e = law.extrapolate(old, older, 1.);
    const Vector3             u{{6e-5, 1.4e-5, -1e-6}};
    law.evaluate_frozen(u, e, t, D);
    bool ok = old.crack_opening > older.crack_opening && old.xi > older.xi;
    for (unsigned int i = 0; i < 3; ++i)
      {
        const double up = 2 * old.plastic_jump[i] - older.plastic_jump[i];
        const double k  = i == 0 ? kn : ks;
        ok = ok && std::abs(t[i] - k * (u[i] - up)) < 1e-9 * k * 1e-5 &&
             std::abs(D[i][i] - k) == 0;
      }
    ok = ok && std::abs(e.xi - (2 * old.xi - older.xi)) < 1e-12 &&
         std::abs(e.crack_opening -
                  (2 * old.crack_opening - older.crack_opening)) < 1e-15;
    // pushed back below the crack: no traction, zero normal tangent
    Vector3 t2;
    law.evaluate_frozen({{0.5 * e.crack_opening, 0, 0}}, e, t2, D);
    ok = ok && t2[0] == 0 && D[0][0] == 0;
    // below the closed crack: contact from u_p* - w*
    const double closed = e.plastic_jump[0] - e.crack_opening;
    law.evaluate_frozen({{closed - 1e-6, 0, 0}}, e, t2, D);
    ok = ok && std::abs(t2[0] + kn * 1e-6) < 1e-9 * kn * 1e-6 && D[0][0] == kn;
    check(ok,
          "IMPL-EX: t = D_e (u - u_p*) with u_p* = 2 u_p,old - u_p,older, "
          "tangent D_e; an open crack closes without traction");
  }

  // ---------------------------------------------------------------------
  // tangent against central differences
  void
  check_tangent()
  {
    struct Case
    {
      const char *name;
      Vector3     u;
      bool        preload; // first load in compression to harden the cap
    };
    const Case cases[] = {
      {"elastic", {{1e-6, 1e-6, 2e-6}}, false},
      {"tension", {{2e-5, 1e-7, -2e-7}}, false},
      {"shear", {{-0.5e6 / kn, 1e-4, 5e-5}}, false},
      {"tension-shear corner", {{3e-5, 1.2e-4, 0.5e-4}}, false},
      {"cap hardening", {{-6e6 / kn, 0.3e6 / ks, 0.2e6 / ks}}, false},
      {"cap softening", {{-(3e-4 + 9e6 / kn), 0.1e6 / ks, 0}}, true},
      {"shear-cap corner", {{-2e6 / kn, 2e6 / ks, 2e6 / ks}}, false}};
    for (const Case &c : cases)
      {
        CompositeJointState old;
        if (c.preload)
          {
            // harden the cap past its peak along a uniaxial path
            Vector3 t;
            work(law, old, {{0, 0, 0}}, {{c.u[0] * 0.98, 0, 0}}, 400, t);
          }
        CompositeJointState s;
        Vector3             t;
        Matrix3             D;
        law.evaluate(c.u, old, s, t, D);
        double err = 0;
        for (unsigned int j = 0; j < 3; ++j)
          {
            const double        h  = 1e-9;
            Vector3             up = c.u, um = c.u, tp, tm;
            CompositeJointState sp, sm;
            Matrix3             Dp, Dm;
            up[j] += h;
            um[j] -= h;
            law.evaluate(up, old, sp, tp, Dp);
            law.evaluate(um, old, sm, tm, Dm);
            for (unsigned int i = 0; i < 3; ++i)
              err =
                std::max(err,
                         std::abs((tp[i] - tm[i]) / (2 * h) - D[i][j]) / kn);
          }
        check(err < 1e-5,
              std::string("tangent = central differences (1e-5 of k_n): ") +
                c.name);
      }
  }

  // ---------------------------------------------------------------------
  // random cyclic paths (jump increments 1e-6 to 1e-3 m, biased to
  // compression in half of each path): every return is found and the
  // traction lies inside the three surfaces of the state it returns
  void
  check_random_paths()
  {
    CompositeJoint::Parameters q = p;
    q.dilatancy                  = 0.1;
    q.cap_Cn                     = -1e6;
    const CompositeJoint law_q(q);
    unsigned long        seed    = 12345;
    auto                 uniform = [&seed]() {
      seed = seed * 6364136223846793005ul + 1442695040888963407ul;
      return double(seed >> 11) / double(1ul << 53);
    };
    unsigned int failures = 0, steps = 0;
    double       worst = 0;
    for (unsigned int path = 0; path < 400; ++path)
      {
        CompositeJointState s;
        Vector3             u{{0, 0, 0}};
        const double        scale = std::pow(10., -6 + 3 * uniform());
        for (unsigned int k = 0; k < 60; ++k)
          {
            for (unsigned int i = 0; i < 3; ++i)
              u[i] += scale * (2 * uniform() - 1) -
                      (i == 0 && k % 20 < 10 ? scale : 0.);
            CompositeJointState s1;
            Vector3             t;
            Matrix3             D;
            try
              {
                law_q.evaluate(u, s, s1, t, D);
              }
            catch (const std::runtime_error &)
              {
                ++failures;
                break;
              }
            ++steps;
            s                = s1;
            const double E   = std::exp(-s.xi);
            const double tau = std::hypot(t[1], t[2]);
            const double tp =
              q.friction + (q.residual_friction - q.friction) * (1 - E);
            const double sb = law_q.cap_yield(s.kappa_cap);
            worst =
              std::max({worst,
                        (t[0] - q.tensile_strength * E) / q.tensile_strength,
                        (tau + t[0] * tp - q.cohesion * E) / q.cohesion,
                        (t[0] * t[0] + q.cap_Css * tau * tau + q.cap_Cn * t[0] -
                         sb * sb) /
                          (q.cap_strength * q.cap_strength)});
          }
      }
    check(failures == 0 && steps == 400 * 60 && worst < 1e-9,
          "random cyclic paths: every return found, tractions inside all "
          "surfaces (1e-9 of the strengths)");
  }

  // a softening steeper than the penalty is refused, naming the entry
  void
  check_snap_back()
  {
    CompositeJoint::Parameters q = p;
    q.cap_energy                 = 100;
    std::string message;
    try
      {
        const CompositeJoint bad(q);
      }
    catch (const std::invalid_argument &e)
      {
        message = e.what();
      }
    check(message.find("Compressive fracture energy") != std::string::npos,
          "snap-back of the cap softening refused, naming Compressive "
          "fracture energy");
    // a cap below the tension cut-off (a cap of 1 Pa stopped a wallette
    // run with no admissible return) is refused too
    q              = p;
    q.cap_strength = 0.5 * p.tensile_strength;
    message.clear();
    try
      {
        const CompositeJoint bad(q);
      }
    catch (const std::invalid_argument &e)
      {
        message = e.what();
      }
    check(message.find("Cap strength must not be below Tensile strength") !=
            std::string::npos,
          "a cap strength below the tensile strength refused, naming Cap "
          "strength");
  }

  // ---------------------------------------------------------------------
  // the tangent in a global Newton solve: a joint in series with a unit
  // (k_b = E_b / h_b = 10 GPa / 65 mm per unit area), (a) displacement-
  // controlled compression through the cap's peak into its tail, (b) a
  // constant normal load of -0.5 MPa and a prescribed shear displacement
  // (with dilatancy 0.1, so that normal and shear are coupled). Every step
  // converges to 1e-10 of the strengths in at most 5 iterations (2 and 3
  // are needed; with the elastic tangent neither path converges in 30).
  void
  check_newton()
  {
    CompositeJoint::Parameters q = p;
    q.dilatancy                  = 0.1;
    const CompositeJoint law_q(q);
    const double         kb      = 10e9 / 0.065;
    unsigned int         worst_a = 0, worst_b = 0;
    bool                 converged = true;
    {
      CompositeJointState s;
      double              u_n = 0;
      for (unsigned int k = 1; k <= 200; ++k)
        {
          const double U = -k * 5e-6; // to 1 mm
          unsigned int it;
          for (it = 0; it < 30; ++it)
            {
              CompositeJointState s1;
              Vector3             t;
              Matrix3             D;
              law_q.evaluate({{u_n, 0, 0}}, s, s1, t, D);
              const double r = t[0] - kb * (U - u_n);
              if (std::abs(r) < 1e-10 * q.cap_strength)
                {
                  s = s1;
                  break;
                }
              u_n -= r / (D[0][0] + kb);
            }
          converged = converged && it < 30;
          worst_a   = std::max(worst_a, it);
        }
    }
    {
      CompositeJointState s;
      double              u[2] = {-0.5e6 / q.normal_stiffness, 0};
      const double        kbs  = kb / 2.3; // G_b / h_b, nu_b = 0.15
      for (unsigned int k = 1; k <= 200; ++k)
        {
          const double S = k * 5e-6; // to 1 mm of slip
          unsigned int it;
          for (it = 0; it < 30; ++it)
            {
              CompositeJointState s1;
              Vector3             t;
              Matrix3             D;
              law_q.evaluate({{u[0], u[1], 0}}, s, s1, t, D);
              const double r0 = t[0] + 0.5e6, r1 = t[1] - kbs * (S - u[1]);
              if (std::abs(r0) + std::abs(r1) < 1e-10 * q.cohesion)
                {
                  s = s1;
                  break;
                }
              const double a00 = D[0][0], a01 = D[0][1], a10 = D[1][0],
                           a11 = D[1][1] + kbs;
              const double det = a00 * a11 - a01 * a10;
              u[0] -= (a11 * r0 - a01 * r1) / det;
              u[1] -= (a00 * r1 - a10 * r0) / det;
            }
          converged = converged && it < 30;
          worst_b   = std::max(worst_b, it);
        }
    }
    check(converged && worst_a <= 5 && worst_b <= 5,
          "Newton with the algorithmic tangent: unit + joint in compression "
          "through the cap peak, and under constant normal load in shear "
          "with dilatancy, every step in <= 5 iterations");
  }

  // ---------------------------------------------------------------------
  // Lourenço-Rots penalties: E_b = 10 GPa, E_m = 2 GPa, h_m = 10 mm give
  // k_n = 2.5e11 Pa/m; nu = 0.15 and 0.2: G_b = 4.3478 GPa, G_m = 0.8333 GPa
  void
  check_penalties()
  {
    const auto   k  = CompositeJoint::penalties(10e9, 0.15, 2e9, 0.2, 0.01);
    const double Gb = 10e9 / 2.3, Gm = 2e9 / 2.4;
    check(std::abs(k[0] - 2.5e11) < 1 &&
            std::abs(k[1] - Gb * Gm / (0.01 * (Gb - Gm))) < 1,
          "penalties: k_n = E_b E_m / (h_m (E_b - E_m)) = 2.5e11 Pa/m, "
          "k_s = G_b G_m / (h_m (G_b - G_m))");
    bool threw = false;
    try
      {
        CompositeJoint::penalties(2e9, 0.15, 10e9, 0.2, 0.01);
      }
    catch (const std::invalid_argument &)
      {
        threw = true;
      }
    check(threw, "penalties: a mortar stiffer than the unit is refused");
  }

} // namespace

int
main()
{
  check_elastic();
  check_tension();
  check_shear();
  check_tension_shear_corner();
  check_cap();
  check_shear_cap_corner();
  check_energy_mode_I();
  check_energy_mode_II();
  check_energy_mode_II_compressed();
  check_cap_curve();
  check_crack_closure();
  check_impl_ex();
  check_tangent();
  check_random_paths();
  check_snap_back();
  check_newton();
  check_penalties();
  return all_ok ? 0 : 1;
}
