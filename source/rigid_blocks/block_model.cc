#include <masonry/core/parameters.h>
#include <masonry/geometry/interface.h>
#include <masonry/geometry/patch_occt.h>
#include <masonry/rigid_blocks/block_model.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cmath>

namespace masonry
{
  namespace rigid_blocks
  {
    namespace
    {
      constexpr double gravity = 9.81;

      /** Bilinear map of the reference square onto a cell (deal.II vertex
       * order: (0,0), (1,0), (0,1), (1,1)). */
      dealii::Point<2>
      cell_point(const std::array<dealii::Point<2>, 4> &c,
                 const double                           xi,
                 const double                           eta)
      {
        return dealii::Point<2>(
          (1 - xi) * (1 - eta) * c[0][0] + xi * (1 - eta) * c[1][0] +
            (1 - xi) * eta * c[2][0] + xi * eta * c[3][0],
          (1 - xi) * (1 - eta) * c[0][1] + xi * (1 - eta) * c[1][1] +
            (1 - xi) * eta * c[2][1] + xi * eta * c[3][1]);
      }

      /** |det| of the Jacobian of cell_point. */
      double
      cell_jacobian(const std::array<dealii::Point<2>, 4> &c,
                    const double                           xi,
                    const double                           eta)
      {
        const dealii::Tensor<1, 2> d_xi =
          (1 - eta) * (c[1] - c[0]) + eta * (c[3] - c[2]);
        const dealii::Tensor<1, 2> d_eta =
          (1 - xi) * (c[2] - c[0]) + xi * (c[3] - c[1]);
        return std::abs(d_xi[0] * d_eta[1] - d_xi[1] * d_eta[0]);
      }

      /** Derivatives of the unit normal by central differences (the step
       * keeps the error near 1e-10 of the curvature). */
      std::array<dealii::Tensor<1, 3>, 2>
      normal_derivatives(const geometry::Patch  &patch,
                         const dealii::Point<2> &uv)
      {
        const double                        h = 1e-6;
        std::array<dealii::Tensor<1, 3>, 2> dn;
        for (unsigned int d = 0; d < 2; ++d)
          {
            dealii::Point<2> a = uv, b = uv;
            a[d]  = std::max(0.0, uv[d] - h);
            b[d]  = std::min(1.0, uv[d] + h);
            dn[d] = (patch.normal(b) - patch.normal(a)) / (b[d] - a[d]);
          }
        return dn;
      }

      /** Knots of a patch in unit-square parameters (u: d = 0, v: d = 1). */
      std::vector<double>
      unit_knots(const geometry::Patch &patch, const unsigned int d)
      {
        const geometry::PatchSurface &s      = patch.surface();
        const Handle(Geom_BSplineSurface) &b = s.bspline;
        const int    n  = d == 0 ? b->NbUKnots() : b->NbVKnots();
        const double lo = d == 0 ? s.u0 : s.v0, hi = d == 0 ? s.u1 : s.v1;
        std::vector<double> knots;
        for (int i = 1; i <= n; ++i)
          knots.push_back(((d == 0 ? b->UKnot(i) : b->VKnot(i)) - lo) /
                          (hi - lo));
        return knots;
      }

      /** [a, b] split at the knots inside it. */
      std::vector<double>
      breaks(const double a, const double b, const std::vector<double> &knots)
      {
        std::vector<double> x = {a};
        for (const double k : knots)
          if (k > a + 1e-12 && k < b - 1e-12)
            x.push_back(k);
        x.push_back(b);
        return x;
      }
    } // namespace

