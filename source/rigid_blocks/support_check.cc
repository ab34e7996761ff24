/**
 * @file
 * The direct check of a prescribed support motion (support_check.h).
 */
#include <masonry/geometry/interface.h>
#include <masonry/rigid_blocks/interface_model.h>
#include <masonry/rigid_blocks/support_check.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <numeric>
#include <sstream>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace
    {
      using Vector3 = Eigen::Vector3d;

      /**
       * The jumps a joint admits: the cone K spanned by the normals a_k of
       * its yield planes (associative flow rule: [u] = Σ λ_k a_k, λ_k ≥ 0),
       * in the contact point's local frame (normal, across, along).
       */
      class JumpCone
      {
      public:
        explicit JumpCone(const std::vector<YieldPlane> &planes)
        {
          generators.resize(3, planes.size());
          for (unsigned int k = 0; k < planes.size(); ++k)
            {
              const Vector3 a(planes[k].a[0], planes[k].a[1], planes[k].a[2]);
              generators.col(k) = a / a.norm();
            }
          // the components orthogonal to span(K) are fixed: the null space
          // of the Gram matrix of the generators
          const Eigen::Matrix3d gram = generators * generators.transpose();
          const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(gram);
          const double largest = std::max(eigen.eigenvalues().maxCoeff(), 0.);
          for (unsigned int i = 0; i < 3; ++i)
            if (!(eigen.eigenvalues()[i] > 1e-12 * std::max(largest, 1.)))
              fixed.push_back(eigen.eigenvectors().col(i));
          // K is all of R^3 if it holds the six coordinate directions
          everything = fixed.empty();
          for (unsigned int i = 0; i < 3 && everything; ++i)
            for (const double sign : {-1., 1.})
              everything =
                everything && distance(sign * Vector3::Unit(i)) < 1e-12;
        }

        /** The distance of the jump @p j (local frame) from K. */
        double
        distance(const Vector3 &j) const
        {
          return (j - generators * nnls(j)).norm();
        }

        /** Unit directions (local frame) in which a jump must vanish. */
        std::vector<Vector3> fixed;
        /** Whether K is all of R^3 (every jump admitted). */
        bool everything = false;

      private:
        /** Normalised plane normals, one per column. */
        Eigen::Matrix<double, 3, Eigen::Dynamic> generators;

        /**
         * The nonnegative weights λ that minimise |A λ − j| (Lawson and
         * Hanson's active-set method; A the generators).
         */
        Eigen::VectorXd
        nnls(const Vector3 &j) const
        {
          const unsigned int m      = generators.cols();
          Eigen::VectorXd    lambda = Eigen::VectorXd::Zero(m);
          std::vector<bool>  active(m, false);
          const double       tiny = 1e-14 * std::max(j.norm(), 1e-300);
          // the least-squares weights on the active columns, others zero
          const auto solve = [&]() {
            std::vector<unsigned int> set;
            for (unsigned int k = 0; k < m; ++k)
              if (active[k])
                set.push_back(k);
            Eigen::MatrixXd a(3, set.size());
            for (unsigned int i = 0; i < set.size(); ++i)
              a.col(i) = generators.col(set[i]);
            const Eigen::VectorXd s =
              a.completeOrthogonalDecomposition().solve(j);
            Eigen::VectorXd z = Eigen::VectorXd::Zero(m);
            for (unsigned int i = 0; i < set.size(); ++i)
              z[set[i]] = s[i];
            return z;
          };
          for (unsigned int outer = 0; outer < 3 * m + 3; ++outer)
            {
              const Eigen::VectorXd w =
                generators.transpose() * (j - generators * lambda);
              int    best  = -1;
              double value = tiny;
              for (unsigned int k = 0; k < m; ++k)
                if (!active[k] && w[k] > value)
                  {
                    best  = k;
                    value = w[k];
                  }
              if (best < 0)
                break;
              active[best] = true;
              for (unsigned int inner = 0; inner < m + 1; ++inner)
                {
                  const Eigen::VectorXd z       = solve();
                  double                alpha   = 1;
                  bool                  clipped = false;
                  for (unsigned int k = 0; k < m; ++k)
                    if (active[k] && z[k] <= 0)
                      {
                        clipped        = true;
                        const double d = lambda[k] - z[k];
                        if (d > 0)
                          alpha = std::min(alpha, lambda[k] / d);
                        else
                          alpha = 0;
                      }
                  if (!clipped)
                    {
                      lambda = z;
                      break;
                    }
                  lambda += alpha * (z - lambda);
                  for (unsigned int k = 0; k < m; ++k)
                    if (active[k] && lambda[k] <= tiny)
                      {
                        active[k] = false;
                        lambda[k] = 0;
                      }
                }
            }
          return lambda;
        }
      };

      /** A row of a rigid-motion fit: the component of the motion at
       * @p x along the unit vector @p e equals @p target. */
      struct FitRow
      {
        Vector3 e;
        Vector3 x;
        double  target;
        /** Index of the contact point (in the group's list) it belongs
         * to. */
        unsigned int point;
      };

      /** A rigid motion v(x) = t + θ × (x − origin). */
      struct RigidMotion
      {
        Vector3 t = Vector3::Zero(), theta = Vector3::Zero(),
                origin = Vector3::Zero();
        Vector3
        at(const Vector3 &x) const
        {
          return t + theta.cross(x - origin);
        }
      };

      /** The least-squares rigid motion of @p rows: the motion, its rank
       * and the residual of every row. */
      struct Fit
      {
        RigidMotion         motion;
        unsigned int        rank = 0;
        std::vector<double> residual;
      };

      Fit
      fit_rigid_motion(const std::vector<FitRow> &rows, const double length)
      {
        Fit fit;
        if (rows.empty())
          return fit;
        for (const auto &r : rows)
          fit.motion.origin += r.x;
        fit.motion.origin /= rows.size();
        // columns: translation, rotation × length (entries O(1))
        Eigen::MatrixXd a(rows.size(), 6);
        Eigen::VectorXd b(rows.size());
        for (unsigned int i = 0; i < rows.size(); ++i)
          {
            const Vector3 r     = rows[i].x - fit.motion.origin;
            a.block<1, 3>(i, 0) = rows[i].e.transpose();
            a.block<1, 3>(i, 3) = r.cross(rows[i].e).transpose() / length;
            b[i]                = rows[i].target;
          }
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> qr(a);
        qr.setThreshold(1e-10);
        const Eigen::VectorXd s        = qr.solve(b);
        fit.rank                       = qr.rank();
        fit.motion.t                   = s.head<3>();
        fit.motion.theta               = s.tail<3>() / length;
        const Eigen::VectorXd residual = a * s - b;
        fit.residual.assign(residual.data(), residual.data() + rows.size());
        return fit;
      }

      Vector3
      to_eigen(const dealii::Tensor<1, 3> &v)
      {
        return Vector3(v[0], v[1], v[2]);
      }

      /** The local frame of a contact point, one axis per row. */
      Eigen::Matrix3d
      frame(const ContactPoint &c)
      {
        Eigen::Matrix3d f;
        f.row(0) = to_eigen(c.normal).transpose();
        f.row(1) = to_eigen(c.across).transpose();
        f.row(2) = to_eigen(c.along).transpose();
        return f;
      }

      /** Union-find of blocks. */
      struct Groups
      {
        explicit Groups(const unsigned int n)
          : parent(n)
        {
          std::iota(parent.begin(), parent.end(), 0u);
        }
        unsigned int
        find(unsigned int b)
        {
          while (parent[b] != b)
            b = parent[b] = parent[parent[b]];
          return b;
        }
        void
        join(const unsigned int a, const unsigned int b)
        {
          parent[find(a)] = find(b);
        }
        std::vector<unsigned int> parent;
      };

      std::string
      format_point(const dealii::Point<3> &p)
      {
        std::ostringstream s;
        s << std::setprecision(4) << "(" << p[0] << ", " << p[1] << ", " << p[2]
          << ")";
        return s.str();
      }

      /**
       * The ground's displacement (m) by @p u0 at the point @p c of the
       * support interface @p i (zero without a support motion).
       */
      Vector3
      ground_motion(const SupportMotion &u0,
                    const Interface     &i,
                    const ContactPoint  &c)
      {
        return u0 ? to_eigen(u0(c.position, i.support_label)) :
                    Vector3(Vector3::Zero());
      }

      /** Block @p b of @p model (its patch and centroid) into @p x. */
      void
      describe_block(Incompatibility   &x,
                     const BlockModel  &model,
                     const unsigned int b)
      {
        const auto &blocks  = model.blocks();
        const auto &patches = model.geometry().patches();
        x.block             = b;
        x.patch             = patches[blocks[b].patch].name();
        x.centroid          = blocks[b].centroid;
      }

      /**
       * Step 2 of check_support_motion(), the fit: per group of blocks,
       * its exactly prescribed support components (@p rows_of, at the
       * points @p points_of) fitted by one rigid motion. A group whose
       * largest misfit (m) exceeds @p tolerance counts in
       * @p support_worst, which keeps the worst; a group fitted within it
       * with full rank gets its motion in @p fixed_motion. The counts and
       * the largest misfit go to @p check.
       */
      void
      fit_support_groups(
        const BlockModel                                  &model,
        const std::map<unsigned int, std::vector<FitRow>> &rows_of,
        const std::map<unsigned int,
                       std::vector<std::pair<unsigned int, unsigned int>>>
                                            &points_of,
        const double                         tolerance,
        SupportCheck                        &check,
        Incompatibility                     &support_worst,
        std::map<unsigned int, RigidMotion> &fixed_motion)
      {
        const auto  &interfaces = model.interfaces();
        const double length     = model.length_scale();
        for (const auto &[g, rows] : rows_of)
          {
            ++check.n_supported_groups;
            const Fit           fit = fit_rigid_motion(rows, length);
            const auto         &pts = points_of.at(g);
            std::vector<double> misfit(pts.size(), 0.);
            for (unsigned int r = 0; r < rows.size(); ++r)
              misfit[rows[r].point] += fit.residual[r] * fit.residual[r];
            double       sum = 0, largest = 0;
            unsigned int worst = 0;
            for (unsigned int p = 0; p < pts.size(); ++p)
              {
                sum += misfit[p];
                misfit[p] = std::sqrt(misfit[p]);
                if (misfit[p] > largest)
                  {
                    largest = misfit[p];
                    worst   = p;
                  }
              }
            check.largest_misfit = std::max(check.largest_misfit, largest);
            if (largest > tolerance)
              {
                ++support_worst.n_found;
                if (largest > support_worst.misfit)
                  {
                    const auto &i               = interfaces[pts[worst].first];
                    support_worst.kind          = "support";
                    support_worst.support_label = i.support_label;
                    describe_block(support_worst, model, i.first);
                    support_worst.position =
                      i.points[pts[worst].second].position;
                    support_worst.misfit     = largest;
                    support_worst.rms_misfit = std::sqrt(sum / pts.size());
                  }
              }
            else if (fit.rank == 6)
              {
                fixed_motion[g] = fit.motion;
                ++check.n_fixed_groups;
              }
          }
      }

      /**
       * Step 3 of check_support_motion(): the jumps between groups of
       * blocks of fixed motion (@p fixed_motion, by group of @p groups),
       * and at unilateral supports of such a group (ground motion @p u0,
       * not if @p bonded), measured by their distance (m) from the
       * @p cone of admissible jumps. Returns the worst joint beyond
       * @p tolerance (kind `joint`) and how many there are (n_found).
       */
      Incompatibility
      inadmissible_jumps(
        const BlockModel                          &model,
        const JumpCone                            &cone,
        Groups                                    &groups,
        const std::map<unsigned int, RigidMotion> &fixed_motion,
        const SupportMotion                       &u0,
        const bool                                 bonded,
        const double                               tolerance)
      {
        const auto     &interfaces = model.interfaces();
        Incompatibility joint_worst;
        for (const auto &i : interfaces)
          {
            const bool support = i.second == Interface::support;
            if (support && bonded)
              continue;
            const auto a = fixed_motion.find(groups.find(i.first));
            if (a == fixed_motion.end())
              continue;
            const unsigned int gb =
              support ? Interface::support : groups.find(i.second);
            if (!support && gb == groups.find(i.first))
              continue;
            const auto b = support ? fixed_motion.end() : fixed_motion.find(gb);
            if (!support && b == fixed_motion.end())
              continue;
            double       largest = 0, sum = 0;
            unsigned int worst = 0;
            for (unsigned int p = 0; p < i.points.size(); ++p)
              {
                const auto   &c = i.points[p];
                const Vector3 x = to_eigen(c.position);
                const Vector3 jump =
                  (support ? ground_motion(u0, i, c) : b->second.at(x)) -
                  a->second.at(x);
                const double d = cone.distance(frame(c) * jump);
                sum += d * d;
                if (d > largest)
                  {
                    largest = d;
                    worst   = p;
                  }
              }
            if (largest > tolerance)
              {
                ++joint_worst.n_found;
                if (largest > joint_worst.misfit)
                  {
                    joint_worst.kind          = "joint";
                    joint_worst.support_label = i.support_label;
                    joint_worst.other_block   = i.second;
                    describe_block(joint_worst, model, i.first);
                    joint_worst.position   = i.points[worst].position;
                    joint_worst.misfit     = largest;
                    joint_worst.rms_misfit = std::sqrt(sum / i.points.size());
                  }
              }
          }
        return joint_worst;
      }
    } // namespace

    std::string
    Incompatibility::describe() const
    {
      std::ostringstream s;
      s << std::setprecision(3);
      const std::string where = "block " + std::to_string(block) + " (patch `" +
                                patch + "', centroid " +
                                format_point(centroid) + " m)";
      if (kind == "lp")
        s << "the least total misfit of the contact conditions (the linear "
             "program's phase 1: "
          << total_misfit << " m in sum) leaves the largest, " << misfit
          << " m " << direction << ", at " << format_point(position)
          << " m on the joint of " << where << " with "
          << (other_block == Interface::support ?
                "the support edge `" + support_label + "'" :
                "block " + std::to_string(other_block))
          << " (" << n_found
          << (n_found == 1 ? " contact row" : " contact rows")
          << " misfit more than the tolerance)";
      else if (kind == "support")
        s << "the motion prescribed on the support edge `" << support_label
          << "' is no rigid motion of " << where << ": misfit " << misfit
          << " m at " << format_point(position)
          << " m (largest distance from the best-fitting rigid motion; "
          << n_found << (n_found == 1 ? " block" : " blocks")
          << " misfit more than the tolerance)";
      else
        s << "the supports fix the motion of " << where << " and of "
          << (other_block == Interface::support ?
                "the ground at the support edge `" + support_label + "'" :
                "block " + std::to_string(other_block))
          << ", and their joint at " << format_point(position)
          << " m would have to close or slide by " << misfit << " m ("
          << n_found << (n_found == 1 ? " joint" : " joints")
          << " in this state)";
      return s.str();
    }

    SupportCheck
    check_support_motion(const BlockModel     &model,
                         const InterfaceModel &joints,
                         const SupportMotion  &u0,
                         const bool            bonded,
                         const double          tolerance)
    {
      SupportCheck check;
      check.tolerance               = tolerance;
      const JumpCone     cone       = JumpCone(joints.yield_planes());
      const auto        &blocks     = model.blocks();
      const auto        &interfaces = model.interfaces();
      const double       length     = model.length_scale();
      const unsigned int n_blocks   = blocks.size();
      check.exact                   = cone.everything;

      // 1. groups of blocks joined by rigid interfaces: the fixed
      // components at their points determine the relative motion
      Groups groups(n_blocks);
      if (cone.fixed.size() > 0)
        for (const auto &i : interfaces)
          {
            if (i.second == Interface::support)
              continue;
            std::vector<FitRow> rows;
            for (const auto &c : i.points)
              for (const auto &f : cone.fixed)
                rows.push_back(
                  {frame(c).transpose() * f, to_eigen(c.position), 0., 0});
            if (fit_rigid_motion(rows, length).rank == 6)
              groups.join(i.first, i.second);
          }

      // 2. per group, the exactly prescribed support components fitted by
      // one rigid motion
      std::map<unsigned int, std::vector<FitRow>> rows_of;
      // per group: (support interface, point) of each fitted point
      std::map<unsigned int, std::vector<std::pair<unsigned int, unsigned int>>>
        points_of;
      for (unsigned int n = 0; n < interfaces.size(); ++n)
        {
          const auto &i = interfaces[n];
          if (i.second != Interface::support)
            continue;
          const unsigned int g   = groups.find(i.first);
          auto              &pts = points_of[g];
          for (unsigned int p = 0; p < i.points.size(); ++p)
            {
              const auto           &c = i.points[p];
              const Eigen::Matrix3d f = frame(c);
              const Vector3         u = ground_motion(u0, i, c);
              std::vector<Vector3>  directions;
              if (bonded)
                directions = {f.row(0).transpose(),
                              f.row(1).transpose(),
                              f.row(2).transpose()};
              else
                for (const auto &d : cone.fixed)
                  directions.push_back(f.transpose() * d);
              if (directions.empty())
                continue;
              for (const auto &e : directions)
                rows_of[g].push_back({e,
                                      to_eigen(c.position),
                                      e.dot(u),
                                      (unsigned int)pts.size()});
              pts.emplace_back(n, p);
            }
        }
      std::map<unsigned int, RigidMotion> fixed_motion;
      Incompatibility                     support_worst, joint_worst;
      fit_support_groups(model,
                         rows_of,
                         points_of,
                         tolerance,
                         check,
                         support_worst,
                         fixed_motion);

      // 3. the jumps between groups of fixed motion, and at unilateral
      // supports of such a group, must be admissible
      if (!cone.everything)
        joint_worst = inadmissible_jumps(
          model, cone, groups, fixed_motion, u0, bonded, tolerance);
      // a support motion that is no rigid motion is the cause; a joint
      // that would have to close follows from the fitted motions
      if (support_worst.n_found > 0)
        check.worst = support_worst;
      else if (joint_worst.n_found > 0)
        check.worst = joint_worst;
      check.incompatible = !check.worst.kind.empty();
      return check;
    }

    Incompatibility
    locate_row_misfit(const BlockModel          &model,
                      const MechanismProblem    &problem,
                      const std::vector<double> &row_misfit,
                      const double               velocity_scale,
                      const double               tolerance)
    {
      Incompatibility                   x;
      const std::array<const char *, 3> direction = {
        {"normal to the joint", "across the thickness", "along the joint"}};
      unsigned int p       = 0;
      const auto  &blocks  = model.blocks();
      const auto  &patches = model.geometry().patches();
      for (const auto &i : model.interfaces())
        for (unsigned int q = 0; q < i.points.size(); ++q, ++p)
          for (unsigned int k = 0; k < 3; ++k)
            {
              const int row = problem.point_rows[p][k];
              if (row < 0 ||
                  static_cast<unsigned int>(row) >= row_misfit.size())
                continue;
              const double m = row_misfit[row] * velocity_scale;
              x.total_misfit += m;
              if (m > tolerance)
                ++x.n_found;
              if (m > x.misfit)
                {
                  x.kind          = "lp";
                  x.misfit        = m;
                  x.block         = i.first;
                  x.other_block   = i.second;
                  x.support_label = i.support_label;
                  x.patch         = patches[blocks[i.first].patch].name();
                  x.centroid      = blocks[i.first].centroid;
                  x.position      = i.points[q].position;
                  x.direction     = direction[k];
                }
            }
      return x;
    }
  } // namespace rigid_blocks
} // namespace masonry
