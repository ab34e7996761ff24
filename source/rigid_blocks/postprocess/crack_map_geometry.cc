/**
 * @file
 * The state of an interface (crack type) and the developed vault surface
 * of the crack map.
 */
#include <masonry/geometry/interface.h>
#include <masonry/geometry/patch.h>
#include <masonry/rigid_blocks/postprocess/crack_map.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace postprocess
    {
      InterfaceState
      interface_state(const Result &result, const rigid_blocks::Interface &i)
      {
        InterfaceState state;
        bool first = true, first_intrados = true, first_extrados = true;
        for (const auto &c : i.points)
          {
            const auto   j       = result.jump(i, c);
            const double opening = j * c.normal;
            state.max_opening =
              first ? opening : std::max(state.max_opening, opening);
            state.min_opening =
              first ? opening : std::min(state.min_opening, opening);
            double &face =
              c.intrados ? state.intrados_opening : state.extrados_opening;
            bool &face_first = c.intrados ? first_intrados : first_extrados;
            face             = face_first ? opening : std::max(face, opening);
            face_first       = false;
            state.max_jump   = std::max(state.max_jump, j.norm());
            first            = false;
          }
        const double tolerance = result.tolerance();
        if (state.max_jump > tolerance)
          state.type = state.min_opening <= tolerance ?
                         (state.max_opening > tolerance ? "hinge" : "slip") :
                         "separation";
        const auto &motion = result.motion();
        state.relative_rotation =
          ((i.second == rigid_blocks::Interface::support ?
              dealii::Tensor<1, 3>() :
              motion.rotation[i.second]) -
           motion.rotation[i.first])
            .norm();
        return state;
      }

      namespace
      {
        /** Samples of the arc-length tables per direction. */
        constexpr unsigned int n_samples = 64;

        /** The intrados point of @p patch at @p uv. */
        dealii::Point<3>
        intrados(const geometry::Interface &geometry,
                 const geometry::Patch     &patch,
                 const dealii::Point<2>    &uv)
        {
          const dealii::Point<3> x = patch.point(uv);
          return x - 0.5 * geometry.thickness(x) * patch.normal(uv);
        }

        /** Cumulative chord lengths of the intrados along a parameter line
         * (@p along 0: u at v = 1/2; 1: v at u = 1/2). */
        std::vector<double>
        arc_lengths(const geometry::Interface &geometry,
                    const geometry::Patch     &patch,
                    const unsigned int         along)
        {
          std::vector<double> s(n_samples + 1, 0.);
          dealii::Point<3>    previous;
          for (unsigned int k = 0; k <= n_samples; ++k)
            {
              dealii::Point<2> uv(0.5, 0.5);
              uv[along]                = double(k) / n_samples;
              const dealii::Point<3> x = intrados(geometry, patch, uv);
              if (k > 0)
                s[k] = s[k - 1] + x.distance(previous);
              previous = x;
            }
          return s;
        }

        /** A point of the unit square on side @p side (0: u = 0, 1: u = 1,
         * 2: v = 0, 3: v = 1) at position @p s along it. */
        dealii::Point<2>
        on_side(const unsigned int side, const double s)
        {
          return side < 2 ? dealii::Point<2>(side, s) :
                            dealii::Point<2>(s, side - 2);
        }
      } // namespace

      double
      DevelopedSurface::interpolate(const std::vector<double> &table,
                                    const double               x)
      {
        const double       n = table.size() - 1;
        const double       y = std::clamp(x, 0., 1.) * n;
        const unsigned int k = std::min<unsigned int>(y, n - 1);
        return table[k] + (y - k) * (table[k + 1] - table[k]);
      }

      DevelopedSurface::DevelopedSurface(const BlockModel &model)
      {
        const geometry::Interface &geometry = model.geometry();
        const auto                &patches  = geometry.patches();
        const unsigned int         n        = patches.size();
        for (const auto &patch : patches)
          lengths.push_back(
            {arc_lengths(geometry, patch, 0), arc_lengths(geometry, patch, 1)});
        sign.assign(n, {{1., 1.}});
        offset.assign(n, dealii::Tensor<1, 2>());

        // whole sides that meet: the middle surface at five points along
        // side a of patch p equals that along side b of patch q, in the
        // same order or reversed
        const double tolerance = 1e-8 * model.length_scale();
        struct Glue
        {
          unsigned int p, a, q, b;
          bool         reversed;
        };
        std::vector<Glue> glues;
        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int q = p + 1; q < n; ++q)
            for (unsigned int a = 0; a < 4; ++a)
              for (unsigned int b = 0; b < 4; ++b)
                for (const bool reversed : {false, true})
                  {
                    bool same = (a < 2) == (b < 2);
                    for (unsigned int k = 0; k <= 4 && same; ++k)
                      same = patches[p]
                               .point(on_side(a, k / 4.))
                               .distance(patches[q].point(
                                 on_side(b, reversed ? 1 - k / 4. : k / 4.))) <
                             tolerance;
                    if (same)
                      glues.push_back({p, a, q, b, reversed});
                  }

        // place patch 0, then every patch glued to a placed one; patches
        // whose image would overlap a placed one, and those glued to none,
        // go apart in a row
        std::vector<bool> placed(n, false);
        const auto        box = [&](const unsigned int p) {
          std::array<double, 4> b{{std::numeric_limits<double>::max(),
                                   -std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::max(),
                                   -std::numeric_limits<double>::max()}};
          for (const double u : {0., 1.})
            for (const double v : {0., 1.})
              {
                const dealii::Point<2> x = map(p, dealii::Point<2>(u, v));
                b                        = {{std::min(b[0], x[0]),
                                             std::max(b[1], x[0]),
                                             std::min(b[2], x[1]),
                                             std::max(b[3], x[1])}};
              }
          return b;
        };
        const auto overlaps = [&](const unsigned int p) {
          const auto   b      = box(p);
          const double margin = 1e-6 * model.length_scale();
          for (unsigned int q = 0; q < n; ++q)
            if (placed[q] && q != p)
              {
                const auto c = box(q);
                if (b[0] < c[1] - margin && c[0] < b[1] - margin &&
                    b[2] < c[3] - margin && c[2] < b[3] - margin)
                  return true;
              }
          return false;
        };
        for (unsigned int start = 0; start < n; ++start)
          {
            if (placed[start])
              continue;
            if (start > 0)
              {
                // a new row entry, right of everything placed so far
                double right = -std::numeric_limits<double>::max(), width = 0;
                for (unsigned int q = 0; q < n; ++q)
                  if (placed[q])
                    {
                      const auto b = box(q);
                      right        = std::max(right, b[1]);
                      width        = std::max(width, b[1] - b[0]);
                    }
                offset[start][0] = right + 0.15 * width;
              }
            placed[start] = true;
            for (bool grown = true; grown;)
              {
                grown = false;
                for (const Glue &g : glues)
                  for (const bool forward : {true, false})
                    {
                      const unsigned int p = forward ? g.p : g.q,
                                         q = forward ? g.q : g.p;
                      const unsigned int a = forward ? g.a : g.b,
                                         b = forward ? g.b : g.a;
                      if (!placed[p] || placed[q])
                        continue;
                      // d: the direction across the glued sides (0: s,
                      // from the u sides; 1: t), e: the other one
                      const unsigned int d = a < 2 ? 0 : 1, e = 1 - d;
                      const double       end_p = a % 2, end_q = b % 2;
                      const auto &lp = d == 0 ? lengths[p].s : lengths[p].t;
                      const auto &lq = d == 0 ? lengths[q].s : lengths[q].t;
                      // q lies on the other side of the glued edge than p
                      sign[q][d] =
                        -sign[p][d] * (1 - 2 * end_p) * (1 - 2 * end_q);
                      const double edge =
                        sign[p][d] * interpolate(lp, end_p) + offset[p][d];
                      offset[q][d] = edge - sign[q][d] * interpolate(lq, end_q);
                      // along the edge: the middles of the sides meet
                      const auto &mp = e == 0 ? lengths[p].s : lengths[p].t;
                      const auto &mq = e == 0 ? lengths[q].s : lengths[q].t;
                      sign[q][e]     = g.reversed ? -sign[p][e] : sign[p][e];
                      offset[q][e]   = sign[p][e] * interpolate(mp, 0.5) +
                                     offset[p][e] -
                                     sign[q][e] * interpolate(mq, 0.5);
                      placed[q] = true;
                      if (overlaps(q))
                        {
                          placed[q] = false;
                          sign[q]   = {{1., 1.}};
                          offset[q] = dealii::Tensor<1, 2>();
                        }
                      else
                        grown = true;
                    }
              }
          }
      }

      dealii::Point<2>
      DevelopedSurface::map(const unsigned int      p,
                            const dealii::Point<2> &uv) const
      {
        return dealii::Point<2>(sign[p][0] * interpolate(lengths[p].s, uv[0]) +
                                  offset[p][0],
                                sign[p][1] * interpolate(lengths[p].t, uv[1]) +
                                  offset[p][1]);
      }

      std::vector<dealii::Point<2>>
      DevelopedSurface::segment(const unsigned int      p,
                                const dealii::Point<2> &a,
                                const dealii::Point<2> &b,
                                const unsigned int      n) const
      {
        std::vector<dealii::Point<2>> points;
        for (unsigned int k = 0; k <= n; ++k)
          points.push_back(map(p, a + (double(k) / n) * (b - a)));
        return points;
      }

      dealii::Point<2>
      DevelopedSurface::centre(const unsigned int p) const
      {
        return map(p, dealii::Point<2>(0.5, 0.5));
      }
    } // namespace postprocess
  }   // namespace rigid_blocks
} // namespace masonry
