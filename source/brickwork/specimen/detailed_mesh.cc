/**
 * @file
 * Mesh of the detailed model (MeshSettings::detailed): the units at their
 * actual size, meshed on one tensor grid with the mortar of the joints
 * between them, the partly filled head and collar joints and the unfilled
 * bed strips of workmanship, and the check that every unit keeps a size
 * (the enlarged-brick mesh and the mesh entries: mesh.cc).
 */
#include <masonry/core/parameters.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "mesh.h"

namespace masonry
{
  namespace brickwork
  {
    using namespace dealii;

    void
    check_units(const std::vector<Box> &boxes, const MeshSettings &s)
    {
      const double hm = s.mortar_thickness;
      for (const Box &box : boxes)
        for (unsigned int d = 0; d < 3; ++d)
          {
            // a unit is its enlarged box less one joint: the bond's
            // smallest piece (a half brick, a closer) must keep a size
            const double unit = box.upper[d] - box.lower[d] - hm;
            if (!(unit > 1e-6))
              {
                std::ostringstream m;
                m << hm << " m leaves a unit of the bond "
                  << (unit > 0 ? unit : 0.)
                  << (d == 0 ? " m long" :
                      d == 1 ? " m wide" :
                               " m high")
                  << " (a unit is its share of the wall less one joint: a "
                     "half brick or closer is (brick + joint) / 2 - "
                     "joint); the joint must be thinner than the units";
                AssertThrow(false, ExcParameter("Joint thickness", m.str()));
              }
          }
    }

    namespace model
    {
      namespace
      {
        /** A unit of the detailed model or, split, one of its halves: its
         * box (m) and the index of its brick. */
        struct Piece
        {
          std::array<double, 3> lower, upper;
          unsigned int          brick;
        };

        /** The length, thickness and height of the detailed wallette (the
         * outer faces of its units: each of @p boxes less one joint
         * @p hm), m, into @p g. */
        void
        detailed_extent(const std::vector<Box> &boxes,
                        const double            hm,
                        Geometry               &g)
        {
          for (const Box &box : boxes)
            for (unsigned int d = 0; d < 3; ++d)
              {
                const double top    = box.upper[d] - hm;
                (d == 0 ? g.length :
                 d == 1 ? g.thickness :
                          g.height) = std::max(d == 0 ? g.length :
                                               d == 1 ? g.thickness :
                                                        g.height,
                                               top);
              }
        }

        /** The units of @p boxes (each box less one joint, h_m, at its
         * upper end in every direction) and, with `Splitting interfaces',
         * their halves; the coordinates of their faces and splitting
         * planes (m) are added to @p lines, and each split unit counted
         * in g.n_split_units (@p h: the mesh spacing, m). */
        std::vector<Piece>
        unit_pieces(const std::vector<Box>      &boxes,
                    const MeshSettings          &settings,
                    const std::array<double, 3> &h,
                    std::vector<double> (&lines)[3],
                    Geometry &g)
        {
          const double       hm = settings.mortar_thickness;
          std::vector<Piece> pieces;
          for (unsigned int b = 0; b < boxes.size(); ++b)
            {
              Piece unit{boxes[b].lower, boxes[b].upper, b};
              for (unsigned int d = 0; d < 3; ++d)
                {
                  unit.upper[d] -= hm;
                  lines[d].push_back(unit.lower[d]);
                  lines[d].push_back(unit.upper[d]);
                }
              const unsigned int d    = split_direction(boxes[b]);
              const double       size = unit.upper[d] - unit.lower[d];
              if (settings.split_units && !settings.bonded &&
                  std::round(size / h[d]) >= 2)
                {
                  const double middle = 0.5 * (unit.lower[d] + unit.upper[d]);
                  Piece        first = unit, second = unit;
                  first.upper[d] = second.lower[d] = middle;
                  lines[d].push_back(middle);
                  pieces.push_back(first);
                  pieces.push_back(second);
                  ++g.n_split_units;
                }
              else
                pieces.push_back(unit);
            }
          return pieces;
        }