    std::vector<std::pair<dealii::Point<2>, double>>
    BlockModel::quadrature(const unsigned int b) const
    {
      const Block            &block = block_list[b];
      const auto             &c     = block.corners;
      const dealii::QGauss<1> gauss(options.n_quadrature);
      std::vector<std::pair<dealii::Point<2>, double>> points;
      const bool axis_aligned = c[0][1] == c[1][1] && c[2][1] == c[3][1] &&
                                c[0][0] == c[2][0] && c[1][0] == c[3][0];
      if (axis_aligned)
        {
          const geometry::Patch &patch = geom.patches()[block.patch];
          const auto u = breaks(c[0][0], c[1][0], unit_knots(patch, 0));
          const auto v = breaks(c[0][1], c[2][1], unit_knots(patch, 1));
          for (unsigned int i = 0; i + 1 < u.size(); ++i)
            for (unsigned int j = 0; j + 1 < v.size(); ++j)
              for (unsigned int p = 0; p < gauss.size(); ++p)
                for (unsigned int q = 0; q < gauss.size(); ++q)
                  points.emplace_back(
                    dealii::Point<2>(
                      u[i] + gauss.point(p)[0] * (u[i + 1] - u[i]),
                      v[j] + gauss.point(q)[0] * (v[j + 1] - v[j])),
                    gauss.weight(p) * gauss.weight(q) * (u[i + 1] - u[i]) *
                      (v[j + 1] - v[j]));
          return points;
        }
      for (unsigned int p = 0; p < gauss.size(); ++p)
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const double xi = gauss.point(p)[0], eta = gauss.point(q)[0];
            points.emplace_back(cell_point(c, xi, eta),
                                gauss.weight(p) * gauss.weight(q) *
                                  cell_jacobian(c, xi, eta));
          }
      return points;
    }

    BlockModel::BlockModel(const geometry::Interface &geometry,
                           const Discretisation      &options)
      : geom(geometry)
      , options(options)
    {
      const auto &patches = geom.patches();
      vertices.resize(patches.size());
      for (auto &v : vertices)
        for (unsigned int j = 0; j <= options.n_v; ++j)
          for (unsigned int i = 0; i <= options.n_u; ++i)
            v.emplace_back(double(i) / options.n_u, double(j) / options.n_v);
      build();
    }

    BlockModel::BlockModel(
      const geometry::Interface                        &geometry,
      const Discretisation                             &options,
      const std::vector<std::vector<dealii::Point<2>>> &vertices)
      : geom(geometry)
      , options(options)
      , vertices(vertices)
    {
      build();
    }

    const std::vector<Block> &
    BlockModel::blocks() const
    {
      return block_list;
    }

    const std::vector<Interface> &
    BlockModel::interfaces() const
    {
      return interface_list;
    }

    unsigned int
    BlockModel::n_contact_points() const
    {
      unsigned int n = 0;
      for (const auto &i : interface_list)
        n += i.points.size();
      return n;
    }

    const geometry::Interface &
    BlockModel::geometry() const
    {
      return geom;
    }

    const Discretisation &
    BlockModel::discretisation() const
    {
      return options;
    }

    const std::vector<std::vector<dealii::Point<2>>> &
    BlockModel::parameter_vertices() const
    {
      return vertices;
    }

    double
    BlockModel::length_scale() const
    {
      return size;
    }

    dealii::Point<3>
    BlockModel::solid_point(const unsigned int      b,
                            const dealii::Point<2> &reference,
                            const double            zeta) const
    {
      const Block           &block = block_list[b];
      const geometry::Patch &patch = geom.patches()[block.patch];
      const dealii::Point<2> uv =
        cell_point(block.corners, reference[0], reference[1]);
      const dealii::Point<3> x = patch.point(uv);
      return x + zeta * geom.thickness(x) * patch.normal(uv);
    }

    namespace
    {
      /** Size of the bounding box of 5 x 5 points of every patch, m. */
      double
      bounding_box_size(const std::vector<geometry::Patch> &patches)
      {
        dealii::Point<3> lo, hi;
        bool             first = true;
        for (const auto &p : patches)
          for (unsigned int i = 0; i <= 4; ++i)
            for (unsigned int j = 0; j <= 4; ++j)
              {
                const auto x = p.point(dealii::Point<2>(i / 4., j / 4.));
                for (unsigned int d = 0; d < 3; ++d)
                  {
                    lo[d] = first ? x[d] : std::min(lo[d], x[d]);
                    hi[d] = first ? x[d] : std::max(hi[d], x[d]);
                  }
                first = false;
              }
        return lo.distance(hi);
      }
    } // namespace

    /** A face of a patch's parameter mesh on the patch's boundary. */
    struct BlockModel::BoundaryFace
    {
      unsigned int                    block;
      unsigned int                    patch;
      unsigned int                    edge;
      std::array<dealii::Point<2>, 2> uv;
      std::array<dealii::Point<3>, 3> x; // ends and midpoint
      dealii::Point<2>                outward;
    };

