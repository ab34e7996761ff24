#include <masonry/lp/interface.h>
#include <masonry/rigid_blocks/interface_model.h>
#include <masonry/rigid_blocks/mechanism.h>
#include <masonry/rigid_blocks/output.h>

#include <cmath>

namespace masonry
{
  namespace rigid_blocks
  {
    MechanismProblem
    build_mechanism_problem(const BlockModel     &model,
                            const InterfaceModel &joints,
                            const SupportMotion  &u0,
                            const bool            bonded_supports)
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

      // m·v_b(x) for the rigid motion of block b, in scaled columns
      auto add_velocity = [&](const unsigned int          row,
                              const unsigned int          b,
                              const dealii::Tensor<1, 3> &m,
                              const dealii::Point<3>     &x,
                              const double                sign) {
        const dealii::Tensor<1, 3> r  = x - blocks[b].centroid;
        const dealii::Tensor<1, 3> rm = dealii::cross_product_3d(r, m) / length;
        // entries are O(1); drop the round-off of unit vectors (1e-17),
        // which would otherwise wreck the solvers' scaling
        for (unsigned int d = 0; d < 3; ++d)
          {
            if (std::abs(m[d]) > 1e-13)
              lp.add_entry(row, 6 * b + d, sign * m[d]);
            if (std::abs(rm[d]) > 1e-13)
              lp.add_entry(row, 6 * b + 3 + d, sign * rm[d]);
          }
      };

      const bool  direct = joints.no_tension_no_sliding();
      const auto &planes = joints.yield_planes();
      for (const auto &i : interfaces)
        for (const auto &c : i.points)
          {
            const std::array<dealii::Tensor<1, 3>, 3> frame = {c.normal,
                                                               c.across,
                                                               c.along};
            const bool support = i.second == Interface::support;
            const bool rigid   = support && bonded_supports;
            // jump = v_second − v_first, or u0 − v_first at a support:
            // rows hold the velocity part, bounds the ground motion
            dealii::Tensor<1, 3> ground;
            if (support && u0)
              ground = u0(c.position, i.support_label);
            std::array<unsigned int, 3> rows;
            for (unsigned int k = 0; k < 3; ++k)
              {
                const double rhs = -(frame[k] * ground);
                if (rigid || (!direct) || k > 0)
                  rows[k] = lp.add_row(rhs, rhs);
                else
                  rows[k] = lp.add_row(rhs, inf);
                if (!support)
                  add_velocity(rows[k], i.second, frame[k], c.position, 1);
                add_velocity(rows[k], i.first, frame[k], c.position, -1);
              }
            if (rigid || direct)
              continue;
            // jump − Σ λ_j a_j = 0
            for (const auto &plane : planes)
              {
                const unsigned int col = lp.add_column(0, 0, inf);
                problem.dissipation.resize(col + 1, 0.);
                problem.dissipation[col] = c.area * plane.b;
                for (unsigned int k = 0; k < 3; ++k)
                  if (plane.a[k] != 0)
                    lp.add_entry(rows[k], col, -plane.a[k]);
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
    contact_forces(const lp::Solution &solution,
                   const double        force_scale,
                   const bool          maximised)
    {
      const double sign = maximised ? -force_scale : force_scale;
      std::vector<std::array<double, 3>> forces;
      forces.reserve(solution.row_duals.size() / 3);
      for (unsigned int r = 0; r + 2 < solution.row_duals.size(); r += 3)
        forces.push_back({sign * solution.row_duals[r],
                          sign * solution.row_duals[r + 1],
                          sign * solution.row_duals[r + 2]});
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