        /** The unfilled strips (y from, to; m) of the bed joints along the
         * collar joints between @p pieces, with `Collar bed gap' (none
         * without); their ends are added to the grid lines @p lines_y.
         * Throws if a wythe is left without bed-joint mortar (@p thickness:
         * the wall's, m; @p tol: the tolerance of coordinates, m). */
        std::vector<std::pair<double, double>>
        collar_bed_gaps(const std::vector<Piece> &pieces,
                        const MeshSettings       &settings,
                        const double              thickness,
                        const double              tol,
                        std::vector<double>      &lines_y)
        {
          const double hm = settings.mortar_thickness;
          // the collar planes: a mortar layer h_m thick in y between units on
          // both sides (one wythe's unit ends at y = a, the next one's starts
          // at a + h_m); with a bed gap g the bed joints are void over
          // [a - g, a + h_m + g], and grid lines lie at its ends
          std::vector<std::pair<double, double>> bed_gaps;
          if (settings.collar_bed_gap > 0)
            {
              std::vector<double> ends;
              for (const Piece &p : pieces)
                for (const Piece &q : pieces)
                  if (std::abs(q.lower[1] - p.upper[1] - hm) < tol &&
                      std::none_of(ends.begin(), ends.end(), [&](double e) {
                        return std::abs(e - p.upper[1]) < tol;
                      }))
                    ends.push_back(p.upper[1]);
              for (const double a : ends)
                {
                  bed_gaps.emplace_back(
                    std::max(0., a - settings.collar_bed_gap),
                    std::min(thickness, a + hm + settings.collar_bed_gap));
                  lines_y.push_back(bed_gaps.back().first);
                  lines_y.push_back(bed_gaps.back().second);
                }
              // every wythe keeps a bed: the strips stay apart and off the
              // faces (otherwise a wythe's units rest on nothing)
              std::sort(bed_gaps.begin(), bed_gaps.end());
              double left  = 0;
              bool   apart = true;
              for (const auto &gap : bed_gaps)
                {
                  apart = apart && gap.first - left >= tol;
                  left  = gap.second;
                }
              if (!apart || thickness - left < tol)
                {
                  std::ostringstream m;
                  m << settings.collar_bed_gap
                    << " m leaves a wythe without bed-joint mortar: the "
                       "unfilled strips (the collar joint's "
                    << hm
                    << " m and the gap on each side) meet each other or a "
                       "face of the "
                    << thickness << " m thick wall";
                  AssertThrow(false, ExcParameter("Collar bed gap", m.str()));
                }
            }
          return bed_gaps;
        }

        /** The grid coordinates (m) in one direction: the distinct @p lines
         * (within @p tol), which must run from 0 to @p extent (m), each
         * interval divided at about the mesh spacing @p h (m). */
        std::vector<double>
        grid_from_lines(std::vector<double> l,
                        const double        extent,
                        const double        h,
                        const double        tol)
        {
          std::vector<double> grid;
          std::sort(l.begin(), l.end());
          std::vector<double> unique;
          for (const double x : l)
            if (unique.empty() || x - unique.back() > tol)
              unique.push_back(x);
          AssertThrow(unique.front() > -tol &&
                        std::abs(unique.back() - extent) < tol,
                      ExcInternalError());
          for (unsigned int i = 0; i + 1 < unique.size(); ++i)
            {
              const double       a = unique[i], b = unique[i + 1];
              const unsigned int n = std::max(1., std::round((b - a) / h));
              for (unsigned int k = 0; k < n; ++k)
                grid.push_back(a + (b - a) * k / n);
            }
          grid.push_back(unique.back());
          return grid;
        }