    /** A face between two blocks of one patch. */
    struct BlockModel::InnerFace
    {
      unsigned int                    first, second;
      std::array<dealii::Point<2>, 2> uv;
      dealii::Point<2>                outward;
    };

    void
    BlockModel::build()
    {
      const auto &patches = geom.patches();
      AssertThrow(!patches.empty(),
                  dealii::ExcMessage("the geometry model has no patch"));
      AssertThrow(options.n_u >= 1 && options.n_v >= 1 &&
                    options.n_stations >= 2 && options.n_quadrature >= 1,
                  dealii::ExcMessage("invalid block discretisation"));

      // bounding box: the length scale for tolerances and LP scaling
      size = bounding_box_size(patches);

      // one parameter-space triangulation per patch: cells are blocks,
      // faces are interfaces (boundary ids 0..3: edges u=0, u=1, v=0, v=1)
      std::vector<BoundaryFace> boundary_faces;
      std::vector<InnerFace>    inner_faces;
      block_list.clear();
      interface_list.clear();
      block_samples.clear();
      interface_stations.clear();
      for (unsigned int p = 0; p < patches.size(); ++p)
        add_patch_blocks(p, boundary_faces, inner_faces);

      for (const auto &f : inner_faces)
        add_interface(
          block_list[f.first].patch, f.uv, f.outward, f.first, f.second);
      connect_boundary_faces(boundary_faces);
    }

    namespace
    {
      /** Split the cells of @p mesh (patch @p p) whose centres are listed,
       * round by round (Discretisation::splits). */
      void
      split_cells(const std::vector<std::vector<dealii::Point<2>>> &rounds,
                  const unsigned int                                p,
                  dealii::Triangulation<2>                         &mesh)
      {
        for (const auto &round : rounds)
          {
            for (const auto &centre : round)
              {
                bool found = false;
                for (const auto &cell : mesh.active_cell_iterators())
                  {
                    dealii::Point<2> c;
                    for (const unsigned int v : cell->vertex_indices())
                      c += 0.25 * cell->vertex(v);
                    if (c.distance(centre) < 1e-10)
                      {
                        cell->set_refine_flag();
                        found = true;
                        break;
                      }
                  }
                AssertThrow(found,
                            dealii::ExcMessage(
                              "local refinement: no block of patch " +
                              std::to_string(p) + " has its centre at (" +
                              std::to_string(centre[0]) + ", " +
                              std::to_string(centre[1]) + ")"));
              }
            mesh.execute_coarsening_and_refinement();
          }
      }

    } // namespace

