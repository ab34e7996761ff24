/**
 * @file
 * Lourenço & Rots (1997) composite interface model in 3D: return mapping
 * and algorithmic tangent. See composite_joint.h.
 */
#include <masonry/brickwork/laws/composite_joint.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace masonry
{
  namespace brickwork
  {
    namespace laws
    {
      namespace
      {
        [[noreturn]] void
        bad(const std::string &what)
        {
          throw std::invalid_argument("composite joint: " + what);
        }

        /** Small dense matrices and vectors of the return mapping. */
        using Matrix = Eigen::
          Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor, 5, 5>;
        using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 5, 1>;

        /** LU decomposition with partial pivoting of the leading n x n
         * block of A (n <= 5). */
        Eigen::PartialPivLU<Matrix>
        factorise(const double A[5][5], const unsigned int n)
        {
          return Eigen::PartialPivLU<Matrix>(
            Eigen::Map<
              const Eigen::
                Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>,
              0,
              Eigen::OuterStride<5>>(&A[0][0], n, n));
        }

        /** Whether a pivot of @p lu vanishes (a singular system). */
        bool
        singular(const Eigen::PartialPivLU<Matrix> &lu)
        {
          return !(lu.matrixLU().diagonal().cwiseAbs().minCoeff() > 1e-300);
        }

        /** Solves (LU) x = b for the first n entries of b, x into b. */
        void
        solve(const Eigen::PartialPivLU<Matrix> &lu, double b[5])
        {
          Eigen::Map<Vector> x(b, lu.rows());
          x = lu.solve(Vector(x));
        }

        constexpr unsigned int tension = 1, shear = 2, cap = 4;
      } // namespace

      // -------------------------------------------------------------------
      CompositeJoint::CompositeJoint(const Parameters &parameters)
        : p(parameters)
      {
        auto positive = [](const double v, const char *name) {
          if (!(v > 0) || !std::isfinite(v))
            bad(std::string(name) + " must be positive and finite");
        };
        positive(p.normal_stiffness, "Normal stiffness");
        positive(p.shear_stiffness, "Shear stiffness");
        positive(p.tensile_strength, "Tensile strength");
        positive(p.mode_I_energy, "Mode I fracture energy");
        positive(p.cohesion, "Cohesion");
        positive(p.mode_II_energy, "Mode II fracture energy");
        positive(p.cap_strength, "Cap strength");
        positive(p.cap_Cnn, "Cap Cnn");
        positive(p.cap_Css, "Cap Css");
        positive(p.cap_peak_jump, "Cap peak jump");
        positive(p.cap_energy, "Compressive fracture energy");
        if (!(p.friction >= 0) || !(p.residual_friction >= 0) ||
            !(p.dilatancy >= 0))
          bad("Friction, Residual friction and Dilatancy must be >= 0");
        // the round-off of sigma tan(phi) in the Coulomb yield function,
        // about 1.1e-16 tan(phi) |sigma| with |sigma| up to the cap
        // strength, must stay below the return's tolerance (1e-9 of the cap
        // strength, see admissible()): 1e6 keeps a factor of 10. A steeper
        // cone left no admissible return (the splitting interfaces of a
        // unit whose tensile strength was 1e-300 Pa had tan(phi) = 1e153)
        for (const auto &[value, name] :
             {std::pair<double, const char *>(p.friction, "Friction"),
              std::pair<double, const char *>(p.residual_friction,
                                              "Residual friction")})
          if (value > 1e6)
            {
              std::ostringstream m;
              m << name << " must be at most 1e6 (tan(phi); the return "
                << "mapping's round-off of sigma tan(phi) would exceed its "
                << "tolerance), got " << value;
              bad(m.str());
            }
        if (p.cap_strength < p.tensile_strength)
          bad("Cap strength must not be below Tensile strength (a cap of 1 "
              "Pa left the return mapping without an admissible state)");
        // (to round-off: c / tan(phi) of Mohr-Coulomb through the uniaxial
        // strengths is f_t f_c / (f_c - f_t), which rounds to f_t when f_t
        // is many orders below f_c)
        if (p.tensile_strength * std::max(p.friction, p.residual_friction) >
            p.cohesion * (1 + 1e-12))
          bad("Tensile strength must not exceed Cohesion / Friction (the "
              "tension cut-off would lie beyond the apex of the Coulomb "
              "cone)");
        if (!(p.cap_residual_ratio >= 0 &&
              p.cap_residual_ratio < p.cap_middle_ratio &&
              p.cap_middle_ratio < 1 && p.cap_initial_ratio > 0 &&
              p.cap_initial_ratio < 1))
          bad("cap ratios need 0 < initial < 1 and 0 <= residual < middle "
              "< 1 (fractions of Cap strength)");
        // G_fc = (kappa_m - kappa_p) B, see the header
        const double sp = p.cap_strength, sm = p.cap_middle_ratio * sp,
                     sr = p.cap_residual_ratio * sp;
        const double B =
          sp + (sm - sp) / 3. - sr + (sm - sr) * (sm - sr) / (2. * (sp - sm));
        kappa_m = p.cap_peak_jump + p.cap_energy / B;

        // a softening branch steeper than the elastic penalty snaps back:
        // the jump would have to decrease while the plastic jump grows
        if (p.tensile_strength * p.tensile_strength / p.mode_I_energy >=
            p.normal_stiffness)
          bad("Mode I fracture energy too small for the normal stiffness "
              "(need G_I > f_t0^2 / k_n)");
        if (p.cohesion * p.cohesion / p.mode_II_energy >= p.shear_stiffness)
          bad("Mode II fracture energy too small for the shear stiffness "
              "(need G_II > c0^2 / k_s)");
        if (2 * (sp - sm) /
              ((kappa_m - p.cap_peak_jump) * std::sqrt(p.cap_Cnn)) >=
            p.normal_stiffness)
          bad("Compressive fracture energy too small for the normal "
              "stiffness (the cap softening would snap back: need "
              "2 (sbar_p - sbar_m) / ((kappa_m - kappa_p) sqrt(C_nn)) < "
              "k_n)");
      }

      std::array<double, 2>
      CompositeJoint::penalties(const double E_b,
                                const double nu_b,
                                const double E_m,
                                const double nu_m,
                                const double h_m)
      {
        if (!(h_m > 0))
          bad("Joint thickness must be positive");
        if (!(E_m > 0) || !(E_b > E_m))
          bad("the unit modulus must exceed the mortar modulus (> 0) for "
              "the Lourenco-Rots penalties");
        if (!(nu_b > -1 && nu_b < 0.5 && nu_m > -1 && nu_m < 0.5))
          bad("Poisson ratios must lie in (-1, 0.5)");
        const double G_b = E_b / (2 * (1 + nu_b)), G_m = E_m / (2 * (1 + nu_m));
        if (!(G_b > G_m))
          bad("the unit shear modulus must exceed the mortar's for the "
              "Lourenco-Rots penalties");
        return {
          {E_b * E_m / (h_m * (E_b - E_m)), G_b * G_m / (h_m * (G_b - G_m))}};
      }

      CompositeJointState
      CompositeJoint::extrapolate(const CompositeJointState &old,
                                  const CompositeJointState &older,
                                  const double               ratio) const
      {
        CompositeJointState e = old;
        for (unsigned int i = 0; i < 3; ++i)
          e.plastic_jump[i] +=
            ratio * (old.plastic_jump[i] - older.plastic_jump[i]);
        e.crack_opening =
          std::max(old.crack_opening +
                     ratio * (old.crack_opening - older.crack_opening),
                   0.);
        e.xi = std::max(old.xi + ratio * (old.xi - older.xi), old.xi);
        e.kappa_cap =
          std::max(old.kappa_cap + ratio * (old.kappa_cap - older.kappa_cap),
                   old.kappa_cap);
        return e;
      }

      void
      CompositeJoint::evaluate_frozen(const Vector3             &u,
                                      const CompositeJointState &frozen,
                                      Vector3                   &t,
                                      Matrix3                   &D,
                                      const bool closure_gap) const
      {
        const double kn = p.normal_stiffness, ks = p.shear_stiffness;
        for (auto &row : D)
          row.fill(0.);
        double up_n = frozen.plastic_jump[0];
        D[0][0]     = kn;
        if (closure_gap && p.crack_closure && frozen.crack_opening > 0 &&
            u[0] < up_n)
          {
            // close the crack first, without traction
            up_n = std::max(up_n - frozen.crack_opening, u[0]);
            if (u[0] >= up_n)
              D[0][0] = 0;
          }
        t[0]    = kn * (u[0] - up_n);
        t[1]    = ks * (u[1] - frozen.plastic_jump[1]);
        t[2]    = ks * (u[2] - frozen.plastic_jump[2]);
        D[1][1] = D[2][2] = ks;
      }

      double
      CompositeJoint::cap_yield(const double k) const
      {
        const double sp = p.cap_strength, si = p.cap_initial_ratio * sp,
                     sm = p.cap_middle_ratio * sp,
                     sr = p.cap_residual_ratio * sp, kp = p.cap_peak_jump;
        if (k <= 0)
          return si;
        if (k < kp)
          {
            const double x = k / kp;
            return si + (sp - si) * std::sqrt(std::max(2 * x - x * x, 0.));
          }
        if (k < kappa_m)
          {
            const double h = (k - kp) / (kappa_m - kp);
            return sp + (sm - sp) * h * h;
          }
        const double m = 2 * (sm - sp) / (kappa_m - kp);
        return sr + (sm - sr) * std::exp(m * (k - kappa_m) / (sm - sr));
      }

      double
      CompositeJoint::cap_yield_slope(const double k) const
      {
        const double sp = p.cap_strength, si = p.cap_initial_ratio * sp,
                     sm = p.cap_middle_ratio * sp,
                     sr = p.cap_residual_ratio * sp, kp = p.cap_peak_jump;
        if (k <= 0)
          return (sp - si) / kp * 1e6; // the slope is infinite at 0
        if (k < kp)
          {
            const double x = k / kp;
            return (sp - si) * (1 - x) /
                   (kp * std::sqrt(std::max(2 * x - x * x, 1e-300)));
          }
        if (k < kappa_m)
          return 2 * (sm - sp) * (k - kp) / ((kappa_m - kp) * (kappa_m - kp));
        const double m = 2 * (sm - sp) / (kappa_m - kp);
        return m * std::exp(m * (k - kappa_m) / (sm - sr));
      }

      // -------------------------------------------------------------------
      namespace
      {
        /** The local problem in (sigma, tau >= 0) for one active set. */
        struct Local
        {
          Local(const CompositeJoint &law_,
                const double          sigma_trial_,
                const double          tau_trial_,
                const double          xi0_,
                const double          kappa0_)
            : p(law_.parameters())
            , law(law_)
            , sigma_trial(sigma_trial_)
            , tau_trial(tau_trial_)
            , xi0(xi0_)
            , kappa0(kappa0_)
            , s_ref(std::max({p.tensile_strength, p.cohesion, p.cap_strength}))
            , u_ref(s_ref / p.normal_stiffness)
            , cap_sqrt(kappa0_ < 1e-3 * p.cap_peak_jump)
          {}

          const CompositeJoint::Parameters &p;
          const CompositeJoint             &law;
          double                            sigma_trial, tau_trial;
          double                            xi0, kappa0;
          double                            s_ref, u_ref;
          /** On a (nearly) virgin cap the multiplier is lambda_3 = q^2 with
           * q the unknown: it stays >= 0 and the sqrt hardening of the
           * paper, infinitely steep at kappa_3 = 0, is smooth in q. On a
           * hardened cap lambda_3 = q. */
          bool cap_sqrt;

          // unknowns and results
          unsigned int set      = 0;
          unsigned int n        = 2;            // number of unknowns
          int          index[3] = {-1, -1, -1}; // lambda_a in x, -1: none
          double       x[5]     = {0, 0, 0, 0, 0};
          double       xi = 0, kappa = 0;
          unsigned int iterations = 0;

          /** Scale of the multiplier lambda_a: m for tension and shear
           * (unit flow directions), m/Pa for the cap (flow = lambda_3
           * grad f3, grad f3 in Pa). */
          double
          lambda_scale(const unsigned int a) const
          {
            return a != 2   ? u_ref :
                   cap_sqrt ? std::sqrt(u_ref / s_ref) :
                              u_ref / s_ref;
          }

          double
          lambda(const unsigned int a) const
          {
            return index[a] < 0 ? 0. : x[index[a]];
          }

          /** Yield values at (sigma, tau) with hardening (xi, kappa),
           * scaled by s_ref (f3 by s_ref^2). */
          void
          yield(const double sigma,
                const double tau,
                const double xi_,
                const double kappa_,
                double       f[3]) const
          {
            const double E = std::exp(-xi_);
            const double tanphi =
              p.friction + (p.residual_friction - p.friction) * (1 - E);
            const double sbar = law.cap_yield(kappa_);
            f[0]              = (sigma - p.tensile_strength * E) / s_ref;
            f[1]              = (tau + sigma * tanphi - p.cohesion * E) / s_ref;
            f[2] = (p.cap_Cnn * sigma * sigma + p.cap_Css * tau * tau +
                    p.cap_Cn * sigma - sbar * sbar) /
                   (s_ref * s_ref);
          }

          /** Scaled residual R and scaled Jacobian Js = Dr J Dc at x; with
           * @p exact_slope the cap slope is not regularised at 0. */
          void
          residual(double       R[5],
                   double       Js[5][5],
                   const bool   exact_slope,
                   const double xin[5])
          {
            const double sigma = xin[0], tau = xin[1];
            const double l1  = index[0] < 0 ? 0. : xin[index[0]];
            const double l2  = index[1] < 0 ? 0. : xin[index[1]];
            const double q   = index[2] < 0 ? 0. : xin[index[2]];
            const double l3  = cap_sqrt ? q * q : q;
            const double dl3 = cap_sqrt ? 2 * q : 1.;
            const double a   = p.tensile_strength / p.mode_I_energy,
                         b   = p.cohesion / p.mode_II_energy;
            double dxi1 = 0, dxi2 = 0;
            xi = xi0;
            if (index[0] >= 0 && index[1] >= 0)
              {
                const double s =
                  std::max(std::sqrt(a * a * l1 * l1 + b * b * l2 * l2),
                           1e-300);
                xi += s;
                dxi1 = a * a * l1 / s;
                dxi2 = b * b * l2 / s;
                if (s <= 1e-300)
                  dxi1 = a, dxi2 = b;
              }
            else if (index[0] >= 0)
              xi += a * l1, dxi1 = a;
            else if (index[1] >= 0)
              xi += b * l2, dxi2 = b;
            const double E  = std::exp(-xi);
            const double ft = p.tensile_strength * E, c = p.cohesion * E;
            const double tanphi =
              p.friction + (p.residual_friction - p.friction) * (1 - E);
            const double dtanphi = (p.residual_friction - p.friction) * E;
            const double ns      = 2 * p.cap_Cnn * sigma + p.cap_Cn,
                         nt      = 2 * p.cap_Css * tau;
            const double N       = std::sqrt(ns * ns + nt * nt);
            kappa                = kappa0 + l3 * N;
            double sbar, slope;
            if (!cap_sqrt && l3 < 0)
              {
                // a negative multiplier (rejected at the end) below the
                // hardened state: C1 linear extension for the iterations
                slope = law.cap_yield_slope(kappa0);
                sbar  = law.cap_yield(kappa0) + slope * (kappa - kappa0);
              }
            else
              {
                sbar  = law.cap_yield(kappa);
                slope = law.cap_yield_slope(
                  exact_slope ? kappa :
                                std::max(kappa, 1e-12 * p.cap_peak_jump));
              }
            const double Ninv  = N > 0 ? 1 / N : 0;
            const double dk_ds = l3 * ns * 2 * p.cap_Cnn * Ninv,
                         dk_dt = l3 * nt * 2 * p.cap_Css * Ninv;

            const double kn = p.normal_stiffness, ks = p.shear_stiffness;
            // unscaled residuals and Jacobian
            double r[5], J[5][5];
            for (unsigned int i = 0; i < 5; ++i)
              for (unsigned int j = 0; j < 5; ++j)
                J[i][j] = 0;
            r[0] = (sigma - sigma_trial) / kn + l1 + l2 * p.dilatancy + l3 * ns;
            r[1] = (tau - tau_trial) / ks + l2 + l3 * nt;
            J[0][0] = 1 / kn + l3 * 2 * p.cap_Cnn;
            J[1][1] = 1 / ks + l3 * 2 * p.cap_Css;
            if (index[0] >= 0)
              {
                const int k = index[0];
                J[0][k]     = 1;
                r[k]        = sigma - ft;
                J[k][0]     = 1;
                J[k][k]     = ft * dxi1;
                if (index[1] >= 0)
                  J[k][index[1]] = ft * dxi2;
              }
            if (index[1] >= 0)
              {
                const int k    = index[1];
                J[0][k]        = p.dilatancy;
                J[1][k]        = 1;
                r[k]           = tau + sigma * tanphi - c;
                J[k][0]        = tanphi;
                J[k][1]        = 1;
                const double g = sigma * dtanphi + c;
                J[k][k]        = g * dxi2;
                if (index[0] >= 0)
                  J[k][index[0]] = g * dxi1;
              }
            if (index[2] >= 0)
              {
                const int k = index[2];
                J[0][k]     = ns * dl3;
                J[1][k]     = nt * dl3;
                r[k] = p.cap_Cnn * sigma * sigma + p.cap_Css * tau * tau +
                       p.cap_Cn * sigma - sbar * sbar;
                J[k][0] = ns - 2 * sbar * slope * dk_ds;
                J[k][1] = nt - 2 * sbar * slope * dk_dt;
                J[k][k] = -2 * sbar * slope * N * dl3;
              }
            // scaling
            double Dr[5], Dc[5];
            Dr[0] = Dr[1] = 1 / u_ref;
            Dc[0] = Dc[1] = s_ref;
            for (unsigned int a = 0; a < 3; ++a)
              if (index[a] >= 0)
                {
                  Dr[index[a]] = a == 2 ? 1 / (s_ref * s_ref) : 1 / s_ref;
                  Dc[index[a]] = lambda_scale(a);
                }
            for (unsigned int i = 0; i < n; ++i)
              {
                R[i] = Dr[i] * r[i];
                for (unsigned int j = 0; j < n; ++j)
                  Js[i][j] = Dr[i] * J[i][j] * Dc[j];
              }
          }

          double
          norm(const double R[5]) const
          {
            double s = 0;
            for (unsigned int i = 0; i < n; ++i)
              s += R[i] * R[i];
            return std::sqrt(s);
          }

          /** Newton with backtracking; true if converged. */
          bool
          run(const unsigned int active_set)
          {
            set = active_set;
            n   = 2;
            for (unsigned int a = 0; a < 3; ++a)
              index[a] = (set & (1u << a)) ? int(n++) : -1;
            x[0] = sigma_trial;
            x[1] = tau_trial;
            // start from the perfectly plastic estimate of each multiplier,
            // f_a(trial) / (n_a . D_e m_a) (the trial violation over the
            // elastic slope along the flow), or a small positive value
            double f[3];
            yield(sigma_trial, tau_trial, xi0, kappa0, f);
            const double kn = p.normal_stiffness, ks = p.shear_stiffness;
            const double tanphi0 =
              p.friction +
              (p.residual_friction - p.friction) * (1 - std::exp(-xi0));
            const double ns        = 2 * p.cap_Cnn * sigma_trial + p.cap_Cn,
                         nt        = 2 * p.cap_Css * tau_trial;
            const double slope[3]  = {kn,
                                      ks + kn * tanphi0 * p.dilatancy,
                                      kn * ns * ns + ks * nt * nt};
            const double fscale[3] = {s_ref, s_ref, s_ref * s_ref};
            for (unsigned int a = 0; a < 3; ++a)
              if (index[a] >= 0)
                {
                  double l = slope[a] > 0 ?
                               std::max(f[a], 0.) * fscale[a] / slope[a] :
                               0.;
                  if (a == 2 && cap_sqrt)
                    l = std::sqrt(l);
                  x[index[a]] = std::max(l,
                                         (a == 2 && cap_sqrt ? 0.1 : 1e-3) *
                                           lambda_scale(a));
                }
            double R[5], Js[5][5];
            residual(R, Js, false, x);
            double r0 = norm(R);
            for (iterations = 0; iterations < 60; ++iterations)
              {
                if (r0 < 1e-13)
                  return true;
                double dx[5];
                for (unsigned int i = 0; i < n; ++i)
                  dx[i] = -R[i];
                const auto lu = factorise(Js, n);
                if (singular(lu))
                  return false;
                solve(lu, dx);
                // unscale: x = Dc y
                dx[0] *= s_ref;
                dx[1] *= s_ref;
                for (unsigned int a = 0; a < 3; ++a)
                  if (index[a] >= 0)
                    dx[index[a]] *= lambda_scale(a);
                double alpha = 1, trial[5], r1 = 0;
                for (unsigned int ls = 0; ls < 30; ++ls)
                  {
                    for (unsigned int i = 0; i < n; ++i)
                      trial[i] = x[i] + alpha * dx[i];
                    residual(R, Js, false, trial);
                    r1 = norm(R);
                    if (std::isfinite(r1) && r1 <= (1 - 1e-4 * alpha) * r0)
                      break;
                    alpha *= 0.5;
                  }
                if (!std::isfinite(r1))
                  return false;
                for (unsigned int i = 0; i < n; ++i)
                  x[i] = trial[i];
                r0 = r1;
              }
            return r0 < 1e-10;
          }

          /** Whether the converged return is admissible. */
          bool
          admissible() const
          {
            if (x[1] < -1e-12 * s_ref)
              return false;
            for (unsigned int a = 0; a < 3; ++a)
              if (index[a] >= 0 &&
                  !(a == 2 && cap_sqrt ? x[index[a]] * x[index[a]] > 0 :
                                         x[index[a]] > 0))
                return false;
            double f[3];
            yield(x[0], x[1], xi, kappa, f);
            for (unsigned int a = 0; a < 3; ++a)
              if (index[a] < 0 && f[a] > 1e-9)
                return false;
            return true;
          }
        };
      } // namespace

      void
      CompositeJoint::evaluate(const Vector3             &u,
                               const CompositeJointState &old,
                               CompositeJointState       &updated,
                               Vector3                   &t,
                               Matrix3                   &D,
                               CompositeJointActive      *active) const
      {
        CompositeJointActive info;
        if (step(u, old, updated, t, D, info))
          {
            if (active)
              *active = info;
            return;
          }
        // No admissible closest-point return in one step (possible with the
        // non-associated friction at the shear-cap corner of a softened
        // cap): integrate along the straight path from the unloaded state
        // (zero traction at u = u_p) to u in 2, 4, ... 64 substeps. The
        // tangent is then that of the last substep.
        for (unsigned int n = 2; n <= 64; n *= 2)
          {
            CompositeJointState state = old;
            bool                ok    = true;
            for (unsigned int k = 1; k <= n && ok; ++k)
              {
                Vector3 uk;
                for (unsigned int i = 0; i < 3; ++i)
                  uk[i] = old.plastic_jump[i] +
                          double(k) / n * (u[i] - old.plastic_jump[i]);
                CompositeJointActive sub;
                ok = step(uk, state, updated, t, D, sub);
                info.iterations += sub.iterations;
                if (ok)
                  {
                    state        = updated;
                    info.tension = sub.tension;
                    info.shear   = sub.shear;
                    info.cap     = sub.cap;
                    info.crack_closing =
                      info.crack_closing || sub.crack_closing;
                  }
              }
            if (ok)
              {
                info.substeps = n;
                if (active)
                  *active = info;
                return;
              }
          }
        std::ostringstream m;
        m << "composite joint: no admissible return from jump (" << u[0] << ", "
          << u[1] << ", " << u[2]
          << ") m, even in 64 substeps from the unloaded state";
        throw std::runtime_error(m.str());
      }

      bool
      CompositeJoint::step(const Vector3             &u,
                           const CompositeJointState &old,
                           CompositeJointState       &updated,
                           Vector3                   &t,
                           Matrix3                   &D,
                           CompositeJointActive      &info) const
      {
        const double kn = p.normal_stiffness, ks = p.shear_stiffness;
        updated = old;

        // crack closure: an open tensile crack closes without traction
        double sigma_trial     = kn * (u[0] - old.plastic_jump[0]);
        double dsigma_trial_du = kn;
        if (p.crack_closure && old.crack_opening > 0 && sigma_trial < 0)
          {
            const double closing =
              std::min(old.crack_opening, -sigma_trial / kn);
            updated.crack_opening -= closing;
            updated.plastic_jump[0] -= closing;
            info.crack_closing = true;
            if (updated.crack_opening > 0)
              {
                sigma_trial     = 0; // still open: no normal traction
                dsigma_trial_du = 0;
              }
            else
              {
                updated.crack_opening = 0;
                sigma_trial           = kn * (u[0] - updated.plastic_jump[0]);
              }
          }
        const double ts1       = ks * (u[1] - old.plastic_jump[1]),
                     ts2       = ks * (u[2] - old.plastic_jump[2]);
        const double tau_trial = std::sqrt(ts1 * ts1 + ts2 * ts2);

        Local  L(*this, sigma_trial, tau_trial, old.xi, old.kappa_cap);
        double f[3];
        L.yield(sigma_trial, tau_trial, old.xi, old.kappa_cap, f);

        double A[2][2] = {{1, 0}, {0, 1}}; // d(sigma, tau)/d(trial)
        double sigma = sigma_trial, tau = tau_trial;
        if (f[0] > 1e-12 || f[1] > 1e-12 || f[2] > 1e-12)
          {
            // candidate active sets: the violated singles (largest first),
            // then the corners touching a violated surface, then all
            unsigned int candidates[16], nc = 0;
            unsigned int order[3] = {0, 1, 2};
            std::sort(order, order + 3, [&](unsigned int i, unsigned int j) {
              return f[i] > f[j];
            });
            for (unsigned int k = 0; k < 3; ++k)
              if (f[order[k]] > 1e-12)
                candidates[nc++] = 1u << order[k];
            if (f[0] > 1e-12 || f[1] > 1e-12)
              candidates[nc++] = tension | shear;
            if (f[1] > 1e-12 || f[2] > 1e-12)
              candidates[nc++] = shear | cap;
            // a cap softened below the tensile strength (it is centred at
            // sigma = -C_n / (2 C_nn)) can meet the tension cut-off too
            for (const unsigned int s : {tension,
                                         shear,
                                         cap,
                                         tension | shear,
                                         shear | cap,
                                         tension | cap,
                                         tension | shear | cap})
              candidates[nc++] = s;
            bool done = false;
            for (unsigned int k = 0; k < nc && !done; ++k)
              {
                if (!L.run(candidates[k]))
                  continue;
                info.iterations += L.iterations;
                if (L.admissible())
                  done = true;
              }
            if (!done)
              return false;
            sigma             = L.x[0];
            tau               = std::max(L.x[1], 0.);
            info.tension      = L.index[0] >= 0;
            info.shear        = L.index[1] >= 0;
            info.cap          = L.index[2] >= 0;
            updated.xi        = L.xi;
            updated.kappa_cap = L.kappa;
            updated.crack_opening += L.lambda(0);

            // algorithmic tangent: d x / d trial = J^-1 (-dR/d trial)
            double R[5], Js[5][5];
            L.residual(R, Js, true, L.x);
            const auto lu = factorise(Js, L.n);
            if (singular(lu))
              return false;
            for (unsigned int col = 0; col < 2; ++col)
              {
                // dR/d sigma_trial = -1/kn on row 0 (scaled: -1/(kn u_ref))
                double rhs[5] = {0, 0, 0, 0, 0};
                rhs[col]      = (col == 0 ? 1 / kn : 1 / ks) / L.u_ref;
                solve(lu, rhs);
                A[0][col] = rhs[0] * L.s_ref;
                A[1][col] = rhs[1] * L.s_ref;
              }
          }

        // back to 3D
        t[0] = sigma;
        for (auto &row : D)
          row.fill(0.);
        D[0][0] = A[0][0] * dsigma_trial_du;
        if (tau_trial > 0)
          {
            const double e[2] = {ts1 / tau_trial, ts2 / tau_trial};
            t[1]              = tau * e[0];
            t[2]              = tau * e[1];
            const double r    = tau / tau_trial;
            for (unsigned int i = 0; i < 2; ++i)
              {
                D[0][1 + i] = A[0][1] * ks * e[i];
                D[1 + i][0] = A[1][0] * dsigma_trial_du * e[i];
                for (unsigned int j = 0; j < 2; ++j)
                  D[1 + i][1 + j] = A[1][1] * ks * e[i] * e[j] +
                                    r * ks * ((i == j) - e[i] * e[j]);
              }
          }
        else
          {
            t[1] = t[2] = 0;
            D[1][1] = D[2][2] = A[1][1] * ks;
          }

        // the plastic jump follows from t = D_e (u - u_p)
        updated.plastic_jump[0] = u[0] - t[0] / kn;
        updated.plastic_jump[1] = u[1] - t[1] / ks;
        updated.plastic_jump[2] = u[2] - t[2] / ks;
        return true;
      }
    } // namespace laws
  }   // namespace brickwork
} // namespace masonry