        /** The owner of each cell of the @p n[0] x @p n[1] x @p n[2]
         * cells of @p grid (index i + n[0] (j + n[1] k)): the index of the
         * piece of @p pieces that covers it, else pieces.size() (the
         * mortar); @p tol: the tolerance of coordinates, m. */
        std::vector<unsigned int>
        cell_owners(const std::vector<Piece> &pieces,
                    const std::vector<double> (&grid)[3],
                    const unsigned int (&n)[3],
                    const double tol)
        {
          const unsigned int        mortar = pieces.size();
          std::vector<unsigned int> owner(n[0] * n[1] * n[2], mortar);
          for (unsigned int p = 0; p < pieces.size(); ++p)
            {
              unsigned int from[3], to[3];
              for (unsigned int d = 0; d < 3; ++d)
                {
                  from[d] = std::lower_bound(grid[d].begin(),
                                             grid[d].end(),
                                             pieces[p].lower[d] - tol) -
                            grid[d].begin();
                  to[d] = std::lower_bound(grid[d].begin(),
                                           grid[d].end(),
                                           pieces[p].upper[d] - tol) -
                          grid[d].begin();
                }
              for (unsigned int k = from[2]; k < to[2]; ++k)
                for (unsigned int j = from[1]; j < to[1]; ++j)
                  for (unsigned int i = from[0]; i < to[0]; ++i)
                    owner[i + n[0] * (j + n[1] * k)] = p;
            }
          return owner;
        }

        /** The height ranges (z from, to; m) of the courses of @p pieces,
         * sorted, one per course (bottoms within @p tol). */
        std::vector<std::pair<double, double>>
        course_ranges(const std::vector<Piece> &pieces, const double tol)
        {
          std::vector<std::pair<double, double>> courses;
          for (const Piece &p : pieces)
            courses.emplace_back(p.lower[2], p.upper[2]);
          std::sort(courses.begin(), courses.end());
          courses.erase(std::unique(courses.begin(),
                                    courses.end(),
                                    [&](const auto &a, const auto &b) {
                                      return std::abs(a.first - b.first) < tol;
                                    }),
                        courses.end());
          return courses;
        }
      } // namespace