    void
    BlockModel::add_patch_blocks(const unsigned int         p,
                                 std::vector<BoundaryFace> &boundary_faces,
                                 std::vector<InnerFace>    &inner_faces)
    {
      const auto              &patches = geom.patches();
      dealii::Triangulation<2> mesh;
      dealii::GridGenerator::subdivided_hyper_rectangle(mesh,
                                                        {options.n_u,
                                                         options.n_v},
                                                        dealii::Point<2>(0, 0),
                                                        dealii::Point<2>(1, 1),
                                                        true);
      AssertThrow(vertices[p].size() == mesh.n_vertices(),
                  dealii::ExcMessage("parameter mesh of patch " +
                                     std::to_string(p) +
                                     " has the wrong number of vertices"));
      // subdivided_hyper_rectangle numbers vertices lexicographically
      for (const auto &cell : mesh.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          cell->vertex(v) = vertices[p][cell->vertex_index(v)];
      if (p < options.splits.size())
        split_cells(options.splits[p], p, mesh);

      const unsigned int offset = block_list.size();
      for (const auto &cell : mesh.active_cell_iterators())
        {
          Block block;
          block.patch = p;
          for (unsigned int v = 0; v < 4; ++v)
            block.corners[v] = cell->vertex(v);
          block_list.push_back(block);
          std::vector<SurfaceSample> samples;
          for (const auto &[uv, w] : quadrature(block_list.size() - 1))
            {
              SurfaceSample sample;
              sample.uv                 = uv;
              sample.weight             = w;
              sample.point              = patches[p].point(uv);
              sample.tangents           = patches[p].tangents(uv);
              sample.normal             = patches[p].normal(uv);
              sample.normal_derivatives = normal_derivatives(patches[p], uv);
              sample.unscaled_thickness = geom.unscaled_thickness(sample.point);
              samples.push_back(sample);
            }
          block_samples.push_back(std::move(samples));
          compute_mass(block_list.size() - 1);
        }

      for (const auto &cell : mesh.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            // outward direction of the face in parameter space
            dealii::Point<2> outward;
            outward[f / 2]                           = (f % 2 == 0) ? -1. : 1.;
            const std::array<dealii::Point<2>, 2> uv = {
              {cell->face(f)->vertex(0), cell->face(f)->vertex(1)}};
            const unsigned int b = offset + cell->active_cell_index();
            if (cell->at_boundary(f))
              {
                BoundaryFace bf{
                  b, p, cell->face(f)->boundary_id(), uv, {}, outward};
                bf.x[0] = patches[p].point(uv[0]);
                bf.x[1] = patches[p].point(uv[1]);
                bf.x[2] =
                  patches[p].point(dealii::Point<2>(0.5 * (uv[0] + uv[1])));
                boundary_faces.push_back(bf);
              }
            else if (cell->face(f)->has_children())
              // split neighbours: one interface along each half of the edge
              for (unsigned int sf = 0; sf < cell->face(f)->n_children(); ++sf)
                {
                  const auto neighbor = cell->neighbor_child_on_subface(f, sf);
                  AssertThrow(neighbor->is_active(),
                              dealii::ExcInternalError());
                  inner_faces.push_back(
                    {b,
                     offset + neighbor->active_cell_index(),
                     {{cell->face(f)->child(sf)->vertex(0),
                       cell->face(f)->child(sf)->vertex(1)}},
                     outward});
                }
            else if (!cell->neighbor_is_coarser(f) &&
                     cell->neighbor(f)->active_cell_index() >
                       cell->active_cell_index())
              inner_faces.push_back(
                {b,
                 offset + cell->neighbor(f)->active_cell_index(),
                 uv,
                 outward});
          }
    }

    void
    BlockModel::compute_mass(const unsigned int b)
    {
      const double zeta_gauss[2] = {-0.5 / std::sqrt(3.), 0.5 / std::sqrt(3.)};
      const double rho_g         = geom.density() * gravity;
      const double factor        = geom.thickness_factor();
      double       volume        = 0;
      dealii::Tensor<1, 3> first_moment;
      for (const auto &sample : block_samples[b])
        {
          const double w  = sample.weight;
          const auto  &s  = sample.point;
          const auto  &ts = sample.tangents;
          const auto  &n  = sample.normal;
          const auto  &dn = sample.normal_derivatives;
          // exactly geometry::Interface::thickness(s)
          const double t = factor * sample.unscaled_thickness;
          for (const double zeta : zeta_gauss)
            {
              // det[x_u, x_v, x_zeta] with x = s + zeta t n; the
              // zeta t_u n terms are parallel to x_zeta and drop
              const double jac = std::abs(
                t * (n * dealii::cross_product_3d(ts[0] + zeta * t * dn[0],
                                                  ts[1] + zeta * t * dn[1])));
              const dealii::Point<3> x = s + zeta * t * n;
              volume += 0.5 * w * jac;
              first_moment += 0.5 * w * jac * x;
            }
        }
      Block &block = block_list[b];
      AssertThrow(volume > 0 && std::isfinite(volume),
                  dealii::ExcMessage(
                    "block " + std::to_string(b) + " of patch " +
                    std::to_string(block.patch) +
                    " has no volume: degenerate cell or thickness"));
      block.volume   = volume;
      block.centroid = dealii::Point<3>(first_moment / volume);
      block.weight   = rho_g * volume;
    }

    const std::vector<SurfaceSample> &
    BlockModel::surface_samples(const unsigned int b) const
    {
      return block_samples[b];
    }

    void
    BlockModel::update_thickness()
    {
      for (unsigned int b = 0; b < block_list.size(); ++b)
        compute_mass(b);
      for (unsigned int i = 0; i < interface_list.size(); ++i)
        compute_contact_points(interface_list[i], interface_stations[i]);
    }

    void
    BlockModel::compute_contact_points(
      Interface                  &interface,
      const std::vector<Station> &stations) const
    {
      const double factor = geom.thickness_factor();
      interface.points.clear();
      interface.area = 0;
      dealii::Tensor<1, 3> centre;
      for (const auto &station : stations)
        {
          // exactly geometry::Interface::thickness(x)
          const double t = factor * station.unscaled_thickness;
          for (const bool intrados : {true, false})
            {
              ContactPoint c;
              c.position =
                station.x + (intrados ? -0.5 : 0.5) * t * station.across;
              c.normal = station.normal;
              c.across = station.across;
              c.along =
                dealii::cross_product_3d(station.normal, station.across);
              c.area     = 0.5 * t * station.weight;
              c.intrados = intrados;
              interface.points.push_back(c);
              interface.area += c.area;
              centre += c.area * c.position;
            }
        }
      if (interface.area > 0)
        interface.centre = dealii::Point<3>(centre / interface.area);
    }

    void
    BlockModel::add_interface(const unsigned int                     p,
                              const std::array<dealii::Point<2>, 2> &uv,
                              const dealii::Point<2>                &outward,
                              const unsigned int                     first,
                              const unsigned int                     second)
    {
      Interface interface;
      interface.first              = first;
      interface.second             = second;
      interface.patch              = p;
      interface.edge               = uv;
      const unsigned int     n     = options.n_stations;
      const geometry::Patch &patch = geom.patches()[p];
      std::vector<Station>   stations;
      for (unsigned int k = 0; k < n; ++k)
        {
          const double               s  = double(k) / (n - 1);
          const dealii::Point<2>     q  = uv[0] + s * (uv[1] - uv[0]);
          const dealii::Point<3>     x  = patch.point(q);
          const auto                 ts = patch.tangents(q);
          const auto                 ns = patch.normal(q);
          const double               t0 = geom.unscaled_thickness(x);
          const dealii::Tensor<1, 3> edge =
            ts[0] * (uv[1][0] - uv[0][0]) + ts[1] * (uv[1][1] - uv[0][1]);
          dealii::Tensor<1, 3> normal = dealii::cross_product_3d(edge, ns);
          const double         norm   = normal.norm();
          if (norm == 0)
            continue;
          normal /= norm;
          const dealii::Tensor<1, 3> out =
            ts[0] * outward[0] + ts[1] * outward[1];
          if (normal * out < 0)
            normal = -normal;
          // trapezoidal weight of the station along the edge
          const double weight =
            edge.norm() / (n - 1) * ((k == 0 || k == n - 1) ? 0.5 : 1.0);
          stations.push_back({x, normal, ns, weight, t0});
        }
      compute_contact_points(interface, stations);
      if (interface.area > 0)
        {
          interface_list.push_back(interface);
          interface_stations.push_back(std::move(stations));
        }
    }

    void
    BlockModel::connect_boundary_faces(
      const std::vector<BoundaryFace> &boundary_faces)
    {
      const auto &patches = geom.patches();
      // boundary faces: glued to another patch's face, on a support, or free
      const double      tolerance = 1e-8 * size;
      std::vector<bool> used(boundary_faces.size(), false);
      for (unsigned int a = 0; a < boundary_faces.size(); ++a)
        {
          if (used[a])
            continue;
          const auto &fa = boundary_faces[a];
          // degenerate edges (a dome's pole) carry no interface
          if (fa.x[0].distance(fa.x[1]) < tolerance &&
              fa.x[0].distance(fa.x[2]) < tolerance)
            continue;
          for (unsigned int b = a + 1; b < boundary_faces.size(); ++b)
            {
              const auto &fb = boundary_faces[b];
              if (used[b] || fa.block == fb.block)
                continue;
              const bool same = fa.x[2].distance(fb.x[2]) < tolerance &&
                                ((fa.x[0].distance(fb.x[0]) < tolerance &&
                                  fa.x[1].distance(fb.x[1]) < tolerance) ||
                                 (fa.x[0].distance(fb.x[1]) < tolerance &&
                                  fa.x[1].distance(fb.x[0]) < tolerance));
              if (same)
                {
                  used[a] = used[b] = true;
                  add_interface(
                    fa.patch, fa.uv, fa.outward, fa.block, fb.block);
                  break;
                }
            }
        }
      // locally refined meshes: a face of a split block glued to part of a
      // coarser block's face of the other patch, along one of the halves
      // (quarters, ...) of that face in its parameters. The pieces are
      // searched level by level, in order along the face, and a piece is
      // halved only while an unmatched face lies near it (within twice the
      // length of its chords; a face inside the piece is within half its
      // arc), so the cost follows the faces present, not the number of
      // refinement rounds (those were once the depth: 2^Stages pieces).
      bool refined = false;
      for (const auto &rounds : options.splits)
        refined = refined || !rounds.empty();
      for (unsigned int a = 0; a < boundary_faces.size() && refined; ++a)
        {
          const auto &fa = boundary_faces[a];
          if (used[a] || (fa.x[0].distance(fa.x[1]) < tolerance &&
                          fa.x[0].distance(fa.x[2]) < tolerance))
            continue;
          // is an unmatched face of another block (than a's) near x?
          const auto near = [&](const dealii::Point<3> &x, const double r) {
            for (unsigned int b = 0; b < boundary_faces.size(); ++b)
              if (!used[b] && b != a && boundary_faces[b].block != fa.block &&
                  boundary_faces[b].x[2].distance(x) < r)
                return true;
            return false;
          };
          // the pieces of the current level, their ends in parameters
          std::vector<std::array<dealii::Point<2>, 2>> pieces = {fa.uv};
          while (!pieces.empty())
            {
              std::vector<std::array<dealii::Point<2>, 2>> next;
              for (const auto &piece : pieces)
                for (unsigned int h = 0; h < 2; ++h)
                  {
                    const dealii::Point<2> mid = 0.5 * (piece[0] + piece[1]);
                    const std::array<dealii::Point<2>, 2> uv = {
                      {h == 0 ? piece[0] : mid, h == 0 ? mid : piece[1]}};
                    const dealii::Point<3> x0 = patches[fa.patch].point(uv[0]),
                                           x1 = patches[fa.patch].point(uv[1]),
                                           xm = patches[fa.patch].point(
                                             0.5 * (uv[0] + uv[1]));
                    const double r = 2 * (x0.distance(xm) + xm.distance(x1));
                    if (r < tolerance || !near(xm, r))
                      continue;
                    bool matched = false;
                    for (unsigned int b = 0; b < boundary_faces.size(); ++b)
                      {
                        const auto &fb = boundary_faces[b];
                        if (used[b] || b == a || fa.block == fb.block)
                          continue;
                        if (fb.x[2].distance(xm) < tolerance &&
                            ((fb.x[0].distance(x0) < tolerance &&
                              fb.x[1].distance(x1) < tolerance) ||
                             (fb.x[0].distance(x1) < tolerance &&
                              fb.x[1].distance(x0) < tolerance)))
                          {
                            // the geometry of the face listed first, as for
                            // conforming faces (where the patches meet at an
                            // angle, the contact points depend on the side)
                            used[a] = used[b] = matched = true;
                            if (b < a)
                              add_interface(fb.patch,
                                            fb.uv,
                                            fb.outward,
                                            fb.block,
                                            fa.block);
                            else
                              add_interface(
                                fa.patch, uv, fa.outward, fa.block, fb.block);
                            break;
                          }
                      }
                    if (!matched)
                      next.push_back(uv);
                  }
              pieces = std::move(next);
            }
        }
      std::set<std::string> labels_found;
      for (unsigned int a = 0; a < boundary_faces.size(); ++a)
        {
          const auto       &fa    = boundary_faces[a];
          const std::string label = patches[fa.patch].edge_labels()[fa.edge];
          labels_found.insert(label);
          if (used[a] || options.supported_edges.count(label) == 0)
            continue;
          const unsigned int before = interface_list.size();
          add_interface(
            fa.patch, fa.uv, fa.outward, fa.block, Interface::support);
          if (interface_list.size() > before)
            interface_list.back().support_label = label;
        }
      for (const auto &label : options.supported_edges)
        {
          std::string known;
          for (const auto &l : labels_found)
            known += (known.empty() ? "" : ", ") + l;
          AssertThrow(
            labels_found.count(label) > 0,
            ExcParameter("Supported edges",
                         "no free edge of the geometry is labelled '" + label +
                           "'; the edges are: " + known));
        }
    }
  } // namespace rigid_blocks
} // namespace masonry
