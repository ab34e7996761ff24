#include <masonry/lp/interface.h>
#include <masonry/rigid_blocks/interface_model.h>
#include <masonry/rigid_blocks/mechanism.h>
#include <masonry/rigid_blocks/output.h>

#include <algorithm>
#include <cmath>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace
    {
      /**
       * One contact row before it enters the LP: its coefficients on the
       * six columns of the first block (0–5) and of the second (6–11), its
       * right-hand side, and whether it is an equality (else row ≥ rhs).
       */
      struct ContactRow
      {
        std::array<double, 12> a{};
        double                 rhs      = 0;
        bool                   equality = true;
        /** Index of the contact point in the interface, and direction. */
        unsigned int point = 0, k = 0;
      };

      double
      max_abs(const std::array<double, 13> &v)
      {
        double m = 0;
        for (const double x : v)
          m = std::max(m, std::abs(x));
        return m;
      }

      /** The row with its right-hand side appended. */
      std::array<double, 13>
      augmented(const ContactRow &row)
      {
        std::array<double, 13> v;
        std::copy(row.a.begin(), row.a.end(), v.begin());
        v[12] = row.rhs;
        return v;
      }

      /**
       * Relative tolerance below which a row counts as implied by others:
       * the coefficients come from the geometry with round-off of ~1e-15,
       * and a dropped row then holds to this fraction of the velocities.
       */
      constexpr double implied_tolerance = 1e-11;

      /**
       * Largest sum of |weights| of the kept rows that imply a dropped one:
       * the solver satisfies the kept rows to its tolerance only, which a
       * dropped row then meets to this multiple of it.
       */
      constexpr double largest_weight = 4;

      /**
       * Whether inequality row @p r (a·x ≥ rhs) follows from the
       * inequality rows @p others: a = Σ w_j a_j with w_j ≥ 0 for one, two
       * or three of them, and rhs ≤ Σ w_j rhs_j. The weights come from
       * least squares and the identity is then verified.
       */
      bool
      implied_inequality(const ContactRow                      &r,
                         const std::vector<const ContactRow *> &others)
      {
        const unsigned int n     = others.size();
        double             scale = 0;
        for (const double x : r.a)
          scale = std::max(scale, std::abs(x));
        if (scale == 0)
          return false;
        const double tolerance = implied_tolerance * scale;
        auto         check     = [&](const std::vector<unsigned int> &set) {
          const unsigned int m = set.size();
          // normal equations G w = b of the least-squares fit
          double G[3][3], b[3], w[3];
          for (unsigned int i = 0; i < m; ++i)
            {
              b[i] = 0;
              for (unsigned int d = 0; d < 12; ++d)
                b[i] += others[set[i]]->a[d] * r.a[d];
              for (unsigned int j = 0; j < m; ++j)
                {
                  G[i][j] = 0;
                  for (unsigned int d = 0; d < 12; ++d)
                    G[i][j] += others[set[i]]->a[d] * others[set[j]]->a[d];
                }
            }
          // Gaussian elimination without pivoting on the (small, positive
          // semi-definite) Gram matrix; a tiny pivot means dependent rows
          for (unsigned int i = 0; i < m; ++i)
            {
              if (!(G[i][i] > 1e-12 * scale * scale))
                return false;
              for (unsigned int j = i + 1; j < m; ++j)
                {
                  const double f = G[j][i] / G[i][i];
                  for (unsigned int l = i; l < m; ++l)
                    G[j][l] -= f * G[i][l];
                  b[j] -= f * b[i];
                }
            }
          double sum = 0;
          for (int i = m - 1; i >= 0; --i)
            {
              w[i] = b[i];
              for (unsigned int l = i + 1; l < m; ++l)
                w[i] -= G[i][l] * w[l];
              w[i] /= G[i][i];
              if (w[i] < 0)
                return false;
              sum += w[i];
            }
          if (sum > largest_weight)
            return false;
          // verify: coefficients reproduced, right-hand side not weaker
          double rhs = 0;
          for (unsigned int d = 0; d < 12; ++d)
            {
              double v = r.a[d];
              for (unsigned int i = 0; i < m; ++i)
                v -= w[i] * others[set[i]]->a[d];
              if (std::abs(v) > tolerance)
                return false;
            }
          for (unsigned int i = 0; i < m; ++i)
            rhs += w[i] * others[set[i]]->rhs;
          return r.rhs <= rhs + tolerance * std::max(1., std::abs(rhs));
        };
        for (unsigned int i = 0; i < n; ++i)
          {
            if (check({i}))
              return true;
            for (unsigned int j = i + 1; j < n; ++j)
              {
                if (check({i, j}))
                  return true;
                for (unsigned int l = j + 1; l < n; ++l)
                  if (check({i, j, l}))
                    return true;
              }
          }
        return false;
      }

      /**
       * Which of the rows of one interface (all without plastic
       * multipliers) the LP needs: an equality row is dropped if it is,
       * with its right-hand side, a linear combination of the equality rows
       * kept before it (Gram–Schmidt); an inequality row if it is a
       * nonnegative combination of at most three other inequality rows
       * still kept, with a right-hand side that is not stronger. Each
       * dropped row thus follows from the kept ones, so the feasible set
       * and the optimum do not change.
       */
      std::vector<bool>
      needed_rows(const std::vector<ContactRow> &rows)
      {
        std::vector<bool> keep(rows.size(), true);
        // Gram-Schmidt on the augmented equality rows [a, rhs]: the
        // orthonormal basis q_k and the triangular R with row_k = Σ R_jk q_j
        std::vector<std::array<double, 13>> basis;
        std::vector<std::vector<double>>    R;
        for (unsigned int r = 0; r < rows.size(); ++r)
          if (rows[r].equality)
            {
              auto         v     = augmented(rows[r]);
              const double scale = max_abs(v);
              if (scale == 0)
                {
                  keep[r] = false; // 0 = 0
                  continue;
                }
              std::vector<double> c(basis.size(), 0.);
              for (unsigned int pass = 0; pass < 2; ++pass)
                for (unsigned int j = 0; j < basis.size(); ++j)
                  {
                    double dot = 0;
                    for (unsigned int d = 0; d < 13; ++d)
                      dot += basis[j][d] * v[d];
                    for (unsigned int d = 0; d < 13; ++d)
                      v[d] -= dot * basis[j][d];
                    c[j] += dot;
                  }
              const double residual = max_abs(v) / scale;
              if (residual <= implied_tolerance)
                {
                  // row = Σ w_k row_k over the rows of the basis: dropped
                  // only with moderate weights, since the solver satisfies
                  // the kept rows to its tolerance only
                  std::vector<double> w(basis.size(), 0.);
                  double              sum = 0;
                  for (int k = basis.size() - 1; k >= 0; --k)
                    {
                      double x = c[k];
                      for (unsigned int l = k + 1; l < basis.size(); ++l)
                        x -= R[l][k] * w[l];
                      w[k] = x / R[k][k];
                      sum += std::abs(w[k]);
                    }
                  if (sum <= largest_weight)
                    keep[r] = false;
                }
              else if (residual >= 1e-3)
                {
                  // a well-conditioned new direction (rows between the two
                  // thresholds are kept, outside the basis)
                  double norm = 0;
                  for (const double x : v)
                    norm += x * x;
                  norm = std::sqrt(norm);
                  for (double &x : v)
                    x /= norm;
                  basis.push_back(v);
                  c.push_back(norm);
                  // R[k][j] for j <= k: the coefficients of row k
                  R.push_back(c);
                }
            }
        for (unsigned int r = 0; r < rows.size(); ++r)
          if (!rows[r].equality)
            {
              std::vector<const ContactRow *> others;
              for (unsigned int s = 0; s < rows.size(); ++s)
                if (s != r && keep[s] && !rows[s].equality)
                  others.push_back(&rows[s]);
              if (implied_inequality(rows[r], others))
                keep[r] = false;
            }
        return keep;
      }
    } // namespace


    MechanismProblem
    build_mechanism_problem(const BlockModel     &model,
                            const InterfaceModel &joints,
                            const SupportMotion  &u0,
                            const bool            bonded_supports,
                            const bool            leave_out_implied_rows)
    {
      const auto &blocks     = model.blocks();
      const auto &interfaces = model.interfaces();

      MechanismProblem problem;
      problem.length          = model.length_scale();
      problem.n_block_columns = 6 * blocks.size();
      const double length     = problem.length;
      auto        &lp         = problem.lp;
      const double inf        = lp::infinity;
      for (unsigned int c = 0; c < problem.n_block_columns; ++c)
        lp.add_column(0, -inf, inf);

      // m·v_b(x) for the rigid motion of block b, in scaled columns, into
      // a[offset ... offset + 5]
      auto velocity = [&](std::array<double, 12>     &a,
                          const unsigned int          offset,
                          const unsigned int          b,
                          const dealii::Tensor<1, 3> &m,
                          const dealii::Point<3>     &x,
                          const double                sign) {
        const dealii::Tensor<1, 3> r  = x - blocks[b].centroid;
        const dealii::Tensor<1, 3> rm = dealii::cross_product_3d(r, m) / length;
        for (unsigned int d = 0; d < 3; ++d)
          {
            a[offset + d]     = sign * m[d];
            a[offset + 3 + d] = sign * rm[d];
          }
      };

      const bool  direct = joints.no_tension_no_sliding();
      const auto &planes = joints.yield_planes();
      problem.point_rows.reserve(model.n_contact_points());
      std::vector<ContactRow> rows;
      for (const auto &i : interfaces)
        {
          const bool support = i.second == Interface::support;
          const bool rigid   = support && bonded_supports;
          rows.clear();
          for (unsigned int p = 0; p < i.points.size(); ++p)
            {
              const auto                               &c     = i.points[p];
              const std::array<dealii::Tensor<1, 3>, 3> frame = {
                {c.normal, c.across, c.along}};
              // jump = v_second − v_first, or u0 − v_first at a support:
              // rows hold the velocity part, bounds the ground motion
              dealii::Tensor<1, 3> ground;
              if (support && u0)
                ground = u0(c.position, i.support_label);
              for (unsigned int k = 0; k < 3; ++k)
                {
                  ContactRow row;
                  row.rhs      = -(frame[k] * ground);
                  row.equality = rigid || (!direct) || k > 0;
                  row.point    = p;
                  row.k        = k;
                  if (!support)
                    velocity(row.a, 6, i.second, frame[k], c.position, 1);
                  velocity(row.a, 0, i.first, frame[k], c.position, -1);
                  // entries are O(1); drop the round-off of unit vectors
                  // (1e-17), which would otherwise wreck the solvers'
                  // scaling
                  for (double &x : row.a)
                    if (std::abs(x) <= 1e-13)
                      x = 0;
                  rows.push_back(row);
                }
            }
          // without plastic multipliers (no tension no sliding, bonded
          // supports) rows that follow from the others are left out
          const bool        reducible = rigid || direct;
          std::vector<bool> keep(rows.size(), true);
          if (reducible && leave_out_implied_rows)
            keep = needed_rows(rows);
          const unsigned int first_point = problem.point_rows.size();
          problem.point_rows.resize(first_point + i.points.size(),
                                    {{-1, -1, -1}});
          for (unsigned int r = 0; r < rows.size(); ++r)
            {
              if (!keep[r])
                continue;
              const auto        &row   = rows[r];
              const unsigned int index = row.equality ?
                                           lp.add_row(row.rhs, row.rhs) :
                                           lp.add_row(row.rhs, inf);
              problem.point_rows[first_point + row.point][row.k] = index;
              for (const unsigned int offset : {6u, 0u})
                {
                  if (offset == 6 && support)
                    continue;
                  const unsigned int b = offset == 6 ? i.second : i.first;
                  for (unsigned int d = 0; d < 3; ++d)
                    {
                      if (row.a[offset + d] != 0)
                        lp.add_entry(index, 6 * b + d, row.a[offset + d]);
                      if (row.a[offset + 3 + d] != 0)
                        lp.add_entry(index,
                                     6 * b + 3 + d,
                                     row.a[offset + 3 + d]);
                    }
                }
              if (reducible || row.k < 2)
                continue;
              // after the point's three rows: jump − Σ λ_j a_j = 0
              const auto &c = i.points[row.point];
              for (const auto &plane : planes)
                {
                  const unsigned int col = lp.add_column(0, 0, inf);
                  problem.dissipation.resize(col + 1, 0.);
                  problem.dissipation[col] = c.area * plane.b;
                  for (unsigned int k = 0; k < 3; ++k)
                    if (plane.a[k] != 0)
                      lp.add_entry(
                        problem.point_rows[first_point + row.point][k],
                        col,
                        -plane.a[k]);
                }
            }
        }
      problem.dissipation.resize(lp.n_columns(), 0.);
      return problem;
    }

    std::vector<double>
    load_work(const std::vector<dealii::Tensor<1, 3>> &force,
              const std::vector<dealii::Tensor<1, 3>> &moment,
              const double                             length,
              const double                             force_scale)
    {
      std::vector<double> c(6 * force.size(), 0.);
      for (unsigned int b = 0; b < force.size(); ++b)
        for (unsigned int d = 0; d < 3; ++d)
          {
            c[6 * b + d]     = force[b][d] / force_scale;
            c[6 * b + 3 + d] = moment[b][d] / (force_scale * length);
          }
      return c;
    }

    Motion
    motion_from_solution(const MechanismProblem    &problem,
                         const std::vector<double> &x,
                         const double               velocity_scale)
    {
      const unsigned int n_blocks = problem.n_block_columns / 6;
      Motion             motion(n_blocks);
      for (unsigned int b = 0; b < n_blocks; ++b)
        for (unsigned int d = 0; d < 3; ++d)
          {
            motion.translation[b][d] = x[6 * b + d] * velocity_scale;
            motion.rotation[b][d] =
              x[6 * b + 3 + d] * velocity_scale / problem.length;
          }
      return motion;
    }

    std::vector<std::array<double, 3>>
    contact_forces(const MechanismProblem &problem,
                   const lp::Solution     &solution,
                   const double            force_scale,
                   const bool              maximised)
    {
      const double sign = maximised ? -force_scale : force_scale;
      std::vector<std::array<double, 3>> forces;
      forces.reserve(problem.point_rows.size());
      for (const auto &rows : problem.point_rows)
        {
          std::array<double, 3> f = {{0., 0., 0.}};
          for (unsigned int k = 0; k < 3; ++k)
            if (rows[k] >= 0 &&
                static_cast<unsigned int>(rows[k]) < solution.row_duals.size())
              f[k] = sign * solution.row_duals[rows[k]];
          forces.push_back(f);
        }
      return forces;
    }

    double
    dissipated(const MechanismProblem &problem, const std::vector<double> &x)
    {
      double d = 0;
      for (unsigned int c = problem.n_block_columns; c < x.size(); ++c)
        d += problem.dissipation[c] * x[c];
      return d;
    }
  } // namespace rigid_blocks
} // namespace masonry