      Geometry
      make_detailed_mesh(const std::vector<Box> &boxes,
                         const MeshSettings     &settings,
                         Triangulation<3>       &triangulation)
      {
        const double hm = settings.mortar_thickness;
        const auto   h  = mesh_spacing(settings);
        Geometry     g;
        check_units(boxes, settings);
        detailed_extent(boxes, hm, g);
        const double extent[3] = {g.length, g.thickness, g.height};
        const double tol       = 1e-9 * std::max({g.length, g.height});
        // the units and, split, their halves
        std::vector<double>      lines[3];
        const std::vector<Piece> pieces =
          unit_pieces(boxes, settings, h, lines, g);
        // partly filled head and collar joints: a grid line at the top of
        // the filled part of every course
        const double fills[2] = {settings.head_joint_fill,
                                 settings.collar_joint_fill};
        for (const Piece &p : pieces)
          for (const double f : fills)
            if (f > 0 && f < 1)
              lines[2].push_back(p.lower[2] + f * (p.upper[2] - p.lower[2]));
        // the unfilled strips of the bed joints along the collar joints
        const std::vector<std::pair<double, double>> bed_gaps =
          collar_bed_gaps(pieces, settings, extent[1], tol, lines[1]);
        // the grid: the lines through every face, each interval divided
        // at about the mesh spacing (mortar intervals, h_m, in one cell)
        std::vector<double> grid[3];
        for (unsigned int d = 0; d < 3; ++d)
          grid[d] = grid_from_lines(lines[d], extent[d], h[d], tol);
        // the owner of each grid cell: a piece, or the mortar
        const unsigned int n[3] = {
          static_cast<unsigned int>(grid[0].size()) - 1,
          static_cast<unsigned int>(grid[1].size()) - 1,
          static_cast<unsigned int>(grid[2].size()) - 1};
        const unsigned int              mortar = pieces.size();
        const std::vector<unsigned int> owner =
          cell_owners(pieces, grid, n, tol);
        // the courses (height ranges of the units), for the vertical joints
        const std::vector<std::pair<double, double>> courses =
          course_ranges(pieces, tol);
        auto is_unit = [&](const int i, const int j, const int k) {
          return i >= 0 && j >= 0 && k >= 0 && i < int(n[0]) && j < int(n[1]) &&
                 k < int(n[2]) && owner[i + n[0] * (j + n[1] * k)] != mortar;
        };
        // a mortar cell of a vertical joint whose centre lies above the
        // filled part of its course is a void (no cell)
        auto is_void = [&](const unsigned int i,
                           const unsigned int j,
                           const unsigned int k) {
          const double zc = 0.5 * (grid[2][k] + grid[2][k + 1]);
          for (const auto &[bottom, top] : courses)
            if (zc > bottom && zc < top)
              {
                // head joint: the run of mortar cells along x through this
                // one (a head joint may be cut by the splitting plane of
                // the next course) ends at units on both sides and is one
                // joint thick; otherwise (units on both sides in y, or a
                // crossing) the collar joint
                int first = i, last = i;
                while (first > 0 && !is_unit(first - 1, j, k))
                  --first;
                while (last + 1 < int(n[0]) && !is_unit(last + 1, j, k))
                  ++last;
                const bool head = is_unit(first - 1, j, k) &&
                                  is_unit(last + 1, j, k) &&
                                  grid[0][last + 1] - grid[0][first] < 1.5 * hm;
                const double fill = head ? fills[0] : fills[1];
                const bool   gone = zc > bottom + fill * (top - bottom);
                // the cell's share of the joint's area in its plane (a
                // joint may be meshed as two cells across its thickness)
                const double area = (grid[0][i + 1] - grid[0][i]) *
                                    (grid[1][j + 1] - grid[1][j]) *
                                    (grid[2][k + 1] - grid[2][k]) / hm;
                (head ? g.head_joint_area : g.collar_joint_area) += area;
                if (gone)
                  (head ? g.head_void_area : g.collar_void_area) += area;
                return gone;
              }
          // a bed joint: void in the strips along the collar joints
          const double yc = 0.5 * (grid[1][j] + grid[1][j + 1]);
          for (const auto &[a, b] : bed_gaps)
            if (yc > a && yc < b)
              {
                g.bed_void_area +=
                  (grid[0][i + 1] - grid[0][i]) * (grid[1][j + 1] - grid[1][j]);
                return true;
              }
          return false;
        };
        // one vertex per grid point and owner (all owners one, bonded)
        std::map<std::array<unsigned int, 4>, unsigned int> vertex_of;
        std::vector<Point<3>>                               vertices;
        std::vector<CellData<3>>                            cells;
        for (unsigned int k = 0; k < n[2]; ++k)
          for (unsigned int j = 0; j < n[1]; ++j)
            for (unsigned int i = 0; i < n[0]; ++i)
              {
                const unsigned int o = owner[i + n[0] * (j + n[1] * k)];
                if (o == mortar && is_void(i, j, k))
                  {
                    ++g.n_void_cells;
                    continue;
                  }
                CellData<3> c;
                for (unsigned int v = 0; v < 8; ++v)
                  {
                    const std::array<unsigned int, 4> key = {
                      {i + v % 2,
                       j + (v / 2) % 2,
                       k + v / 4,
                       settings.bonded ? 0 : o}};
                    const auto it = vertex_of.find(key);
                    if (it != vertex_of.end())
                      c.vertices[v] = it->second;
                    else
                      {
                        c.vertices[v] = vertices.size();
                        vertex_of.emplace(key, vertices.size());
                        vertices.emplace_back(grid[0][key[0]],
                                              grid[1][key[1]],
                                              grid[2][key[2]]);
                      }
                  }
                c.material_id = o == mortar ? boxes.size() : pieces[o].brick;
                if (o == mortar)
                  ++g.n_mortar_cells;
                cells.push_back(c);
              }
        g.n_bricks   = boxes.size();
        g.gross_area = g.length * g.thickness;
        triangulation.create_triangulation(vertices, cells, SubCellData());
        return g;
      }
    } // namespace model
  }   // namespace brickwork
} // namespace masonry
